/* The units of the appendix's normalisation (sphere_light/sphere_light_study.h,
 * sphere_units_result; issue 26, item 7). */
#include <math.h>
#include <stdlib.h>

#include "core/sampling/sobol.h"
#include "sphere_light/sphere_light_fit.h"
#include "sphere_light/sphere_light_study.h"

#define UNITS_SEED 0x5a17u

static const char *const names[SPHERE_READINGS] = {"sin", "tan", "length"};
static const char *const meanings[SPHERE_READINGS] = {
    "sin(sigma) = R/d (gtlab's, Karis's sourceRadius/distance)", "tan(sigma)",
    "the radius as a length, R = d sin(sigma), d from 0.25 to 4 units"};

/* The normalisation's r under a reading for configuration i. */
static float reading_radius(int reading, double sin_sigma, uint32_t i)
{
    if (reading == SPHERE_READING_TAN)
        return (float)(sin_sigma / sqrt(1.0 - sin_sigma * sin_sigma));
    if (reading == SPHERE_READING_LENGTH)
        return (float)(sin_sigma * 0.25 * pow(16.0, hash_combine(hash_combine(UNITS_SEED, i), 7u) * 0x1p-32));
    return (float)sin_sigma;
}

/* count configurations from index first with their references (norm_radius left 0). */
static sphere_light_sample *make(uint32_t first, int count, uint32_t samples, int threads)
{
    sphere_light_sample *s = malloc(sizeof *s * (size_t)count);
    if (!s)
        return NULL;
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
    for (int i = 0; i < count; ++i) {
        sphere_light_config c = sphere_light_realistic_config(UNITS_SEED, first + (uint32_t)i);
        s[i] = sphere_light_reference_sample(&c, samples, hash_combine(UNITS_SEED ^ 0x9e3779b9u, first + (uint32_t)i));
    }
    return s;
}

static void set_reading(sphere_light_sample *s, int count, uint32_t first, int reading)
{
    for (int i = 0; i < count; ++i)
        s[i].norm_radius = reading_radius(reading, s[i].sin_sigma, first + (uint32_t)i);
}

/* One reading: scored with the published constants, refitted, scored again. */
static int run_reading(sphere_light_sample *train, sphere_light_sample *test, const sphere_units_result *u, int reading,
                       int threads, sphere_reading_row *row, gt_error *e)
{
    const decima_sphere_constants published = decima_sphere_published();
    set_reading(train, u->train, 0, reading);
    set_reading(test, u->test, (uint32_t)u->train, reading);
    row->name = names[reading], row->meaning = meanings[reading];
    sphere_light_measure(SPHERE_MODEL_DECIMA, &published, test, (size_t)u->test, &row->published);
    sphere_light_fit_result fit;
    if (sphere_light_fit(train, (size_t)u->train, &published, threads, &fit, e) != 0)
        return -1;
    for (int j = 0; j < SPHERE_FIT_PARAMS; ++j)
        row->value[j] = fit.value[j], row->stderr_[j] = fit.stderr_[j];
    sphere_light_measure(SPHERE_MODEL_DECIMA, &fit.constants, test, (size_t)u->test, &row->refit);
    return 0;
}

/* gtlab's reading without any normalisation, and its paired gain. */
static void score_normalisation(const sphere_light_sample *test, int count, sphere_units_result *u)
{
    const decima_sphere_constants published = decima_sphere_published();
    decima_sphere_constants none = published;
    none.norm_scale = 0.0f;
    sphere_light_measure(SPHERE_MODEL_DECIMA, &none, test, (size_t)count, &u->none);
    double sum = 0.0, sq = 0.0;
    for (int i = 0; i < count; ++i) {
        double d = fabs(sphere_light_residual(SPHERE_MODEL_DECIMA, &none, &test[i])) -
                   fabs(sphere_light_residual(SPHERE_MODEL_DECIMA, &published, &test[i]));
        sum += d, sq += d * d;
    }
    u->gain = sum / count;
    u->gain_se = sqrt(fmax(0.0, sq / count - u->gain * u->gain) / (count - 1));
}

int sphere_units_study(int train, int test, uint32_t samples, int threads, sphere_units_result *out, gt_error *e)
{
    out->train = train, out->test = test, out->samples = samples;
    sphere_light_sample *a = make(0, train, samples, threads), *b = make((uint32_t)train, test, samples, threads);
    int rc = a && b ? 0 : gt_error_set(e, "sphere light", "out of memory");
    if (rc == 0) {
        set_reading(b, test, (uint32_t)train, SPHERE_READING_SIN);
        score_normalisation(b, test, out);
    }
    for (int r = 0; r < SPHERE_READINGS && rc == 0; ++r)
        rc = run_reading(a, b, out, r, threads, &out->rows[r], e);
    free(a), free(b);
    return rc;
}
