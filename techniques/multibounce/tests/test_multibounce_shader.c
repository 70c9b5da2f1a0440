/* One source for GTAOMultiBounce (multibounce/multibounce.inc): the C compiled
 * from it gives the same bits as the C written before it (transcribed here:
 * Horner's loop, the cubic, fmax); the generated HLSL and GLSL are the .inc
 * verbatim and compile; the generated C header compiles, and its functions
 * give the same bits as the header gtlab wrote before (its expressions
 * transcribed here, in float, with the same "%.9g" literals) and agree with
 * the C in double to float rounding; no other file spells the formula. */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "multibounce/multibounce.h"
#include "multibounce/multibounce_shader.h"
#include "tests/check.h"
#include "tests/source_text.h"
#include "test_multibounce_models.h"


/* The models the tests generate: the talk's (linear), a quadratic, the anchored form. */
enum { MODELS = TEST_MULTIBOUNCE_MODELS, GRID_X = 133, GRID_RHO = 69 };
static const char *const kNames[MODELS] = {"mb_test_linear", "mb_test_quadratic", "mb_test_anchored"};

static void test_models(multibounce_model m[MODELS]) { test_multibounce_models(m); }

/* The grid: V_d and rho a little beyond [0, 1] on both sides. */
static float grid_x(int i) { return (i * 4 - 8) / 512.0f; }
static float grid_rho(int j) { return (j - 2) / 64.0f; }

/* ---- The C before the .inc, transcribed ---- */

static double previous_polynomial(const double *coef, int degree, double rho)
{
    double v = coef[degree];
    for (int k = degree - 1; k >= 0; --k)
        v = v * rho + coef[k];
    return v;
}

static double previous_cubic(double a, double b, double c, double x) { return ((a * x + b) * x + c) * x; }

static void test_c_matches_previous_c(void)
{
    multibounce_model m[MODELS + 1];
    test_models(m);
    m[MODELS] = (multibounce_model){.degree = 0, .a = {1.5}, .b = {-2.25}, .c = {1.75}};
    int mismatches = 0;
    for (int k = 0; k <= MODELS; ++k)
        for (int i = 0; i < GRID_X; ++i)
            for (int j = 0; j < GRID_RHO; ++j) {
                double x = grid_x(i) * 1.0009765625, rho = grid_rho(j) * 0.9990234375; /* not only floats */
                const multibounce_model *mk = &m[k];
                double a = previous_polynomial(mk->a, mk->degree, rho), b = previous_polynomial(mk->b, mk->degree, rho);
                double c = previous_polynomial(mk->c, mk->degree, rho), cubic = previous_cubic(a, b, c, x);
                multibounce_cubic got = multibounce_cubic_at(mk, rho);
                mismatches += got.a != a || got.b != b || got.c != c || multibounce_cubic_eval(&got, x) != cubic ||
                              gtao_multibounce(mk, x, rho) != fmax(x, cubic);
            }
    CHECK_MSG(mismatches == 0, "%d values differ from the C before multibounce/multibounce.inc", mismatches);
}

static void test_embedded_text_is_the_file(void)
{
    char *text = read_text(GTLAB_SOURCE_DIR "/techniques/multibounce/multibounce.inc");
    CHECK(text != NULL && strcmp(text, multibounce_inc_text) == 0);
    free(text);
}

static void functions_of(const multibounce_model m[MODELS], multibounce_shader_function f[MODELS])
{
    for (int k = 0; k < MODELS; ++k)
        f[k] = (multibounce_shader_function){.name = kNames[k], .comment = "test", .model = m[k]};
}

/* A fragment shader calling every function, compiled by glslangValidator. */
static int shader_compiles(shader_language language)
{
    multibounce_model m[MODELS];
    multibounce_shader_function f[MODELS];
    test_models(m);
    functions_of(m, f);
    char *source = multibounce_shader_source(language, "// test\n", f, MODELS), path[4096], command[16384];
    CHECK(source != NULL && strstr(source, multibounce_inc_text) != NULL);
    snprintf(path, sizeof path, "%s/multibounce_shader.%s", check_tmp_dir(), language == SHADER_HLSL ? "hlsl" : "frag");
    FILE *out = fopen(path, "w");
    if (!out || !source)
        return 0;
    if (language == SHADER_GLSL)
        fprintf(out, "#version 450\n%s\nlayout(location = 0) in vec4 v;\nlayout(location = 0) out vec4 o;\n"
                     "void main() { o = vec4(%s(v.x, v.yzw) + %s(v.x, v.yzw) + %s(v.x, v.yzw), 1.0); }\n",
                source, kNames[0], kNames[1], kNames[2]);
    else
        fprintf(out, "%s\nfloat4 main(float4 v : TEXCOORD0) : SV_Target { return float4(%s(v.x, v.yzw) + "
                     "%s(v.x, v.yzw) + %s(v.x, v.yzw), 1.0); }\n",
                source, kNames[0], kNames[1], kNames[2]);
    fclose(out);
    free(source);
    snprintf(command, sizeof command, "glslangValidator %s %s -o %s.spv >%s.log 2>&1",
             language == SHADER_HLSL ? "-D -V -e main -S frag" : "-V", path, path, path);
    return system(command) == 0;
}

/* ---- The header gtlab wrote before the .inc, transcribed (float) ---- */

/* A coefficient as the generated code spells it: "%.9g" and an f. */
static float literal(double v)
{
    char digits[40];
    snprintf(digits, sizeof digits, "%.9g", v);
    return strtof(digits, NULL);
}

/* "k0 + albedo * (k1 + albedo * (k2))" */
static float previous_rho_polynomial(const double *coef, int degree, float albedo)
{
    float v = literal(coef[degree]);
    for (int k = degree - 1; k >= 0; --k)
        v = literal(coef[k]) + albedo * v;
    return v;
}

static float previous_header_function(const multibounce_model *m, float visibility, float albedo)
{
    float a = previous_rho_polynomial(m->a, m->degree, albedo), b = previous_rho_polynomial(m->b, m->degree, albedo);
    float c = previous_rho_polynomial(m->c, m->degree, albedo);
    float x = visibility, y = ((a * x + b) * x + c) * x;
    return y > x ? y : x;
}

/* Writes the generated header <tmp>/multibounce_test.h and a program
 * <tmp>/multibounce_header_probe.c printing every function on the grid (%a). */
static int write_header_probe(const multibounce_model m[MODELS])
{
    multibounce_shader_function f[MODELS];
    functions_of(m, f);
    char *header = multibounce_c_header_source("/* test */\n", "MB_TEST_H", f, MODELS), path[4200];
    snprintf(path, sizeof path, "%s/multibounce_test.h", check_tmp_dir());
    FILE *out = fopen(path, "w");
    CHECK(header != NULL && out != NULL && strstr(header, multibounce_inc_text) != NULL);
    if (out && header)
        fputs(header, out);
    free(header);
    if (!out || fclose(out) != 0 || !header)
        return -1;
    snprintf(path, sizeof path, "%s/multibounce_header_probe.c", check_tmp_dir());
    if (!(out = fopen(path, "w")))
        return -1;
    fprintf(out, "#include \"multibounce_test.h\"\n#include \"multibounce_test.h\" /* the guard */\n#include <stdio.h>\n"
                 "int main(void)\n{\n    for (int k = 0; k < %d; ++k)\n        for (int i = 0; i < %d; ++i)\n"
                 "            for (int j = 0; j < %d; ++j) {\n"
                 "                float x = (i * 4 - 8) / 512.0f, rho = (j - 2) / 64.0f; /* grid_x, grid_rho */\n"
                 "                printf(\"%%a\\n\", k == 0 ? %s(x, rho) : k == 1 ? %s(x, rho) : %s(x, rho));\n"
                 "            }\n    return 0;\n}\n",
            MODELS, GRID_X, GRID_RHO, kNames[0], kNames[1], kNames[2]);
    return fclose(out);
}

/* Compiles the probe as an engine would (C11, warnings as errors), runs it
 * and reads its values into values[(k GRID_X + i) GRID_RHO + j]. */
static int run_header_probe(float *values)
{
    const char *dir = check_tmp_dir();
    char *command = NULL, path[4200], line[64];
    if (asprintf(&command,
                 "%s -std=c11 -Wall -Wextra -Werror -O2 -ffp-contract=off %s/multibounce_header_probe.c -o "
                 "%s/multibounce_header_probe >%s/multibounce_header_probe.log 2>&1 && "
                 "%s/multibounce_header_probe >%s/multibounce_header_probe.txt",
                 GTLAB_C_COMPILER, dir, dir, dir, dir, dir) < 0)
        return -1;
    int rc = system(command);
    free(command);
    snprintf(path, sizeof path, "%s/multibounce_header_probe.txt", dir);
    FILE *in = rc == 0 ? fopen(path, "r") : NULL;
    int n = 0;
    while (in && n < MODELS * GRID_X * GRID_RHO && fgets(line, sizeof line, in))
        values[n++] = strtof(line, NULL);
    if (in)
        fclose(in);
    return n == MODELS * GRID_X * GRID_RHO ? 0 : -1;
}

static void test_c_header(void)
{
    static float values[MODELS * GRID_X * GRID_RHO];
    multibounce_model m[MODELS];
    test_models(m);
    CHECK_MSG(write_header_probe(m) == 0 && run_header_probe(values) == 0,
              "the generated header does not compile or run (see %s/multibounce_header_probe.log)", check_tmp_dir());
    int mismatches = 0;
    double worst = 0.0;
    for (int k = 0; k < MODELS; ++k)
        for (int i = 0; i < GRID_X; ++i)
            for (int j = 0; j < GRID_RHO; ++j) {
                float got = values[(k * GRID_X + i) * GRID_RHO + j], x = grid_x(i), rho = grid_rho(j);
                mismatches += memcmp(&got, &(float){previous_header_function(&m[k], x, rho)}, sizeof got) != 0;
                worst = fmax(worst, fabs(got - gtao_multibounce(&m[k], x, rho)));
            }
    CHECK_MSG(mismatches == 0, "%d values differ from the header written before multibounce/multibounce.inc", mismatches);
    CHECK_MSG(worst < 1e-5, "largest difference from the C in double %g (float rounding only)", worst);
}

/* Fingerprints of the formula (and of the old hand-written copies) that only
 * multibounce/multibounce.inc may contain. */
static void test_no_second_copy(void)
{
    static const char *const files[] = {"techniques/multibounce/multibounce.c",
                                        "techniques/multibounce/multibounce_shader.c",
                                        "techniques/multibounce/multibounce_fit_outputs.c"};
    static const char *const prints[] = {"* x + b", "* x + c", "x * a", "albedo * ("};
    check_no_file_spells(files, sizeof files / sizeof files[0], prints, sizeof prints / sizeof prints[0]);
}

int main(void)
{
    test_embedded_text_is_the_file();
    test_c_matches_previous_c();
    CHECK_MSG(shader_compiles(SHADER_GLSL), "generated GLSL does not compile (see the .log beside it)");
    CHECK_MSG(shader_compiles(SHADER_HLSL), "generated HLSL does not compile (see the .log beside it)");
    test_c_header();
    test_no_second_copy();
    return check_report("multibounce_shader");
}
