#define _GNU_SOURCE
#include "multibounce/multibounce_shader.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The dialects of multibounce/multibounce.inc. C: float, and the max as the
 * earlier generated headers wrote it (no <math.h> needed). */
static const char c_dialect[] = "#define MB_FN static inline\n"
                                "typedef float mb_real;\n"
                                "typedef float mb_color;\n"
                                "static inline float mb_max(float y, float x) { return y > x ? y : x; }\n";

static const char hlsl_dialect[] = "#define MB_FN\n"
                                   "#define mb_real float\n"
                                   "#define mb_color float3\n"
                                   "#define mb_max max\n";

static const char glsl_dialect[] = "#define MB_FN\n"
                                   "#define mb_real float\n"
                                   "#define mb_color vec3\n"
                                   "#define mb_max max\n";

/* The language's words for one generated function. */
typedef struct {
    const char *dialect, *color, *returns, *comment_open, *comment_close;
} language_words;

static const language_words kC = {c_dialect, "float", "static inline float", "/* ", " */"};
static const language_words kHlsl = {hlsl_dialect, "float3", "float3", "// ", ""};
static const language_words kGlsl = {glsl_dialect, "vec3", "vec3", "// ", ""};

/* A float literal C, HLSL and GLSL (1.30 and later) all read: "1.0f", "-0.410470316f", "2e-05f". */
static void print_literal(FILE *out, double v)
{
    char digits[40];
    snprintf(digits, sizeof digits, "%.9g", v);
    fprintf(out, "%s%sf", digits, strpbrk(digits, ".e") ? "" : ".0");
}

/* "    float3 a = mb_rho_linear(k0, k1, albedo);" for the polynomial coef. */
static void print_coefficient(FILE *out, const language_words *w, char name, const double *coef, int degree)
{
    int terms = degree == 1 ? 2 : 3;
    fprintf(out, "    %s %c = mb_rho_%s(", w->color, name, degree == 1 ? "linear" : "quadratic");
    for (int k = 0; k < terms; ++k)
        print_literal(out, coef[k]), fputs(", ", out);
    fputs("albedo);\n", out);
}

static void print_function(FILE *out, const language_words *w, const multibounce_shader_function *f)
{
    const multibounce_model *m = &f->model;
    fprintf(out, "\n%s%s%s\n%s %s(float visibility, %s albedo)\n{\n", w->comment_open, f->comment, w->comment_close,
            w->returns, f->name, w->color);
    print_coefficient(out, w, 'a', m->a, m->degree);
    print_coefficient(out, w, 'b', m->b, m->degree);
    print_coefficient(out, w, 'c', m->c, m->degree);
    fputs("    return mb_multibounce(a, b, c, visibility);\n}\n", out);
}

/* preamble, [guard], dialect, the .inc, the functions, [#endif]. */
static char *source(const language_words *w, const char *preamble, const char *guard,
                    const multibounce_shader_function *functions, int count)
{
    char *text = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&text, &size);
    if (!out)
        return NULL;
    fputs(preamble, out);
    if (guard)
        fprintf(out, "#ifndef %s\n#define %s\n", guard, guard);
    fprintf(out, "\n%s\n%s", w->dialect, multibounce_inc_text);
    for (int i = 0; i < count; ++i)
        print_function(out, w, &functions[i]);
    if (guard)
        fputs("\n#endif\n", out);
    int failed = ferror(out);
    if (fclose(out) != 0 || failed) {
        free(text);
        return NULL;
    }
    return text;
}

char *multibounce_shader_source(shader_language language, const char *preamble,
                                const multibounce_shader_function *functions, int count)
{
    return source(language == SHADER_HLSL ? &kHlsl : &kGlsl, preamble, NULL, functions, count);
}

char *multibounce_c_header_source(const char *preamble, const char *guard,
                                  const multibounce_shader_function *functions, int count)
{
    return source(&kC, preamble, guard, functions, count);
}
