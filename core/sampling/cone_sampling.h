/* Uniform sampling of the directions inside a cone (a spherical cap): the
 * solid angle a sphere of radius R subtends from a point at distance d > R
 * from its centre, with sin(sigma) = R / d (pbrt-v4, "Sampling Spheres",
 * section 6.2.4, in its stable form). 1 - cos(sigma) is computed as
 * sin^2(sigma) / (1 + cos(sigma)), which keeps full relative precision for
 * a sun-sized cap (sigma = 0.0047 rad), where 1 - cos(sigma) ~ 1e-5. */
#ifndef GTLAB_CORE_SAMPLING_CONE_SAMPLING_H
#define GTLAB_CORE_SAMPLING_CONE_SAMPLING_H

#include "core/vec3.h"

/* 1 - cos(sigma) for sin(sigma) in (0, 1]. */
double cone_one_minus_cos(double sin_sigma);

/* The solid angle of the cap: 2 pi (1 - cos(sigma)). */
double cone_solid_angle(double sin_sigma);

/* A direction uniformly distributed in the cap of unit axis `axis` and
 * angular radius sigma, from u in [0, 1)^2; its density is
 * 1 / cone_solid_angle(sin_sigma). */
vec3 cone_sample_uniform(vec3 axis, double sin_sigma, const float u[2]);

/* 1 when the unit direction d lies in the cap, tested in double as
 * |d - axis|^2 <= 2 (1 - cos(sigma)) with both normalised in double, which
 * is well conditioned for small caps (a dot product against cos(sigma) ~ 1
 * is not). */
int cone_contains(vec3 axis, double sin_sigma, vec3 d);

#endif
