/* Running a generated LUT lookup (a table's writer's GLSL or HLSL: the
 * table as constant arrays, then the lookup's text) on Vulkan against the C
 * lookup of the same table at the same float inputs, within a derived
 * bound. Shared by the LUT techniques' GPU tests (techniques/dfg/,
 * techniques/ltc/, techniques/atmosphere/: tests/test_*_gpu*.c); the shader
 * wraps the functions as tests/gpu/sample_shader.h does. The tables are
 * small and pseudo-random (fill_table): the lookup is under test, and
 * texels differing from their neighbours make a wrong index or axis
 * visible. The points (axis_point): ends, texel centres, edges and grid
 * points, outside the range (the clamps), uniform inside.
 *
 * The bound, u = 2^-24, per output channel c of a table with largest
 * |texel| M_c and largest difference of adjacent texels along axis a
 * D_{a,c} (lookup_bound):
 *   |gpu - c| <= u (10 L M_c + sum_a s_a D_{a,c})
 * - L levels of lerps a + w (b - a), w in [0, 1]: each rounds three times
 *   (|w (b - a)| <= 2 M), 5 u M, and passes its inputs' errors on at most
 *   unchanged (a convex combination); a fused or reordered form rounds
 *   less. Both sides so err by <= 5 u M L: 10 u M L apart.
 * - The weights: a position p off by dp in texel units moves the
 *   interpolant by at most dp D_a (it is continuous, with slope <= D_a
 *   along a, also where the two sides floor p to different texels); the
 *   fractional part p - floor(p) is exact where it matters (p >= 0; below,
 *   both indices clamp to texel 0). s_a bounds dp / u: each table's test
 *   derives its own from its lookup's position arithmetic.
 * Each function here is static: CHECK counts in the including test, which
 * defines _GNU_SOURCE before any include (asprintf, sample_shader.h). */
#ifndef GTLAB_TESTS_GPU_LUT_SHADER_CHECK_H
#define GTLAB_TESTS_GPU_LUT_SHADER_CHECK_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/sampling/splitmix64.h"
#include "gpu/sample_map.h"
#include "gpu/shader_compiler.h"
#include "gpu/vulkan_device.h"
#include "tests/check.h"
#include "tests/gpu/sample_shader.h"

static const double kU = 1.0 / 16777216.0; /* 2^-24 */

enum { SAMPLES = 1 << 14, MAX_OUTPUTS = 6, AXES = 4 };

/* ---- Tables and their scales ---- */

/* Pseudo-random texels in [-1, 1) times a scale per channel. */
static void fill_table(float *data, size_t texels, int channels, unsigned long long seed)
{
    for (size_t t = 0; t < texels; ++t)
        for (int c = 0; c < channels; ++c)
            data[t * channels + c] = (float)((2.0 * splitmix64_uniform01(&seed) - 1.0) * (1 + 3 * c));
}

/* One channel of a table with axes of sizes n[0..3] (axis 0 fastest) and
 * `channels` floats a texel: M and D_a of the bound. */
typedef struct {
    double magnitude, step[AXES];
} table_scale;

static table_scale channel_scale(const float *data, const int n[AXES], int channels, int channel)
{
    table_scale s = {0.0, {0.0}};
    size_t stride[AXES] = {1, (size_t)n[0], (size_t)n[0] * n[1], (size_t)n[0] * n[1] * n[2]};
    size_t texels = stride[3] * n[3];
    for (size_t t = 0; t < texels; ++t) {
        double v = data[t * channels + channel];
        s.magnitude = fmax(s.magnitude, fabs(v));
        for (int a = 0; a < AXES; ++a)
            if ((t / stride[a]) % n[a] + 1 < (size_t)n[a])
                s.step[a] = fmax(s.step[a], fabs(data[(t + stride[a]) * channels + channel] - v));
    }
    return s;
}

/* u (10 L M + sum_a s_a D_a). */
static double lookup_bound(const table_scale *s, int levels, const double slack[AXES])
{
    double b = 10.0 * levels * s->magnitude;
    for (int a = 0; a < AXES; ++a)
        b += slack[a] * s->step[a];
    return kU * b;
}

/* The bounds of an N x N table's channels (bilinear: L = 2), s_x and s_y of
 * the two axes. */
static inline void square_bounds(const float *data, int size, int channels, double s_x, double s_y, double *bound)
{
    int n[AXES] = {size, size, 1, 1};
    double slack[AXES] = {s_x, s_y, 0.0, 0.0};
    for (int c = 0; c < channels; ++c) {
        table_scale sc = channel_scale(data, n, channels, c);
        bound[c] = lookup_bound(&sc, 2, slack);
    }
}

/* ---- Inputs ---- */

/* A coordinate on an axis [0, top] of n texels (centred: texel centres at
 * (i + 1/2) / n, else grid points i / (n - 1)): an end, a centre, an edge or
 * a point between them, outside the range, or uniform inside it. */
static float axis_point(unsigned long long *state, double top, int n, int centred)
{
    int kind = (int)(8.0 * splitmix64_uniform01(state)), m = centred ? 2 * n : (n > 1 ? 2 * (n - 1) : 2);
    double r = splitmix64_uniform01(state);
    switch (kind) {
    case 0: return 0.0f;
    case 1: return (float)top;
    case 2: return (float)(top * (int)(r * (m + 1)) / m);
    case 3: return (float)(-0.1 * top * r);
    case 4: return (float)(top * (1.0 + 0.1 * r));
    default: return (float)(top * r);
    }
}

/* ---- Running one shader against the C ---- */

/* A generated file under test: its text, the per-sample body (the same in
 * both languages: the dialect's own type names), its inputs and the C. */
typedef struct {
    const char *name;
    int inputs, outputs;
    const char *body;
    void (*c)(const void *table, const float *x, float *out);
    const void *table;
    const double *bound; /* per output channel */
} lookup_case;

/* Worst |gpu - c| / bound over the samples and outputs; *largest: the
 * largest |gpu - c|. */
static double compare(const lookup_case *k, const float *in, const float *out, double *largest)
{
    double worst = 0.0;
    float want[MAX_OUTPUTS];
    *largest = 0.0;
    for (int s = 0; s < SAMPLES; ++s) {
        k->c(k->table, in + (size_t)s * k->inputs, want);
        for (int o = 0; o < k->outputs; ++o) {
            double d = fabs((double)out[(size_t)s * k->outputs + o] - want[o]);
            worst = fmax(worst, d / k->bound[o]);
            *largest = fmax(*largest, d);
        }
    }
    return worst;
}

/* Runs the generated file at `path` over `in` and compares it with the C. */
static void run_case(gpu_device *g, const lookup_case *k, const char *path, const float *in)
{
    char *functions = NULL, *source = NULL;
    float *out = malloc(sizeof(float) * MAX_OUTPUTS * SAMPLES);
    gt_error e = {{0}};
    int rc = gpu_read_source(path, &functions, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    shader_language language = strstr(path, ".glsl") ? SHADER_GLSL : SHADER_HLSL;
    source = rc == 0 ? test_sample_shader(language, functions, k->body) : NULL;
    CHECK(out && (rc != 0 || source));
    if (source && out) {
        rc = gpu_sample_map(g, source, path, NULL, in, k->inputs, out, k->outputs, SAMPLES, 60.0, &e);
        CHECK_MSG(rc == 0, "%s", e.message);
        double largest = 0.0, worst = rc == 0 ? compare(k, in, out, &largest) : 1e30;
        printf("%s (%s): %d samples x %d outputs, worst |gpu - c| = %.3g of the bound (largest %.3g)\n", k->name,
               language == SHADER_GLSL ? "GLSL" : "HLSL", SAMPLES, k->outputs, worst, largest);
        CHECK_MSG(worst <= 1.0, "%s: %g of the bound", path, worst);
    }
    free(functions), free(source), free(out);
}

/* The generated file's path in the scratch folder. */
static void scratch_path(char *path, size_t size, const char *file)
{
    snprintf(path, size, "%s/lut_shader_%s", check_tmp_dir(), file);
}

/* A writer of the table's GLSL (glsl = 1) or HLSL, and both run. */
typedef int (*shader_writer)(const char *path, int glsl, const void *table, gt_error *e);

static void run_both(gpu_device *g, const lookup_case *k, const float *in, const char *base, shader_writer write)
{
    for (int glsl = 1; glsl >= 0; --glsl) {
        char file[256], path[4096];
        gt_error e = {{0}};
        snprintf(file, sizeof file, "%s.%s", base, glsl ? "glsl" : "hlsl");
        scratch_path(path, sizeof path, file);
        int rc = write(path, glsl, k->table, &e);
        CHECK_MSG(rc == 0, "%s", e.message);
        if (rc == 0)
            run_case(g, k, path, in);
    }
}

#endif
