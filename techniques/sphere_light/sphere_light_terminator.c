/* Decima's sphere light near the terminator, as published and mended
 * (sphere_light/sphere_light_study.h, sphere_terminator_result; issue 26, item 8). */
#include <math.h>
#include <stdlib.h>

#include "core/optics/ggx.h"
#include "core/statistics/sample_mean.h"
#include "core/sampling/sobol.h"
#include "sphere_light/sphere_light_fit.h"
#include "sphere_light/sphere_light_reference.h"
#include "sphere_light/sphere_light_study.h"

#define TERMINATOR_SEED 0x7e2au
#define SUN_SIN_SIGMA 0.00465
#define MAX_SIN_SIGMA 0.5

static double unit(uint32_t i, uint32_t k) { return hash_combine(hash_combine(TERMINATOR_SEED, i), k) * 0x1p-32; }

/* Configuration i with the centre's elevation in [lo, hi] angular radii
 * (v's azimuth is 0: the mirror azimuth is pi). */
static sphere_light_sample draw(uint32_t i, double lo, double hi, uint32_t samples)
{
    double roughness = 0.05 + 0.95 * unit(i, 0);
    double sin_sigma = SUN_SIN_SIGMA * pow(MAX_SIN_SIGMA / SUN_SIN_SIGMA, unit(i, 1));
    double n_dot_v = 0.05 + 0.95 * unit(i, 2), sigma = asin(sin_sigma);
    double elevation = sigma * (lo + (hi - lo) * unit(i, 3));
    double azimuth = M_PI * (0.5 + unit(i, 4));
    sphere_light_config c = sphere_light_config_make(n_dot_v, 0.5 * M_PI - elevation, azimuth, sin_sigma, roughness);
    return sphere_light_reference_sample(&c, samples, hash_combine(TERMINATOR_SEED, i));
}

int sphere_terminator_study(int configurations, uint32_t samples, sphere_terminator_result *out)
{
    const decima_sphere_constants k = decima_sphere_published();
    int n = configurations;
    double *x = malloc(sizeof(double) * 5 * (size_t)n);
    if (!x)
        return -1;
    double *signed_talk = x, *abs_talk = x + n, *abs_fixed = x + 2 * n, *gain = x + 3 * n, *above = x + 4 * n;
    int below = 0;
#pragma omp parallel for schedule(dynamic, 16) reduction(+ : below)
    for (int i = 0; i < n; ++i) {
        sphere_light_sample band = draw((uint32_t)i, -1.0, 1.0, samples);
        sphere_light_sample high = draw((uint32_t)(i + n), 1.0, 3.0, samples);
        signed_talk[i] = sphere_light_residual(SPHERE_MODEL_DECIMA, &k, &band);
        abs_talk[i] = fabs(signed_talk[i]);
        abs_fixed[i] = fabs(sphere_light_residual(SPHERE_MODEL_DECIMA_HORIZON, &k, &band));
        gain[i] = abs_talk[i] - abs_fixed[i];
        above[i] = fabs(sphere_light_residual(SPHERE_MODEL_DECIMA, &k, &high));
        below += band.lc.z <= 0.0f;
    }
    out->configurations = n, out->samples = samples;
    out->share_centre_below = (double)below / n;
    sample_mean_se(signed_talk, n, &out->talk_signed, &out->talk_signed_se);
    sample_mean_se(abs_talk, n, &out->talk_abs, &out->talk_abs_se);
    sample_mean_se(abs_fixed, n, &out->fixed_abs, &out->fixed_abs_se);
    sample_mean_se(gain, n, &out->gain, &out->gain_se);
    sample_mean_se(above, n, &out->above_abs, &out->above_abs_se);
    free(x);
    return 0;
}
