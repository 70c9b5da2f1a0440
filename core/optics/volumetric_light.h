/* The lights and the medium of INSIDE's volumetric lighting (Gjoel & Svendsen,
 * GDC 2016, seed 002, "Volumetric Lighting"; issue 29), written once: the
 * single-scattering reference (techniques/volumetric_light/volumetric_light_integral.h) and
 * the real-time ray-march (techniques/volumetric_light/) both evaluate
 * the integrand below, so they differ only in how they integrate it and in
 * how they find the shadows.
 *
 * The medium is homogeneous: scattering sigma_s, extinction sigma_t >= sigma_s
 * [1/m], Henyey-Greenstein phase of mean cosine g (core/optics/phase_function.h).
 *
 * A light is a point of radiant intensity I [W/sr] per colour channel:
 *   point  I(x) = I / r^2                                   (inverse square)
 *   spot   I(x) = I smoothstep(cos_outer, cos_inner, cos theta) / r^2,
 *          theta the angle between the axis and x - p. The falloff is
 *          pbrt-v4's SpotLight::I (Pharr, Jakob, Humphreys 2023, §12.1.2):
 *          smoothstep(a, b, x) = t^2 (3 - 2 t), t = clamp((x - a) / (b - a)),
 *          so 1 inside the inner cone, 0 outside the outer, C^1 between. The
 *          talk names "falloff" and "cookie" without a formula; a cookie is
 *          left out (it would be one more factor).
 *
 * Single scattering towards a camera at o along the unit direction w, at
 * distance s (x = o + s w, r = |p - x|):
 *
 *   L = \int_0^d j(s) ds,
 *   j(s) = sigma_s p_HG(mu, g) I(x) V(x) exp(-sigma_t (s + r)),
 *   mu = dot((p - x) / r, w)   (mu = 1 looks into the light: forward scattering),
 *
 * V the visibility of the light from x (shadow rays or a shadow map), d the
 * distance to the first surface. exp(-sigma_t s) attenuates towards the
 * camera, exp(-sigma_t r) from the light. */
#ifndef GTLAB_CORE_OPTICS_VOLUMETRIC_LIGHT_H
#define GTLAB_CORE_OPTICS_VOLUMETRIC_LIGHT_H

#include "core/error.h"
#include "core/vec3.h"

typedef struct {
    double sigma_s, sigma_t; /* [1/m], 0 <= sigma_s <= sigma_t */
    double g;                /* HG mean cosine, |g| < 1 */
} volumetric_medium;

typedef enum { VOLUMETRIC_POINT_LIGHT = 0, VOLUMETRIC_SPOT_LIGHT } volumetric_light_kind;

typedef struct {
    volumetric_light_kind kind;
    vec3 position;
    vec3 axis;                    /* spot: unit direction of the cone's axis */
    double cos_outer, cos_inner;  /* spot: cosines of the half-angles, cos_outer < cos_inner */
    double intensity[3];          /* I [W/sr] per channel */
} volumetric_light;

/* A spot light of half-angles outer_deg > inner_deg (degrees, < 90) aimed
 * from position at target. */
volumetric_light volumetric_spot_light(vec3 position, vec3 target, double outer_deg, double inner_deg,
                                       const double intensity[3]);
volumetric_light volumetric_point_light(vec3 position, const double intensity[3]);

/* -1 with e naming `what` if a value is out of range. */
int volumetric_medium_validate(const volumetric_medium *m, const char *what, gt_error *e);
int volumetric_light_validate(const volumetric_light *l, const char *what, gt_error *e);

/* The angular falloff of the light towards x (1 for a point light). */
double volumetric_light_falloff(const volumetric_light *l, vec3 x);

/* j(s) / (I V) above: the single-scattering integrand per unit intensity
 * and visibility at distance s along o + s w (0 at the light itself). */
double volumetric_inscatter_density(const volumetric_light *l, const volumetric_medium *m, vec3 o, vec3 w,
                                    double s);

/* The part of [t_min, t_max] along o + t w inside the cone of cosine
 * cos_half about the spot's axis (a convex set: one interval); returns 0
 * and [*t0, *t1] (t0 < t1), or -1 if the ray misses the cone there. A point
 * light returns [t_min, t_max]. */
int volumetric_cone_interval(const volumetric_light *l, double cos_half, vec3 o, vec3 w, double t_min,
                             double t_max, double *t0, double *t1);

#endif
