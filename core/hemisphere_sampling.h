/* Direction sampling on the hemisphere around +z (local frame; see frame.h).
 * Each returns a unit vector with z > 0 — never on the horizon, where a ray
 * would graze the surface it leaves — and documents its density with respect
 * to solid angle. */
#ifndef GTLAB_CORE_HEMISPHERE_SAMPLING_H
#define GTLAB_CORE_HEMISPHERE_SAMPLING_H

#include "core/vec3.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* Cosine-weighted: pdf = cos(theta) / pi. Malley's method through Shirley and
 * Chiu's concentric disc mapping, which keeps the Sobol' stratification. */
vec3 sample_cosine_hemisphere(const float u[2]);

/* Uniform: pdf = 1 / (2 pi). cos(theta) = 1 - u0, phi = 2 pi u1. */
vec3 sample_uniform_hemisphere(const float u[2]);

/* Shirley-Chiu concentric map of [0,1)^2 onto the unit disc. */
void sample_concentric_disc(const float u[2], float *x, float *y);

#endif
