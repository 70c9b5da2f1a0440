/* The exact light a uniform spherical emitter reflects off a GGX or Lambert
 * surface, in parameter space: no scene and no rays, one configuration at a
 * time (unshadowed, as the real-time approximations are). It lives with
 * the references (raytracer/) because it is one: the integrand of
 * `gtlab render sphere-light` at a pixel without occluders, and the data
 * `gtlab fit sphere-light` fits.
 *
 *   L_spec = integral over the cap of f_r(v, l) max(0, n.l) dl   (GGX, no Fresnel)
 *   L_diff = integral over the cap of (1/pi)   max(0, n.l) dl   (Lambert, albedo 1)
 *
 * for emitted radiance 1; directions below the surface contribute 0
 * (horizon clipping). Monte Carlo with two techniques, each sample drawing
 * one of each, combined by multiple importance sampling (Veach 1997,
 * power heuristic, beta = 2): l uniform in the cap (density 1 / solid angle), and
 * l = reflect(v, m) with m from GGX's visible normals (Heitz 2018) for the
 * specular part, resp. a cosine-distributed l for the diffuse part. Points
 * are Owen-scrambled Sobol' (one dimension pair per technique); the
 * standard error is that of the mean of the per-sample MIS sums. */
#ifndef GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_REFERENCE_H
#define GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_REFERENCE_H

#include <stdint.h>

#include "core/optics/sphere_light_units.h"
#include "core/vec3.h"

/* One configuration, in the local frame of the surface (n = +z). */
typedef struct {
    vec3 v;           /* unit view direction, v.z > 0 */
    vec3 lc;          /* unit direction to the light's centre */
    double sin_sigma; /* sin of the angular radius: R / d, in (0, 1) */
    double alpha;     /* GGX alpha = roughness^2 */
} sphere_light_config;

/* v = (sin theta_v, 0, cos theta_v); the light at polar angle theta_l from
 * n and azimuth phi_l from v's half-plane; all angles in radians. */
sphere_light_config sphere_light_config_make(double n_dot_v, double theta_l, double phi_l, double sin_sigma,
                                             double roughness);

/* v as above; the light's centre at angle delta from the mirror direction
 * R of v, turned by psi about R (psi = 0 towards n), but never lower than
 * 1 degree above the horizon (the approximations give 0 below). */
sphere_light_config sphere_light_config_near_mirror(double n_dot_v, double delta, double psi, double sin_sigma,
                                                    double roughness);

typedef struct {
    double spec, spec_stderr; /* L_spec and its standard error */
    double diff, diff_stderr; /* L_diff and its standard error */
} sphere_light_estimate;

/* One MIS sample from two points of [0, 1)^2 (cap technique, BRDF
 * technique): each contribution with the direction that carries it, so a
 * caller can weight each by a Fresnel term or by a shadow ray: the cap
 * direction's specular and diffuse terms, the GGX direction's specular term
 * and the cosine direction's diffuse term (0 when they miss the light). */
typedef struct {
    vec3 l_cap, l_brdf, l_diff;
    double spec_cap, spec_brdf, diff_cap, diff_brdf;
} sphere_light_mis_terms;

void sphere_light_mis_sample(const sphere_light_config *c, const float u_cap[2], const float u_brdf[2],
                             sphere_light_mis_terms *t);

/* Estimates both integrals with `samples` MIS samples (>= 2) from seed. */
void sphere_light_reference(const sphere_light_config *c, uint32_t samples, uint32_t seed,
                            sphere_light_estimate *out);

/* sphere_light_normal_illuminance: pi sin^2(sigma), the illuminance of the
 * sphere at normal incidence per unit radiance, which the approximations are
 * normalised to (core/optics/sphere_light_units.h). */

/* ---- The maximum of (N.H)^2 over the light, by brute force ----
 * The reference for GetNoHSquared (sphere_light/sphere_light.h): plain double
 * vector maths, sharing nothing with the real-time code. n = +z, R the
 * mirror direction of v, T = normalize(R - (R.lc) lc), B = +-(T x lc) with
 * N.B >= 0, and the rim point L(phi) = cos(sigma) lc + sin(sigma) (cos(phi) T + sin(phi) B). */
typedef struct {
    double v[3], lc[3]; /* unit vectors */
    double radius_tan;  /* tan(sigma) */
} sphere_noh_config;

sphere_noh_config sphere_noh_config_make(double n_dot_v, double theta_l, double phi_l, double radius_tan);

/* The talk's scalar inputs: n.lc, n.v, v.lc. */
void sphere_noh_config_dots(const sphere_noh_config *c, float *n_dot_l, float *n_dot_v, float *v_dot_l);

/* 1 when R lies in the light's cone (R.lc >= cos(sigma)). */
int sphere_noh_r_inside(const sphere_noh_config *c);

/* (N.H)^2 with H = normalize(L(phi) + V). */
double sphere_rim_noh_squared_at(const sphere_noh_config *c, double phi);

/* The maximum of (N.H)^2 over the rim (over_disc = 0) or over the whole
 * disc, rim and interior rings (over_disc = 1): `steps` equally spaced
 * angles (and as many radii), the best refined by golden-section search on
 * its neighbouring interval. *phi_out (may be NULL) receives the rim
 * angle of the maximum. */
double sphere_noh_squared_max(const sphere_noh_config *c, int steps, int over_disc, double *phi_out);

#endif
