/* Direction sampling on the hemisphere around +z (local frame; see frame.h).
 * Each returns a unit vector with z > 0 — never on the horizon, where a ray
 * would graze the surface it leaves — and documents its density with respect
 * to solid angle. */
#ifndef GTLAB_CORE_SAMPLING_HEMISPHERE_SAMPLING_H
#define GTLAB_CORE_SAMPLING_HEMISPHERE_SAMPLING_H

#include "core/vec3.h"


/* Cosine-weighted: pdf = cos(theta) / pi. Malley's method through Shirley and
 * Chiu's concentric disc mapping, which keeps the Sobol' stratification. The
 * disc's angle uses a polynomial sine and cosine accurate to ~1e-7, far below
 * any Monte Carlo error. */
vec3 sample_cosine_hemisphere(const float u[2]);

/* Uniform: pdf = 1 / (2 pi). The equal-area map of the same concentric disc
 * point: z = 1 - r^2, horizontal radius r sqrt(2 - r^2). */
vec3 sample_uniform_hemisphere(const float u[2]);

/* Both directions for `count` points (u0[k], u1[k]), several at a time: the
 * same values as the two functions above. */
void sample_hemisphere_batch(const float *restrict u0, const float *restrict u1, int count, vec3 *restrict cosine,
                             vec3 *restrict uniform);

/* Cosine-weighted directions only, for `count` points: the same values as
 * sample_cosine_hemisphere. */
void sample_cosine_hemisphere_batch(const float *restrict u0, const float *restrict u1, int count,
                                    vec3 *restrict cosine);

/* Shirley-Chiu concentric map of [0,1)^2 onto the unit disc. */
void sample_concentric_disc(const float u[2], float *x, float *y);

#endif
