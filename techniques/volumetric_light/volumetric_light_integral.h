/* The single-scattering integral of a shadowed spot or point light along one
 * camera ray (core/optics/volumetric_light.h for the lights, the medium and the
 * integrand j), two ways:
 *
 * 1. Adaptive quadrature (core/sampling/quadrature.h, gk15) in the equiangular angle
 *    (Kulla & Fajardo 2012, "Importance Sampling Techniques for Path Tracing
 *    in Participating Media", EGSR): with s0 = dot(p - o, w) the closest
 *    approach to the light and h = |p - o - s0 w| its distance,
 *        s = s0 + h tan(theta),  ds = (r^2 / h) dtheta,
 *        L = \int j(s) ds = \int j(s(theta)) r^2 / h dtheta,
 *    whose integrand is bounded (the 1/r^2 peak is absorbed) and smooth but
 *    for the cone and the shadows. The cone is exact: the integration runs
 *    over [0, d] intersected with the outer cone, split where the ray crosses
 *    the inner cone (volumetric_cone_interval, analytic), so every piece is
 *    smooth (the smoothstep is C^1 only at the two cones). The range is cut
 *    into at least 16 pieces of equal angle so that an occluder must hide
 *    between nodes of 16 x 15 to be missed. Shadow boundaries are NOT found
 *    separately: they are left to the adaptive bisection and accepted as the
 *    quadrature's error. The estimate, the sum of |K15 - G7| over accepted
 *    intervals, covers them: an interval holding a jump of height J and
 *    width dtheta has |K15 - G7| ~ J dtheta, and bisection goes on until that
 *    is within the tolerance (or depth 30: dtheta below 2^-30 of the range).
 *    The Monte Carlo cross-check below is what tests the claim.
 *
 * 2. Monte Carlo with equiangular sampling over the whole [0, d] (no use of
 *    the cone intervals): theta uniform in [theta(0), theta(d)], so each
 *    sample is (theta_d - theta_0) j r^2 / h with one shadow ray. Unbiased;
 *    the render loop gives it per-pixel standard errors.
 *
 * Visibility V(x): a shadow ray from x towards the light through Embree,
 * NULL occluders: 1. */
#ifndef GTLAB_VOLUMETRIC_LIGHT_VOLUMETRIC_LIGHT_INTEGRAL_H
#define GTLAB_VOLUMETRIC_LIGHT_VOLUMETRIC_LIGHT_INTEGRAL_H

#include "core/optics/volumetric_light.h"
#include "raytracer/embree_scene.h"

typedef struct {
    const volumetric_light *light;   /* validated */
    const volumetric_medium *medium; /* validated */
    const embree_scene *occluders;   /* NULL: unshadowed */
} volumetric_lighting;

typedef struct {
    double radiance[3]; /* L per channel: the light's intensity times the scalar integral */
    double error[3];    /* the quadrature's error estimate of radiance */
    long rays;          /* shadow rays traced */
} volumetric_ray_estimate;

/* L along o + s w (w unit), s in [0, distance], by quadrature to about
 * rel_tol of the integral's bound sigma_s max(p_HG) (theta range) / h. */
void volumetric_light_quadrature(const volumetric_lighting *l, vec3 o, vec3 w, double distance, double rel_tol,
                                 volumetric_ray_estimate *out);

/* One equiangular Monte Carlo sample of the scalar integral (multiply by the
 * intensity) per u[k], k < count (count <= 64), tracing the shadow rays as
 * one stream; returns the rays traced. */
int volumetric_light_mc_samples(const volumetric_lighting *l, vec3 o, vec3 w, double distance, const float *u,
                                int count, double *samples);

/* 1 if x sees the light (no occluder on the segment), tracing one ray. */
int volumetric_light_visible(const embree_scene *occluders, const volumetric_light *light, vec3 x);

#endif
