/* Real-time sphere lights: what a shader evaluates per pixel, in C.
 *
 * Directions live in the surface's local frame, n = +z, all pointing away
 * from the surface; the light is given by the unit direction to its centre
 * lc and the sine of its angular radius, sin(sigma) = R / d.
 * Every specular function returns the reflected radiance per unit normal
 * illuminance E_perp = pi sin^2(sigma) L_e (the illuminance of the sphere
 * at normal incidence), i.e. what a point light of that illuminance gives:
 * as sigma -> 0 they all tend to f_r(v, lc) (n.lc). The illuminance
 * functions return E / L_e (unit radiance). */
#ifndef GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_H
#define GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_H

#include <stddef.h>

#include "core/vec3.h"
#include "realtime/sphere_illuminance.h"

/* ---- De Carpentier's maximisation of N.H on the rim (Decima, 2017) ---- */

/* A point of the rim L(phi) = cos(sigma) lc + sin(sigma) (cos(phi) T + sin(phi) B),
 * T the unit vector towards R orthogonal to lc, B completing the frame with
 * N.B >= 0, held as the dot products GetNoHSquared works with. */
typedef struct {
    float no_t, vo_t; /* N.(sin(sigma) T), V.(sin(sigma) T) */
    float no_b, vo_b; /* N.(sin(sigma) B), V.(sin(sigma) B) */
    float no_c;       /* cos(sigma) N.lc + N.V: the fixed part of N.(L + V) */
    float vo_c;       /* cos(sigma) V.lc + 1:   the fixed part of 1 + V.L */
} sphere_rim;

/* A Newton step x1 = num / den on the rim (sphere_rim_newton_step). */
typedef struct {
    float num, den;
} sphere_rim_step;

/* Sets up the rim at phi = 0 (Karis's point: the rim point nearest R) from
 * the talk's inputs, radius_tan = tan(sigma). Returns 1 when R lies inside
 * the light's cone (then the maximum of (N.H)^2 is 1 and rim is not set), 0
 * otherwise. */
int sphere_rim_setup(float radius_tan, float n_dot_l, float n_dot_v, float v_dot_l, sphere_rim *rim);

/* One Newton step on f(x) = (N.H)^2 of the rim point at phi = 2 atan(x),
 * from x = 0: returns x1 = -f'(0) / f''(0), as the ratio num / den (den may
 * be 0: x1 infinite, phi = pi). */
void sphere_rim_newton_step(const sphere_rim *rim, float *num, float *den);

/* Moves the rim's reference point by phi = 2 atan(num / den), so the next
 * step starts from x = 0 again. */
void sphere_rim_rotate(sphere_rim *rim, float num, float den);

/* GetNoHSquared: (N.H)^2 after newton_steps (0 = Karis's point, 1 = the
 * talk, 2 = one more step from the first), 1 if R is inside the light. */
float sphere_noh_squared(float radius_tan, float n_dot_l, float n_dot_v, float v_dot_l, int newton_steps);

/* The two forms a shader would hard-code (0 and 1 step), as separate
 * functions so their cost can be measured (`gtlab bench sphere-light`). */
float sphere_noh_squared_karis(float radius_tan, float n_dot_l, float n_dot_v, float v_dot_l);
float sphere_noh_squared_decima(float radius_tan, float n_dot_l, float n_dot_v, float v_dot_l);

/* Not in the talk: the step taken only where it heads for a maximum,
 * f''(0) < 0 (xDenom < 0: it has the sign of f''(0)). Where f''(0) >= 0
 * (grazing views) Newton's step heads for a minimum of (N.H)^2 and
 * Karis's point is kept instead. */
float sphere_noh_squared_guarded(float radius_tan, float n_dot_l, float n_dot_v, float v_dot_l);

/* ---- Karis 2013: representative point and normalisation ---- */

/* The direction to the point of the sphere closest to the reflection ray r:
 * lc + c * saturate(sin(sigma) / |c|) with c = (lc.r) r - lc, normalised. */
vec3 karis_sphere_point(vec3 r, vec3 lc, float sin_sigma);

/* (alpha / alpha')^2 with alpha' = saturate(alpha + sin(sigma) / 2)
 * (sourceRadius / (2 distance)). */
float karis_sphere_normalization(float alpha, float sin_sigma);

/* Karis's sphere-light GGX (no Fresnel): normalisation * f_r(v, l) * saturate(n.l)
 * with l the representative point. */
float karis_sphere_ggx(vec3 v, vec3 lc, float sin_sigma, float alpha);

/* ---- Decima's EvaluateSphericalAreaGGX (appendix "Spherical Area Lighting") ---- */

/* The constants of the appendix's radius reduction and normalisation:
 *   radius_tan    = max(min_radius_tan, r/d - radius_reduction * alpha)
 *   normalization = a2 (l.h + norm_eps) / (a2 (l.h + norm_eps) + norm_scale * r/d * (norm_alpha * alpha + r/d))
 * with a2 = alpha^2. */
typedef struct {
    float radius_reduction; /* 0.25 */
    float norm_scale;       /* 0.25 */
    float norm_alpha;       /* 3.0 */
    float norm_eps;         /* 0.001 */
    float min_radius_tan;   /* 0.001 */
} decima_sphere_constants;

/* The talk's values (a comparison, never a result of gtlab). */
decima_sphere_constants decima_sphere_published(void);

/* EvaluateSphericalAreaGGX for one colour channel: D from GetNoHSquared,
 * height-correlated Smith visibility and Schlick Fresnel at the centre's
 * n.l, v.l, l.h, times the normalisation and saturate(n.l) (unadjusted).
 * radius_over_distance = R / d (the appendix divides the light's radius by
 * its distance; its normalisation uses the radius itself, which is not
 * scale invariant: gtlab uses R / d there too, equal at unit distance). */
float decima_sphere_ggx(float n_dot_l, float n_dot_v, float v_dot_l, float l_dot_h, float radius_over_distance,
                        float alpha, float f0, const decima_sphere_constants *k, int newton_steps);

/* The same from local-frame vectors (n = +z), white specular (F0 = 1). */
float decima_sphere_ggx_local(vec3 v, vec3 lc, float sin_sigma, float alpha, const decima_sphere_constants *k,
                              int newton_steps);
/* The same with the normalisation's light_radius given: another reading of
 * the appendix (issue 26, item 7), e.g. tan(sigma) or the radius as a
 * length; norm_radius = sin_sigma is decima_sphere_ggx_local. */
float decima_sphere_ggx_local_radii(vec3 v, vec3 lc, float sin_sigma, float norm_radius, float alpha,
                                    const decima_sphere_constants *k, int newton_steps);

/* Not the talk's: the same with its admitted error near the terminator
 * mended (issue 26, item 8). The talk multiplies by saturate(n.lc), the
 * centre's cosine, which is 0 once the centre sinks below the horizon
 * though part of the cap is still above it. Here that factor is the cap's
 * horizon-clipped form factor, sphere_illuminance_frostbite(n.lc, sin sigma)
 * / (pi sin^2 sigma), which equals n.lc while the whole cap is above the
 * horizon (so away from the terminator this is the talk's value up to float
 * rounding) and falls smoothly to 0 as the cap sets; D, visibility and the
 * normalisation are evaluated with n.lc lifted to at least 1e-4. One extra
 * branch and, in the straddling band only, Frostbite's acos/atan. */
float decima_sphere_ggx_horizon_local(vec3 v, vec3 lc, float sin_sigma, float alpha, const decima_sphere_constants *k,
                                      int newton_steps);

/* ---- Lambert: illuminance of a sphere of unit radiance ---- */

/* The exact illuminance, Frostbite's sphere_illuminance_frostbite, is
 * shared machinery: realtime/sphere_illuminance.h. */

/* The representative point for diffuse (Drobot 2014, as in Karis 2013):
 * the cap's direction closest to n, lit as a point light of illuminance
 * pi sin^2(sigma): pi sin^2(sigma) cos(max(theta - sigma, 0)), 0 once the
 * whole cap is below the horizon. */
float sphere_illuminance_representative(float cos_theta, float sin_sigma);

/* ---- A G-buffer lit by a sphere light, as a real-time renderer shades it ---- */

typedef struct {
    vec3 position;
    float radius, radiance; /* of the sphere; radiance L_e */
} sphere_light_source;

/* Per-pixel planes (world space): position, shading normal, diffuse albedo,
 * perceptual roughness, and the mask of covered pixels. */
typedef struct {
    const float *position[3], *normal[3], *albedo, *roughness, *mask;
    size_t count;
} sphere_light_gbuffer;

/* The radiance towards eye of each covered pixel (0 elsewhere) of a
 * dielectric lit by the sphere: the exact Lambert part albedo/pi E
 * (sphere_illuminance_frostbite) plus the specular with Schlick's Fresnel of
 * f0, by Karis (k == NULL) or by Decima with the constants k (one Newton
 * step), times E_perp = pi sin^2(sigma) L_e. */
void sphere_light_shade(const sphere_light_gbuffer *g, vec3 eye, const sphere_light_source *light, float f0,
                        const decima_sphere_constants *k, float *out);

/* A specular term per unit normal illuminance, Fresnel of f0 included, in
 * the local frame (n = +z); user is the method's data. */
typedef float (*sphere_specular_fn)(const void *user, vec3 v, vec3 lc, float sin_sigma, float roughness, float f0);

/* The same shading with another specular (sphere_light_shade is this with
 * the talks' Karis or Decima specular): the exact Lambert part plus
 * E_perp * specular. */
void sphere_light_shade_specular(const sphere_light_gbuffer *g, vec3 eye, const sphere_light_source *light, float f0,
                                 sphere_specular_fn specular, const void *user, float *out);

#endif
