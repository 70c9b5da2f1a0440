/* The sun regime of Decima's sphere light (sphere_light/sphere_light_study.h,
 * sphere_sun_result; issue 26, item 9). */
#include <math.h>
#include <stdlib.h>

#include "core/statistics/sample_mean.h"
#include "core/sampling/sobol.h"
#include "sphere_light/sphere_light_fit.h"
#include "sphere_light/sphere_light_study.h"

#define SUN_SEED 0x50a1u
#define SUN_SIN_SIGMA 0.00465

static double unit(uint32_t i, uint32_t k) { return hash_combine(hash_combine(SUN_SEED, i), k) * 0x1p-32; }

/* The shortfall of (N.H)^2 below the rim's maximum with `steps` Newton steps. */
static double shortfall(const sphere_light_config *c, double radius_tan, double max, int steps)
{
    sphere_noh_config nc = sphere_noh_config_make(c->v.z, acos(c->lc.z), atan2(c->lc.y, c->lc.x), radius_tan);
    float n_dot_l, n_dot_v, v_dot_l;
    sphere_noh_config_dots(&nc, &n_dot_l, &n_dot_v, &v_dot_l);
    return max - sphere_noh_squared((float)radius_tan, n_dot_l, n_dot_v, v_dot_l, steps);
}

static double residual(const sphere_light_sample *s, int steps)
{
    const decima_sphere_constants k = decima_sphere_published();
    double value = decima_sphere_ggx_local(s->v, s->lc, s->sin_sigma, s->alpha, &k, steps);
    return log((value + SPHERE_FIT_FLOOR) / (s->reference + SPHERE_FIT_FLOOR));
}

int sphere_sun_study(int configurations, uint32_t samples, sphere_sun_result *out)
{
    int n = configurations;
    double *x = malloc(sizeof(double) * 6 * (size_t)n);
    if (!x)
        return -1;
    double *karis = x, *step = x + n, *noh_gain = x + 2 * n, *abs0 = x + 3 * n, *abs1 = x + 4 * n, *gain = x + 5 * n;
    double radius_tan = SUN_SIN_SIGMA / sqrt(1.0 - SUN_SIN_SIGMA * SUN_SIN_SIGMA), sigma = asin(SUN_SIN_SIGMA);
#pragma omp parallel for schedule(dynamic, 16)
    for (int i = 0; i < n; ++i) {
        double n_dot_v = 0.02 + 0.28 * unit((uint32_t)i, 0), roughness = 0.05 + 0.25 * unit((uint32_t)i, 1);
        double delta = sigma * (1.0 + 3.0 * unit((uint32_t)i, 2)), psi = 2.0 * M_PI * unit((uint32_t)i, 3);
        sphere_light_config c = sphere_light_config_near_mirror(n_dot_v, delta, psi, SUN_SIN_SIGMA, roughness);
        sphere_noh_config nc = sphere_noh_config_make(c.v.z, acos(c.lc.z), atan2(c.lc.y, c.lc.x), radius_tan);
        double max = sphere_noh_squared_max(&nc, 256, 0, NULL);
        karis[i] = shortfall(&c, radius_tan, max, 0), step[i] = shortfall(&c, radius_tan, max, 1);
        noh_gain[i] = karis[i] - step[i];
        sphere_light_sample s = sphere_light_reference_sample(&c, samples, hash_combine(SUN_SEED, (uint32_t)i));
        abs0[i] = fabs(residual(&s, 0)), abs1[i] = fabs(residual(&s, 1));
        gain[i] = abs0[i] - abs1[i];
    }
    out->configurations = n, out->samples = samples;
    sample_mean_se(karis, n, &out->shortfall_karis, &out->shortfall_karis_se);
    sample_mean_se(step, n, &out->shortfall_step, &out->shortfall_step_se);
    sample_mean_se(noh_gain, n, &out->shortfall_gain, &out->shortfall_gain_se);
    sample_mean_se(abs0, n, &out->abs_karis, &out->abs_karis_se);
    sample_mean_se(abs1, n, &out->abs_step, &out->abs_step_se);
    sample_mean_se(gain, n, &out->gain, &out->gain_se);
    free(x);
    return 0;
}
