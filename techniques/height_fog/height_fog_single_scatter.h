/* Single scattering in the height fog along one ray, by adaptive quadrature
 * (core/sampling/quadrature.h, gk15) with an error estimate: the reference the
 * analytic model (height_fog/height_fog.h) is tested against and `gtlab
 * render fog --fog-scattering single` writes (docs/render-quantities.md).
 *
 * Along the ray x(s) = o + s w, s in [0, d], the transmittance is
 * T_c = exp(-beta_t,c D(d)) (D the integral of rho, core/optics/height_fog_medium.h)
 * and the light scattered once towards o is
 *
 *   L_c = \int_0^d rho(s) e^{-beta_t,c D(s)} J_c(s) ds
 *       = \int_0^{D(d)} e^{-beta_t,c u} J_c(s(u)) du,
 *   J_c(s) = E_sun,c S_sun,c(mu) T_sun,c(y(s)) V_sun(x(s)) + beta_s,c L_amb,c,
 *
 * where mu = dot(sun_direction, w). The change of variable u = D(s)
 * (ds = du / rho, inverted in closed form by height_fog_distance_at) makes
 * the integrand bounded and smooth apart from shadow edges, whatever H and
 * beta are; [0, D(d)] is split where beta_t,c u = 0, 1/2, 1, 2, 4, ... and cut
 * at beta_t,c u = 50 (the rest is below e^-50 of the unattenuated total).
 *
 * Options that separate the analytic model's assumptions:
 *   sun_extinction  T_sun = the fog's transmittance towards the sun
 *                   (height_fog_sun_transmittance), else 1;
 *   occluders       V_sun traced with Embree (a shadow ray towards the
 *                   sun from every quadrature node), NULL: V_sun = 1;
 *   sky_extinction  the ambient term is the sky of the upper hemisphere
 *                   seen through the fog above the point (an infinite flat
 *                   layer: nothing arrives from below, where the optical
 *                   depth is infinite), with an isotropic phase:
 *                     beta_s,c L_amb,c (1/4pi) \int_{w.y > 0} e^{-a_c / w.y} dw
 *                       = beta_s,c L_amb,c E_2(a_c) / 2,   a_c = beta_t,c H rho(y)
 *                   (E_2 the exponential integral, here by quadrature of
 *                   \int_0^1 e^{-a / mu} dmu); else the model's: an isotropic
 *                   sky of radiance L_amb reaching every point from the
 *                   whole sphere, unattenuated and unshadowed.
 * The multiple-scattering reference (techniques/height_fog/height_fog_path_tracer.h) drops
 * every one of these assumptions. */
#ifndef GTLAB_HEIGHT_FOG_SINGLE_SCATTER_H
#define GTLAB_HEIGHT_FOG_SINGLE_SCATTER_H

#include "core/optics/height_fog_medium.h"
#include "raytracer/embree_scene.h"

typedef struct {
    const height_fog_param *medium; /* validated */
    int sun_extinction;             /* 1: the fog attenuates the sun before it scatters */
    const embree_scene *occluders;  /* the scene shadows the fog; NULL: nothing does */
    int sky_extinction;             /* 1: the ambient is the upper hemisphere's sky seen through the fog */
} height_fog_lighting;

/* E_2(a) = \int_0^1 e^{-a / mu} dmu (a >= 0; E_2(0) = 1), by quadrature to about 1e-12. */
double height_fog_exponential_integral_e2(double a);

typedef struct {
    double transmittance[3];
    double inscatter[3];
    double error[3]; /* the quadrature's error estimate of inscatter */
    long rays;       /* shadow rays traced */
} height_fog_ray_estimate;

/* The integral of rho from o along the unit direction w over [0, distance];
 * distance may be +infinity (the whole column upwards, or infinity). */
double height_fog_ray_density(const height_fog_param *p, double y0, double dir_y, double distance);

/* T and the single-scattered L above, L within about rel_tol of its
 * unattenuated bound (J_max / beta_t). */
void height_fog_single_scatter(const height_fog_lighting *l, vec3 origin, vec3 dir, double distance, double rel_tol,
                        height_fog_ray_estimate *out);

#endif
