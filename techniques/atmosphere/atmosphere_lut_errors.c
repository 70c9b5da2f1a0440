/* The atmosphere LUTs' errors at random points; see atmosphere_lut_errors.h. */
#include "atmosphere/atmosphere_lut_errors.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/statistics/bootstrap.h"
#include "core/optics/phase_function.h"
#include "core/sampling/splitmix64.h"
#include "core/vec3.h" /* M_PI */

static const double SINGLE_TOLERANCE = 1e-7, MULTIPLE_TOLERANCE = 1e-6, FLOOR = 1e-3;

/* The three tables' values at p by `how` into v[table][k]; returns the
 * references' largest error estimate. */
static double evaluate(const atmosphere_solution *s, atmosphere_method how, const atmosphere_lut_point *p,
                       double v[ATMOSPHERE_TABLES][ATMOSPHERE_LUT_VALUES])
{
    double r = s->model.bottom_radius + p->altitude, mu = cos(p->theta_v), mu_s = cos(p->theta_s);
    double S[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS], M[3], T[3], sky[3];
    double e1 = atmosphere_single_scattering(s, how, r, mu, mu_s, SINGLE_TOLERANCE, S);
    double e2 = atmosphere_multiple_scattering(s, how, r, mu, mu_s, MULTIPLE_TOLERANCE, M);
    double pbar = atmosphere_azimuthal_phase(ATMOSPHERE_RAYLEIGH, s->model.mie_g, mu, mu_s);
    atmosphere_transmittance_to_sun(s, how, r, mu_s, T);
    double e3 = atmosphere_sky_mean_radiance(s, how == ATMOSPHERE_FAST ? how : ATMOSPHERE_ADAPTIVE, r, mu_s, 0.0, sky);
    memset(v, 0, sizeof(double) * ATMOSPHERE_TABLES * ATMOSPHERE_LUT_VALUES);
    for (int c = 0; c < 3; ++c) {
        v[ATMOSPHERE_TABLE_INSCATTER][c] = S[ATMOSPHERE_RAYLEIGH][c] + M[c] / pbar;
        v[ATMOSPHERE_TABLE_INSCATTER][3 + c] = S[ATMOSPHERE_MIE][c];
        v[ATMOSPHERE_TABLE_SUN][c] = s->model.solar_irradiance[c] * T[c];
        v[ATMOSPHERE_TABLE_SKY][c] = sky[c];
    }
    return fmax(e1, fmax(e2, e3));
}

static void draw_points(atmosphere_lut_reference *ref, const atmosphere_solution *solutions, int count, unsigned seed)
{
    unsigned long long state = (unsigned long long)seed * 0x2545f4914f6cdd1dull + 7u;
    for (int i = 0; i < ref->count; ++i) {
        atmosphere_lut_point *p = &ref->points[i];
        p->theta_s = splitmix64_uniform01(&state) * ATMOSPHERE_LUT_THETA_S_MAX;
        p->altitude = splitmix64_uniform01(&state) * ATMOSPHERE_LUT_MAX_ALTITUDE;
        double r = solutions[0].model.bottom_radius, horizon = 0.5 * M_PI + acos(r / (r + p->altitude));
        p->theta_v = splitmix64_uniform01(&state) * horizon;
        p->t = solutions[i % count].t;
    }
}

static void set_floors(atmosphere_lut_reference *ref)
{
    for (int table = 0; table < ATMOSPHERE_TABLES; ++table) {
        double top = 0.0;
        for (int i = 0; i < ref->count; ++i)
            for (int k = 0; k < ATMOSPHERE_LUT_VALUES; ++k)
                top = fmax(top, fabs(ref->reference[(i * ATMOSPHERE_TABLES + table) * ATMOSPHERE_LUT_VALUES + k]));
        ref->floor[table] = FLOOR * top;
    }
}

int atmosphere_lut_reference_build(atmosphere_lut_reference *ref, const atmosphere_solution *solutions, int count,
                                   int points, unsigned seed, int threads)
{
    size_t values = (size_t)points * ATMOSPHERE_TABLES * ATMOSPHERE_LUT_VALUES;
    *ref = (atmosphere_lut_reference){.count = points};
    ref->points = malloc(sizeof *ref->points * (size_t)(points > 0 ? points : 1));
    ref->reference = malloc(sizeof *ref->reference * (values ? values : 1));
    ref->fast = malloc(sizeof *ref->fast * (values ? values : 1));
    if (!ref->points || !ref->reference || !ref->fast || count < 1) {
        atmosphere_lut_reference_free(ref);
        return -1;
    }
    draw_points(ref, solutions, count, seed);
    double worst = 0.0;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads) reduction(max : worst)
    for (int i = 0; i < points; ++i) {
        const atmosphere_solution *s = &solutions[i % count];
        size_t at = (size_t)i * ATMOSPHERE_TABLES * ATMOSPHERE_LUT_VALUES;
        worst = fmax(worst, evaluate(s, ATMOSPHERE_REFERENCE, &ref->points[i], (void *)(ref->reference + at)));
        evaluate(s, ATMOSPHERE_FAST, &ref->points[i], (void *)(ref->fast + at));
    }
    ref->quadrature_estimate = worst;
    set_floors(ref);
    return 0;
}

void atmosphere_lut_reference_free(atmosphere_lut_reference *ref)
{
    free(ref->points), free(ref->reference), free(ref->fast);
    ref->points = NULL, ref->reference = NULL, ref->fast = NULL;
}

/* The largest relative difference over a table's values at one point. */
static double point_error(const double *a, const double *b, int n, double floor)
{
    double worst = 0.0;
    for (int k = 0; k < n; ++k)
        worst = fmax(worst, fabs(a[k] - b[k]) / (fabs(b[k]) + floor));
    return worst;
}

/* max, rms, 95th percentile (nearest rank) of errors[0..n) and the
 * percentile's bootstrap standard error (2000 resamples, a fixed seed);
 * sorts them. */
static atmosphere_error_stats stats_of(double *errors, int n)
{
    atmosphere_error_stats s = {0.0, 0.0, 0.0, 0.0};
    double sum = 0.0, p = 0.95;
    for (int i = 0; i < n; ++i)
        sum += errors[i] * errors[i];
    if (n > 0) {
        s.p95 = quantile_nearest_rank(errors, n, p);
        s.p95_se = n > 1 ? bootstrap_standard_error(errors, n, bootstrap_quantile, &p, 2000, 95u) : 0.0;
        s.max = errors[n - 1], s.rms = sqrt(sum / n);
    }
    return s;
}

/* The lookup of `table` at p into v (ATMOSPHERE_LUT_VALUES, zero-padded). */
static void lookup(const atmosphere_luts *luts, int table, const atmosphere_lut_point *p, double *v)
{
    float f[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS] = {{0}};
    if (table == ATMOSPHERE_TABLE_INSCATTER)
        atmosphere_lut_inscatter(luts, (float)p->theta_s, (float)p->theta_v, (float)p->altitude, (float)p->t, f);
    else
        atmosphere_lut_light(luts, table, (float)p->theta_s, (float)p->altitude, (float)p->t, f[0]);
    for (int k = 0; k < ATMOSPHERE_LUT_VALUES; ++k)
        v[k] = f[k / 3][k % 3];
}

int atmosphere_lut_errors(const atmosphere_luts *luts, const atmosphere_lut_reference *ref,
                          atmosphere_table_error out[ATMOSPHERE_TABLES])
{
    int n = ref->count;
    double *e = malloc(sizeof *e * 5 * (size_t)(n > 0 ? n : 1));
    if (!e)
        return -1;
    for (int table = 0; table < ATMOSPHERE_TABLES; ++table) {
        int values = table == ATMOSPHERE_TABLE_INSCATTER ? 6 : 3;
        int day = 0, twilight = 0;
        for (int i = 0; i < n; ++i) {
            double got[ATMOSPHERE_LUT_VALUES];
            size_t at = ((size_t)i * ATMOSPHERE_TABLES + table) * ATMOSPHERE_LUT_VALUES;
            lookup(luts, table, &ref->points[i], got);
            e[i] = point_error(got, ref->fast + at, values, ref->floor[table]);
            e[n + i] = point_error(ref->fast + at, ref->reference + at, values, ref->floor[table]);
            e[2 * n + i] = point_error(got, ref->reference + at, values, ref->floor[table]);
            if (ref->points[i].theta_s <= ATMOSPHERE_DAY_THETA_S)
                e[3 * n + day++] = e[2 * n + i];
            else
                e[4 * n + twilight++] = e[2 * n + i];
        }
        out[table].day_total = stats_of(e + 3 * n, day);
        out[table].twilight_total = stats_of(e + 4 * n, twilight);
        out[table].day_points = day, out[table].twilight_points = twilight;
        out[table].interpolation = stats_of(e, n);
        out[table].quadrature = stats_of(e + n, n);
        out[table].total = stats_of(e + 2 * n, n);
    }
    free(e);
    return 0;
}

/* L_background by the table's definition at a pixel, FAST. */
static void sky_truth(const atmosphere_solution *s, const atmosphere_lut_point *p, double nu, double out[3])
{
    double r = s->model.bottom_radius + p->altitude, mu = cos(p->theta_v), mu_s = cos(p->theta_s);
    double S[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS], M[3];
    atmosphere_single_scattering(s, ATMOSPHERE_FAST, r, mu, mu_s, 0.0, S);
    atmosphere_multiple_scattering(s, ATMOSPHERE_FAST, r, mu, mu_s, 0.0, M);
    double pbar = atmosphere_azimuthal_phase(ATMOSPHERE_RAYLEIGH, s->model.mie_g, mu, mu_s);
    double pr = rayleigh_phase(nu), pm = cornette_shanks_phase(nu, s->model.mie_g);
    for (int c = 0; c < 3; ++c)
        out[c] = pr * (S[ATMOSPHERE_RAYLEIGH][c] + M[c] / pbar) + pm * S[ATMOSPHERE_MIE][c];
}

static void draw_pixels(atmosphere_sky_sample *x, const atmosphere_solution *solutions, int count, double low,
                        double high, unsigned seed)
{
    unsigned long long state = (unsigned long long)seed * 0x9e3779b97f4a7c15ull + 11u;
    double R = solutions[0].model.bottom_radius;
    for (int i = 0; i < x->count; ++i) {
        atmosphere_lut_point *p = &x->points[i];
        p->theta_s = low + splitmix64_uniform01(&state) * (high - low);
        p->altitude = splitmix64_uniform01(&state) * ATMOSPHERE_LUT_MAX_ALTITUDE;
        double mu_h = atmosphere_lut_horizon_cosine(p->altitude, R);
        double mu = mu_h + splitmix64_uniform01(&state) * (1.0 - mu_h), phi = 2.0 * M_PI * splitmix64_uniform01(&state);
        p->theta_v = acos(mu);
        p->t = solutions[i % count].t;
        x->nu[i] = mu * cos(p->theta_s) + sqrt(fmax(1.0 - mu * mu, 0.0)) * sin(p->theta_s) * cos(phi);
    }
}

int atmosphere_sky_sample_build(atmosphere_sky_sample *x, const atmosphere_solution *solutions, int count, int pixels,
                                double theta_s_low, double theta_s_high, unsigned seed, int threads)
{
    *x = (atmosphere_sky_sample){.count = pixels};
    size_t n = (size_t)(pixels > 0 ? pixels : 1);
    x->points = malloc(sizeof *x->points * n), x->nu = malloc(sizeof *x->nu * n);
    x->truth = malloc(sizeof *x->truth * 3 * n);
    if (!x->points || !x->nu || !x->truth || count < 1) {
        atmosphere_sky_sample_free(x);
        return -1;
    }
    draw_pixels(x, solutions, count, theta_s_low, theta_s_high, seed);
#pragma omp parallel for schedule(dynamic, 8) num_threads(threads)
    for (int i = 0; i < pixels; ++i)
        sky_truth(&solutions[i % count], &x->points[i], x->nu[i], x->truth + 3 * (size_t)i);
    return 0;
}

void atmosphere_sky_sample_free(atmosphere_sky_sample *x)
{
    free(x->points), free(x->nu), free(x->truth);
    x->points = NULL, x->nu = NULL, x->truth = NULL;
}

int atmosphere_sky_errors(const atmosphere_luts *luts, const atmosphere_sky_sample *x, atmosphere_error_stats *out)
{
    double *e = malloc(sizeof *e * (size_t)(x->count > 0 ? x->count : 1));
    if (!e)
        return -1;
    for (int i = 0; i < x->count; ++i) {
        const atmosphere_lut_point *p = &x->points[i];
        const double *truth = x->truth + 3 * (size_t)i;
        float got[3];
        atmosphere_lut_background(luts, (float)p->theta_s, (float)p->theta_v, (float)p->altitude, (float)p->t,
                                  (float)x->nu[i], got);
        double scale = fmax(truth[0], fmax(truth[1], truth[2])), worst = 0.0;
        for (int c = 0; c < 3; ++c)
            worst = fmax(worst, fabs(got[c] - truth[c]));
        e[i] = scale > 0.0 ? worst / scale : worst > 0.0;
    }
    *out = stats_of(e, x->count);
    free(e);
    return 0;
}
