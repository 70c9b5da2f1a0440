/* The sphere-light study's configurations and their Monte Carlo references
 * (sphere_light_study.h): the realistic distribution the refit draws from,
 * also drawn by the sun, terminator and units subsets. Apart from the
 * refit's file so the subsets it calls do not call back into it. */
#include "sphere_light/sphere_light_study.h"

#include <math.h>

#include "core/optics/ggx.h"
#include "core/sampling/sobol.h"
#include "sphere_light/sphere_light_reference.h"

#define SUN_SIN_SIGMA 0.00465 /* the sun seen from the earth */
#define MAX_SIN_SIGMA 0.5

static double uniform01(uint32_t seed, uint32_t i, uint32_t k)
{
    return hash_combine(hash_combine(seed, i), k) * 0x1p-32;
}

/* Configuration i of the realistic distribution: roughness uniform in
 * [0.05, 1], sin(sigma) log-uniform from the sun's to 0.5 (30 deg), n.v
 * uniform in [0.05, 1]; the light's centre 70% of the time within
 * 2 (alpha + sigma) of the mirror direction (where highlights are: a
 * uniform choice would fill the data with dark configurations), otherwise
 * cosine-distributed over the hemisphere; always 1 deg or more above the
 * horizon (Decima's term is 0 once the centre is below). */
sphere_light_config sphere_light_realistic_config(uint32_t seed, uint32_t i)
{
    double roughness = 0.05 + 0.95 * uniform01(seed, i, 0);
    double sin_sigma = SUN_SIN_SIGMA * pow(MAX_SIN_SIGMA / SUN_SIN_SIGMA, uniform01(seed, i, 1));
    double n_dot_v = 0.05 + 0.95 * uniform01(seed, i, 2);
    double u4 = uniform01(seed, i, 4), u5 = uniform01(seed, i, 5);
    if (uniform01(seed, i, 3) < 0.7) {
        double delta = 2.0 * (ggx_alpha(roughness) + asin(sin_sigma)) * sqrt(u4);
        return sphere_light_config_near_mirror(n_dot_v, delta, 2.0 * M_PI * u5, sin_sigma, roughness);
    }
    double theta = fmin(acos(sqrt(u4)), 0.5 * M_PI - M_PI / 180.0);
    return sphere_light_config_make(n_dot_v, theta, 2.0 * M_PI * u5, sin_sigma, roughness);
}

sphere_light_sample sphere_light_reference_sample(const sphere_light_config *c, uint32_t samples, uint32_t seed)
{
    sphere_light_estimate est;
    sphere_light_reference(c, samples, seed, &est);
    double e_perp = sphere_light_normal_illuminance(c->sin_sigma);
    sphere_light_sample s = {c->v, c->lc, (float)c->sin_sigma, (float)c->alpha, est.spec / e_perp,
                             est.spec_stderr / e_perp, 0.0f};
    return s;
}
