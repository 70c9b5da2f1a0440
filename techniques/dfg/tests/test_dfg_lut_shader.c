/* One source for the DFG table's lookup (luts/table_lookup.inc): dfg_lut_sample,
 * compiled from it, gives the same bits as the lookup written before it
 * (transcribed here); the shaders' half of the .inc, compiled here as C with
 * the shaders' table access, gives the same bits as dfg_lut_sample; the
 * generated HLSL and GLSL carry the .inc verbatim, with that table access,
 * and compile; no other file spells the lookup. On a small table of
 * arbitrary values: the lookup does not care what the texels hold. */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dfg/dfg_lut_writers.h"
#include "luts/dfg_lut.h"
#include "luts/table_lookup.h"
#include "tests/check.h"
#include "tests/source_text.h"

/* ---- The shaders' half of the .inc as C: the shaders' dialect (dfg/dfg_lut_writers.c)
 * with the table DFG_LUT a global array, one channel at a time ---- */
#define DFG_LUT_SIZE 7
static float DFG_LUT[DFG_LUT_SIZE * DFG_LUT_SIZE];
#define DFG_LUT_SHADER
#define DFG_FN static inline
#define dfg_floor floorf
#define dfg_float(i) ((float)(i))
#define dfg_int(x) ((int)(x))
#define dfg_table int
#define dfg_table_size(t) DFG_LUT_SIZE
#define dfg_texel(t, i, j) DFG_LUT[(j) * DFG_LUT_SIZE + (i)]
#define dfg_value float
typedef struct {
    int i0, i1;
    float w;
} dfg_axis;
static inline float dfg_saturate(float u) { return fminf(fmaxf(u, 0.0f), 1.0f); }
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter" /* the placeholder table */
#include "luts/table_lookup.inc"
#pragma GCC diagnostic pop

/* The lines of the generated shaders that the definitions above mirror. */
static const char *const kShaderTableAccess[] = {"#define dfg_table_size(t) DFG_LUT_SIZE\n",
                                                 "#define dfg_texel(t, i, j) DFG_LUT[(j) * DFG_LUT_SIZE + (i)]\n"};


/* A DFG_LUT_SIZE^2 table of arbitrary values in [0, 1). */
static void arbitrary_table(dfg_lut *lut)
{
    lut->size = DFG_LUT_SIZE;
    lut->data = malloc(sizeof *lut->data * DFG_LUT_SIZE * DFG_LUT_SIZE * DFG_CHANNELS);
    lut->error_estimate = NULL;
    lut->max_error_estimate = 0.0;
    unsigned state = 12345u;
    for (int t = 0; lut->data && t < DFG_LUT_SIZE * DFG_LUT_SIZE * DFG_CHANNELS; ++t) {
        state = state * 1664525u + 1013904223u;
        lut->data[t] = (float)(state >> 8) / 16777216.0f;
    }
}

/* ---- dfg_lut_sample as written before the .inc, transcribed ---- */

static void previous_axis(float u, int n, int *i0, int *i1, float *w)
{
    float x = fminf(fmaxf(u, 0.0f), 1.0f) * (float)n - 0.5f, f = floorf(x);
    int i = (int)f;
    *w = x - f;
    *i0 = i < 0 ? 0 : i > n - 1 ? n - 1 : i;
    *i1 = i + 1 < 0 ? 0 : i + 1 > n - 1 ? n - 1 : i + 1;
}

static float previous_lerp(float a, float b, float w) { return a + w * (b - a); }

static void previous_sample(const dfg_lut *lut, float n_dot_v, float roughness, float out[3])
{
    int n = lut->size, i0, i1, j0, j1;
    float wx, wy;
    previous_axis(n_dot_v, n, &i0, &i1, &wx);
    previous_axis(roughness, n, &j0, &j1, &wy);
    const float *d = lut->data;
    for (int c = 0; c < DFG_CHANNELS; ++c) {
        float top = previous_lerp(d[((size_t)j0 * n + i0) * 3 + c], d[((size_t)j0 * n + i1) * 3 + c], wx);
        float bottom = previous_lerp(d[((size_t)j1 * n + i0) * 3 + c], d[((size_t)j1 * n + i1) * 3 + c], wx);
        out[c] = previous_lerp(top, bottom, wy);
    }
}

/* The grid: n.v and r from -0.2 to 1.2 in steps of 1/160, beyond the edges on both sides. */
enum { GRID = 225 };
static float grid(int i) { return -0.2f + i / 160.0f; }

static void test_lookup_matches_previous_and_shader(const dfg_lut *lut)
{
    int previous_mismatches = 0, shader_mismatches = 0;
    for (int c = 0; c < DFG_CHANNELS; ++c) {
        for (int t = 0; t < DFG_LUT_SIZE * DFG_LUT_SIZE; ++t)
            DFG_LUT[t] = lut->data[t * DFG_CHANNELS + c];
        for (int i = 0; i < GRID; ++i)
            for (int j = 0; j < GRID; ++j) {
                float got[3], want[3], shader = DFG(grid(i), grid(j));
                dfg_lut_sample(lut, grid(i), grid(j), got);
                previous_sample(lut, grid(i), grid(j), want);
                previous_mismatches += memcmp(&got[c], &want[c], sizeof(float)) != 0;
                shader_mismatches += memcmp(&got[c], &shader, sizeof(float)) != 0;
            }
    }
    CHECK_MSG(previous_mismatches == 0, "%d values differ from the lookup before luts/table_lookup.inc", previous_mismatches);
    CHECK_MSG(shader_mismatches == 0, "%d values differ between the C and the shaders' DFG()", shader_mismatches);
    /* The lookup is the table at texel centres (i + 0.5)/N. */
    float v[3];
    dfg_lut_sample(lut, 2.5f / DFG_LUT_SIZE, 4.5f / DFG_LUT_SIZE, v);
    CHECK(v[DFG_BIAS] == lut->data[(4 * DFG_LUT_SIZE + 2) * DFG_CHANNELS + DFG_BIAS]);
}

static void test_embedded_text_is_the_file(void)
{
    char *text = read_text(GTLAB_SOURCE_DIR "/luts/table_lookup.inc");
    CHECK(text != NULL && strcmp(text, table_lookup_inc_text) == 0);
    free(text);
}

/* The generated shader (HLSL or GLSL) carries the .inc and the table access
 * mirrored above, and compiles with glslangValidator in a fragment shader. */
static int shader_compiles(const dfg_lut *lut, int hlsl)
{
    char path[4096], main_path[4200], command[16384];
    gt_error e;
    snprintf(path, sizeof path, "%s/dfg_shader.%s", check_tmp_dir(), hlsl ? "hlsl" : "glsl");
    int rc = hlsl ? dfg_lut_write_hlsl(path, "DFG_LUT", lut, &e) : dfg_lut_write_glsl(path, "DFG_LUT", lut, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    char *text = rc == 0 ? read_text(path) : NULL;
    CHECK(text != NULL && strstr(text, table_lookup_inc_text) != NULL);
    for (size_t k = 0; text && k < sizeof kShaderTableAccess / sizeof kShaderTableAccess[0]; ++k)
        CHECK_MSG(strstr(text, kShaderTableAccess[k]) != NULL, "the shader lacks %s", kShaderTableAccess[k]);
    snprintf(main_path, sizeof main_path, "%s.%s", path, hlsl ? "hlsl" : "frag");
    FILE *out = fopen(main_path, "w");
    if (!text || !out) {
        free(text);
        return 0;
    }
    if (hlsl)
        fprintf(out, "%s\nfloat4 main(float4 v : TEXCOORD0) : SV_Target { return float4(DFG(v.x, v.y), 1.0); }\n",
                text);
    else
        fprintf(out, "#version 450\n%s\nlayout(location = 0) in vec4 v;\nlayout(location = 0) out vec4 o;\n"
                     "void main() { o = vec4(DFG(v.x, v.y), 1.0); }\n",
                text);
    fclose(out);
    free(text);
    snprintf(command, sizeof command, "glslangValidator %s %s -o %s.spv >%s.log 2>&1",
             hlsl ? "-D -V -e main -S frag" : "-V", main_path, main_path, main_path);
    return system(command) == 0;
}

/* Fingerprints of the lookup (and of the old hand-written HLSL) that only
 * luts/table_lookup.inc may contain. */
static void test_no_second_copy(void)
{
    static const char *const files[] = {"luts/dfg_lut.c", "techniques/dfg/dfg_lut_writers.c",
                                         "techniques/dfg/dfg_interpolation.c"};
    static const char *const prints[] = {"lerp", "floor(", "floorf(", "DFGAxis", "i0 ="};
    check_no_file_spells(files, sizeof files / sizeof files[0], prints, sizeof prints / sizeof prints[0]);
}

int main(void)
{
    dfg_lut lut;
    arbitrary_table(&lut);
    CHECK(lut.data != NULL);
    if (!lut.data)
        return check_report("dfg_lut_shader");
    test_embedded_text_is_the_file();
    test_lookup_matches_previous_and_shader(&lut);
    CHECK_MSG(shader_compiles(&lut, 1), "generated HLSL does not compile (see the .log beside it)");
    CHECK_MSG(shader_compiles(&lut, 0), "generated GLSL does not compile (see the .log beside it)");
    test_no_second_copy();
    dfg_lut_free(&lut);
    return check_report("dfg_lut_shader");
}
