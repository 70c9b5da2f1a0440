/* gtlab's generated LUT shaders, executed (issue 15, item 4): the DFG
 * table's DFG(), the LTC table's LTC_INVERSE_M and LTC_MAGNITUDE_FRESNEL and
 * the atmosphere tables' AtmosphereInscatterRayleigh/Mie and
 * AtmosphereSun/Sky, each as its writer writes it (dfg/dfg_lut_writers.c,
 * luts/ltc_ggx_writers.c, luts/atmosphere_luts_writers.c: the tables as
 * constant arrays, then the lookup's text, luts/table_lookup.inc or
 * luts/atmosphere_luts.inc), GLSL and HLSL, wrapped into a compute shader
 * (tests/gpu/sample_shader.h), run on Vulkan at pseudo-random points (ends,
 * texel centres, edges and grid points, outside the range: the clamps) and
 * compared with the C lookups (dfg_lut_sample, ltc_table_sample,
 * atmosphere_lut_inscatter, atmosphere_lut_light) of the same tables at the
 * same float inputs. The tables are small and pseudo-random: the lookup is
 * under test, and texels differing from their neighbours make a wrong index
 * or axis visible. Small, too, because lavapipe's JIT lowers a constant
 * array indexed at run time to code whose compile time grows steeply with
 * the array and the number of reads: 8 x 8 DFG and 4 x 4 LTC texels, and
 * two along each interpolated atmosphere axis, compile in about a second
 * each; 16 x 16, 8 x 8 and three take over a minute (the production tables
 * are for real compilers).
 *
 * The bound (docs/decisions.md), u = 2^-24, per output channel c of a table
 * with largest |texel| M_c and largest difference of adjacent texels along
 * axis a D_{a,c}:
 *   |gpu - c| <= u (10 L M_c + sum_a s_a D_{a,c})
 * - L levels of lerps a + w (b - a), w in [0, 1] (L = 2 bilinear, 4 for the
 *   atmosphere's four axes): each rounds
 *   three times (|w (b - a)| <= 2 M), 5 u M, and passes its inputs' errors on
 *   at most unchanged (a convex combination); a fused or reordered form
 *   rounds less. Both sides so err by <= 5 u M L: 10 u M L apart.
 * - The weights: a position p off by dp in texel units moves the
 *   interpolant by at most dp D_a (it is continuous, with slope <= D_a
 *   along a, also where the two sides floor p to different texels); the
 *   fractional part p - floor(p) is exact where it matters (p >= 0; below,
 *   both indices clamp to texel 0). s_a bounds dp / u: x = saturate(u) N -
 *   0.5 is two correctly rounded operations (Vulkan's +, *), <= 2 u N each
 *   side: s = 4 N. LTC's first axis adds sqrt(1 - n.v) (Vulkan: 1 /
 *   inversesqrt, taken as 16 u relative as in test_gpu_specular_occlusion.c),
 *   times N: s = 20 N. Atmosphere, p = saturate(x / max) (N - 1): the C's
 *   division is correctly rounded, Vulkan's within 2.5 ulp (5 u), and the
 *   product rounds once (2 u and 6 u of N - 1), plus 2 u should the
 *   shader's decimal axis end round to another float than the C's:
 *   s = 10 (N - 1). */
#define _GNU_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/splitmix64.h"
#include "dfg/dfg_lut_writers.h"
#include "gpu/sample_map.h"
#include "gpu/shader_compiler.h"
#include "gpu/vulkan_device.h"
#include "luts/atmosphere_luts.h"
#include "luts/atmosphere_luts_writers.h"
#include "luts/dfg_lut.h"
#include "luts/ltc_ggx.h"
#include "luts/ltc_ggx_writers.h"
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
    snprintf(path, size, "%s/test_gpu_lut_shaders_%s", check_tmp_dir(), file);
}

/* The bounds of an N x N table's channels (bilinear: L = 2), s_x and s_y of
 * the two axes. */
static void square_bounds(const float *data, int size, int channels, double s_x, double s_y, double *bound)
{
    int n[AXES] = {size, size, 1, 1};
    double slack[AXES] = {s_x, s_y, 0.0, 0.0};
    for (int c = 0; c < channels; ++c) {
        table_scale sc = channel_scale(data, n, channels, c);
        bound[c] = lookup_bound(&sc, 2, slack);
    }
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

/* ---- DFG ---- */

enum { DFG_N = 8 };

static void dfg_c(const void *table, const float *x, float *out) { dfg_lut_sample(table, x[0], x[1], out); }

static int dfg_write(const char *path, int glsl, const void *table, gt_error *e)
{
    return glsl ? dfg_lut_write_glsl(path, "gtlab_test_dfg", table, e)
                : dfg_lut_write_hlsl(path, "gtlab_test_dfg", table, e);
}

static void test_dfg(gpu_device *g)
{
    dfg_lut lut = {DFG_N, malloc(sizeof(float) * DFG_N * DFG_N * DFG_CHANNELS), NULL, 0.0};
    float *in = malloc(sizeof(float) * 2 * SAMPLES);
    CHECK(lut.data && in);
    if (!lut.data || !in) {
        free(lut.data), free(in);
        return;
    }
    fill_table(lut.data, DFG_N * DFG_N, DFG_CHANNELS, 1);
    unsigned long long state = 2;
    for (int s = 0; s < 2 * SAMPLES; ++s)
        in[s] = axis_point(&state, 1.0, DFG_N, 1);
    double bound[DFG_CHANNELS];
    square_bounds(lut.data, DFG_N, DFG_CHANNELS, 4.0 * DFG_N, 4.0 * DFG_N, bound);
    lookup_case k = {"DFG", 2, DFG_CHANNELS,
                     "    dfg_value d = DFG(v[2u * i], v[2u * i + 1u]);\n"
                     "    r[3u * i] = d.x; r[3u * i + 1u] = d.y; r[3u * i + 2u] = d.z;\n",
                     dfg_c, &lut, bound};
    run_both(g, &k, in, "dfg", dfg_write);
    free(lut.data), free(in);
}

/* ---- LTC ---- */

enum { LTC_N = 4 };

static void ltc_c(const void *table, const float *x, float *out) { ltc_table_sample(table, x[0], x[1], out); }

static int ltc_write(const char *path, int glsl, const void *table, gt_error *e)
{
    return glsl ? ltc_ggx_write_glsl(path, "gtlab_test_ltc", table, e)
                : ltc_ggx_write_hlsl(path, "gtlab_test_ltc", table, e);
}

static void test_ltc(gpu_device *g)
{
    ltc_table t;
    float *in = malloc(sizeof(float) * 2 * SAMPLES);
    int allocated = ltc_table_alloc(&t, LTC_N) == 0;
    CHECK(allocated && in);
    if (!allocated || !in) {
        free(in);
        return;
    }
    fill_table(t.data, LTC_N * LTC_N, LTC_CHANNELS, 3);
    unsigned long long state = 4;
    for (int s = 0; s < SAMPLES; ++s) { /* n.v = 1 - u^2 at u's special points; roughness */
        float u = axis_point(&state, 1.0, LTC_N, 1);
        in[2 * s] = 1.0f - u * u, in[2 * s + 1] = axis_point(&state, 1.0, LTC_N, 1);
    }
    double bound[LTC_CHANNELS];
    square_bounds(t.data, LTC_N, LTC_CHANNELS, 20.0 * LTC_N, 4.0 * LTC_N, bound);
    lookup_case k = {"LTC", 2, LTC_CHANNELS,
                     "    dfg_value m = LTC_INVERSE_M(v[2u * i], v[2u * i + 1u]);\n"
                     "    dfg_value f = LTC_MAGNITUDE_FRESNEL(v[2u * i], v[2u * i + 1u]);\n"
                     "    r[6u * i] = m.x; r[6u * i + 1u] = m.y; r[6u * i + 2u] = m.z; r[6u * i + 3u] = m.w;\n"
                     "    r[6u * i + 4u] = f.x; r[6u * i + 5u] = f.y;\n",
                     ltc_c, &t, bound};
    run_both(g, &k, in, "ltc", ltc_write);
    ltc_table_free(&t), free(in);
}

/* ---- Atmosphere ---- */

/* Two texels along each interpolated axis: more takes lavapipe's JIT over
 * a minute (the four-table fetch is inlined at every one of 16 texel reads). */
static const atmosphere_lut_sizes kAtmoSizes = {{2, 2, 2, 1}, {2, 1, 2, 2}, {2, 1, 1, 1}};

enum { ATMO_RAYLEIGH, ATMO_MIE, ATMO_SUN, ATMO_SKY, ATMO_FUNCTIONS };

/* Function f of the four at sample x (theta_s, theta_v, y, t): the C. */
static void atmo_eval(const atmosphere_luts *luts, int f, const float *x, float *out)
{
    float L[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS];
    if (f == ATMO_SUN || f == ATMO_SKY) {
        atmosphere_lut_light(luts, f == ATMO_SUN ? ATMOSPHERE_TABLE_SUN : ATMOSPHERE_TABLE_SKY, x[0], x[2], x[3], out);
        return;
    }
    atmosphere_lut_inscatter(luts, x[0], x[1], x[2], x[3], L);
    for (int c = 0; c < 3; ++c)
        out[c] = L[f == ATMO_RAYLEIGH ? ATMOSPHERE_RAYLEIGH : ATMOSPHERE_MIE][c];
}

static void atmo_rayleigh_c(const void *t, const float *x, float *out) { atmo_eval(t, ATMO_RAYLEIGH, x, out); }
static void atmo_mie_c(const void *t, const float *x, float *out) { atmo_eval(t, ATMO_MIE, x, out); }
static void atmo_sun_c(const void *t, const float *x, float *out) { atmo_eval(t, ATMO_SUN, x, out); }
static void atmo_sky_c(const void *t, const float *x, float *out) { atmo_eval(t, ATMO_SKY, x, out); }

static const struct {
    const char *name, *call;
    void (*c)(const void *, const float *, float *);
} kAtmoFunctions[ATMO_FUNCTIONS] = {
    {"atmosphere Rayleigh", "AtmosphereInscatterRayleigh(v[b], v[b + 1u], v[b + 2u], v[b + 3u])", atmo_rayleigh_c},
    {"atmosphere Mie", "AtmosphereInscatterMie(v[b], v[b + 1u], v[b + 2u], v[b + 3u])", atmo_mie_c},
    {"atmosphere sun", "AtmosphereSun(v[b], v[b + 2u], v[b + 3u])", atmo_sun_c},
    {"atmosphere sky", "AtmosphereSky(v[b], v[b + 2u], v[b + 3u])", atmo_sky_c}};

/* The bounds of function f's 3 channels (L = 4 levels of lerps). */
static void atmo_bounds(const atmosphere_luts *luts, int f, double bound[3])
{
    const int *sizes[ATMOSPHERE_TABLES] = {luts->sizes.inscatter, luts->sizes.sun, luts->sizes.sky};
    int table = f <= ATMO_MIE ? ATMOSPHERE_TABLE_INSCATTER
                              : f == ATMO_SUN ? ATMOSPHERE_TABLE_SUN : ATMOSPHERE_TABLE_SKY;
    double slack[AXES];
    for (int a = 0; a < AXES; ++a)
        slack[a] = 10.0 * (sizes[table][a] - 1);
    for (int c = 0; c < 3; ++c) {
        table_scale sc = channel_scale(luts->table[table], sizes[table], table ? 3 : 6, (f == ATMO_MIE ? 3 : 0) + c);
        bound[c] = lookup_bound(&sc, 4, slack);
    }
}

static void atmo_inputs(const atmosphere_luts *luts, float *in)
{
    const double top[AXES] = {ATMOSPHERE_LUT_THETA_S_MAX, ATMOSPHERE_LUT_THETA_V_MAX, luts->max_altitude, 1.0};
    unsigned long long state = 6;
    for (int s = 0; s < SAMPLES; ++s)
        for (int a = 0; a < AXES; ++a)
            in[AXES * s + a] = axis_point(&state, top[a], 2, 0);
}

static int atmo_write(const char *path, int glsl, const void *table, gt_error *e)
{
    return atmosphere_luts_write_shader(path, glsl, table, e);
}

static void run_atmosphere(gpu_device *g, const atmosphere_luts *luts, const float *in)
{
    for (int f = 0; f < ATMO_FUNCTIONS; ++f) {
        char body[512];
        double bound[3];
        snprintf(body, sizeof body,
                 "    uint b = 4u * i;\n    atmo_value o = %s;\n"
                 "    r[3u * i] = o.x; r[3u * i + 1u] = o.y; r[3u * i + 2u] = o.z;\n",
                 kAtmoFunctions[f].call);
        atmo_bounds(luts, f, bound);
        lookup_case k = {kAtmoFunctions[f].name, AXES, 3, body, kAtmoFunctions[f].c, luts, bound};
        run_both(g, &k, in, "atmosphere", atmo_write);
    }
}

static void test_atmosphere(gpu_device *g)
{
    atmosphere_luts luts;
    memset(&luts, 0, sizeof luts);
    luts.max_altitude = 1500.0, luts.sizes = kAtmoSizes;
    const int *sizes[ATMOSPHERE_TABLES] = {luts.sizes.inscatter, luts.sizes.sun, luts.sizes.sky};
    int ok = 1;
    for (int t = 0; t < ATMOSPHERE_TABLES; ++t) {
        size_t texels = (size_t)sizes[t][0] * sizes[t][1] * sizes[t][2] * sizes[t][3];
        int channels = t == ATMOSPHERE_TABLE_INSCATTER ? 6 : 3;
        luts.table[t] = malloc(sizeof(float) * texels * channels);
        ok = ok && luts.table[t];
        if (luts.table[t])
            fill_table(luts.table[t], texels, channels, 7 + t);
    }
    float *in = malloc(sizeof(float) * AXES * SAMPLES);
    CHECK(ok && in);
    if (ok && in) {
        atmo_inputs(&luts, in);
        run_atmosphere(g, &luts, in);
    }
    for (int t = 0; t < ATMOSPHERE_TABLES; ++t)
        free(luts.table[t]);
    free(in);
}

int main(void)
{
    gpu_device *g = NULL;
    gt_error e = {{0}};
    CHECK_MSG(gpu_device_open(NULL, &g, &e) == 0, "%s", e.message);
    if (g) {
        test_dfg(g);
        test_ltc(g);
        test_atmosphere(g);
        gpu_device_close(g);
    }
    return check_report("test_gpu_lut_shaders");
}
