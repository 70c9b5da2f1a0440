/* The atmosphere tables' generated lookups, executed (issue 15, item 4):
 * AtmosphereInscatterRayleigh/Mie and AtmosphereSun/Sky as
 * atmosphere_luts_writers.c writes them (the tables as constant arrays,
 * then the text of atmosphere_luts.inc), GLSL and HLSL, run on Vulkan at
 * pseudo-random points and compared with the C lookups
 * (atmosphere_lut_inscatter, atmosphere_lut_light) of the same tables at
 * the same float inputs, within the bound of tests/gpu/lut_shader_check.h.
 * Two texels along each interpolated axis: three take lavapipe's JIT over
 * a minute (the production tables are for real compilers).
 *
 * The bound's weights (four axes: L = 4 levels of lerps): p = saturate(x /
 * max) (N - 1): the C's division is correctly rounded, Vulkan's within 2.5
 * ulp (5 u), and the product rounds once (2 u and 6 u of N - 1), plus 2 u
 * should the shader's decimal axis end round to another float than the
 * C's: s = 10 (N - 1). */
#define _GNU_SOURCE
#include "atmosphere/atmosphere_luts.h"
#include "atmosphere/atmosphere_luts_writers.h"
#include "tests/gpu/lut_shader_check.h"

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
        test_atmosphere(g);
        gpu_device_close(g);
    }
    return check_report("test_gpu_atmosphere_shader");
}
