/* The analytic height fog of the Decima talk (Kojima Productions, "Height
 * fog", SIGGRAPH 2017 Advances, slide "Height fog: Analytic model"), in C
 * with the shader's float arithmetic, as published and corrected where the
 * references show it wrong (techniques/height_fog/README.md). The medium is
 * core/optics/height_fog_medium.h.
 *
 * Published. With beta_t = beta_Rs + beta_Ms + beta_Ma, distance d, camera
 * and world altitudes y_c, y_w:
 *
 *   t = max(1e-2, (y_c - y_w) / H)
 *   T = exp(-d beta_t (1 - e^-t) / t  e^(-y_w / H))
 *   L_in = (E_sun S_sun(mu) + L_amb beta_s) / beta_t (1 - T)
 *
 * For t >= 1e-2 (the world point at least H/100 below the camera) T is the
 * exact transmittance exp(-beta_t d e^{-y_low/H} f(|Delta|/H)) of
 * core/optics/height_fog_medium.h. The clamp replaces t < 1e-2, i.e. every
 * horizontal or upward ray and every world point above the camera, by
 * t = 1e-2, which uses the density of the world point, the thinnest point of
 * an upward ray: T is too high, by exp(beta_t d [e^{-y_c/H} f(Delta/H) -
 * e^{-y_w/H} f(1e-2)]). And L_in is exact single scattering only if the sun
 * reaches every point of the ray unattenuated by the fog and unshadowed, and
 * the ambient is an isotropic, unattenuated, unshadowed sky: then the source
 * term J / beta_t is the same at every point and the integral of
 * beta_s rho T J is J beta_s / beta_t (1 - T).
 *
 * Corrected. T from the exact optical depth for every sign of Delta (no
 * clamp), and the sun attenuated by the fog above each point (a flat,
 * infinite exponential layer; sun elevation sin = mu_s > 0): with the view
 * ray's vertical cosine v_y = Delta / d, tau_v = -ln T, the sun's optical
 * depth at the camera A = beta_t H rho(y_c) / mu_s and m = 1 - v_y / mu_s,
 * d(tau_v + tau_sun)/ds = m d(tau_v)/ds along the ray, so
 *
 *   \int_0^d beta_s rho e^{-tau_v(s) - tau_sun(s)} ds
 *       = beta_s / beta_t e^{-A} tau_v f(m tau_v),   f(x) = (1 - e^-x) / x,
 *
 * exact under single scattering for any direction (f of a negative argument
 * is evaluated as e^{-(A + m tau_v)} tau_v f(-m tau_v): no overflow). With
 * the sun on or below the horizon the sun term is 0.
 *
 * Sky attenuated. The published ambient term is an isotropic sky of
 * radiance L_amb reaching every point from the whole sphere. In an infinite
 * flat exponential layer nothing arrives from below (the optical depth
 * downwards is infinite) and the sky above arrives through the column
 * above the point: from the direction of vertical cosine mu > 0 with
 * transmittance e^{-a(y) / mu}, a(y) = beta_t H rho(y). With an isotropic
 * phase the source is beta_s L_amb E_2(a) / 2 (techniques/height_fog/height_fog_single_scatter.h),
 * and along the ray a = A - v_y tau_v(s), A = a(y_c), exactly as the sun's
 * optical depth above with mu for mu_s: the sky is a continuum of suns, one
 * per elevation, each entering like the attenuated sun term,
 *
 *   L_amb,in = beta_s / beta_t L_amb (1/2) \int_0^1 e^{-A/mu} tau_v f((1 - v_y/mu) tau_v) dmu,
 *
 * integrated in mu by 6-point Gauss-Legendre (Abramowitz and Stegun 1964,
 * table 25.4): 6 nodes x 3 channels x 2 exponentials, a shader's budget.
 * Without fog (A, tau_v -> 0) it is half the published term: the lower
 * hemisphere's half of L_amb never arrives. The ground's own shape (hills
 * hiding part of the sky) is not modelled. */
#ifndef GTLAB_HEIGHT_FOG_H
#define GTLAB_HEIGHT_FOG_H

#include <stddef.h>

#include "core/optics/height_fog_medium.h"

/* The talk's HeightFog(): the argument order and the max(1e-2, ...) clamp
 * as published; in-scatter and transmittance RGB. inSov = dot(sun_dir,
 * view_dir). The sun's direction in p is not read. */
void height_fog_published(const height_fog_param *p, float distance, float camera_y, float world_y, float sov,
                          float inscatter[3], float transmittance[3]);

/* The published function's per-frame constants in float, as a shader's
 * constant buffer holds them (the per-pixel work is then what a pixel
 * shader does): beta_t, the phase weights and the ambient term per channel,
 * and the Henyey-Greenstein terms of g. Evaluating through them gives the
 * bits of evaluating from height_fog_param. */
typedef struct {
    float scale_height;
    float beta_t[3];          /* beta_Rs + (beta_Ms + beta_Ma) */
    float rayleigh_weight[3]; /* albedo_R beta_Rs: multiplies the Rayleigh phase */
    float mie_weight[3];      /* albedo_M beta_Ms: multiplies the HG phase */
    float sun[3];             /* E_sun */
    float ambient[3];         /* L_amb (beta_Rs + beta_Ms) */
    float hg_numerator;       /* 1 - g^2 */
    float hg_base, hg_slope;  /* 1 + g^2 and 2 g: the HG denominator's base 1 + g^2 - 2 g mu */
} height_fog_uniforms;

void height_fog_uniforms_init(const height_fog_param *p, height_fog_uniforms *u);

/* The published HeightFog() for n pixels seen from one camera altitude, in
 * planes (inscatter[c][i], transmittance[c][i]), as a CPU port runs it over
 * an image: the arithmetic of height_fog_published, in a loop the compiler
 * vectorises, with glibc's vector expf (libmvec, within 4 ulp: glibc manual,
 * "Errors in Math Functions") where the compiler supports it, the scalar
 * expf elsewhere. So the result is height_fog_published's within expf's
 * error propagated (the bound is techniques/height_fog/tests/test_height_fog_batch.c's),
 * and the same bits for any split of the n pixels into calls. */
void height_fog_published_batch(const height_fog_uniforms *u, float camera_y, size_t n, const float *distance,
                                const float *world_y, const float *sov, float *const inscatter[3],
                                float *const transmittance[3]);

/* How much of the correction above is applied; each level includes the ones before. */
typedef enum {
    HEIGHT_FOG_FIX_CLAMP,     /* the exact optical depth; the published sun and ambient terms */
    HEIGHT_FOG_ATTENUATE_SUN, /* and the sun attenuated by the fog (reads p->sun_direction.y) */
    HEIGHT_FOG_ATTENUATE_SKY  /* and the ambient: the upper hemisphere's sky seen through the fog */
} height_fog_correction;

/* The corrected model above at the given level. The floor of p is not modelled. */
void height_fog_corrected(const height_fog_param *p, height_fog_correction level, float distance, float camera_y,
                          float world_y, float sov, float inscatter[3], float transmittance[3]);

#endif
