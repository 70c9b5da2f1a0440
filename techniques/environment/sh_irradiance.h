/* Irradiance from 9 spherical-harmonic coefficients: Ramamoorthi and
 * Hanrahan 2001, "An Efficient Representation for Irradiance Environment
 * Maps" (SIGGRAPH), the diffuse ambient term engines ship.
 *
 * Basis (their eq. 3, real SH, l <= 2) at a unit direction (x, y, z):
 *   Y00 = 0.282095
 *   Y1-1 = 0.488603 y,  Y10 = 0.488603 z,  Y11 = 0.488603 x
 *   Y2-2 = 1.092548 xy, Y2-1 = 1.092548 yz, Y21 = 1.092548 xz
 *   Y20 = 0.315392 (3 z^2 - 1),  Y22 = 0.546274 (x^2 - y^2)
 * (the exact constants: 1/2 sqrt(1/pi), sqrt(3/(4 pi)), 1/2 sqrt(15/pi),
 * 1/4 sqrt(5/pi), 1/4 sqrt(15/pi)). The basis is orthonormal in any frame,
 * so gtlab uses world coordinates (+Y up) as they come.
 *
 * Projection (eq. 10): L_lm = \int L(w) Y_lm(w) dw, integrated EXACTLY per
 * texel of the equirect environment read as piecewise constant: each Y_lm
 * is a polynomial of degree <= 2 in w and its integral over a texel has a
 * closed form (environment/environment_equirect.h, equirect_texel_moments). No
 * quadrature error beyond the environment's own texels.
 *
 * Irradiance (eqs. 12-13): E(n) = sum_lm A_l L_lm Y_lm(n), with the clamped
 * cosine's convolution weights A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4.
 *
 * Truncation (tests/test_sh_irradiance.c): for a constant environment
 * L the result pi L is exact. For a single clamped-cosine lobe L(w) =
 * max(0, w.d) the exact irradiance at angle g between n and d is
 *   E(g) = 2/3 ((pi - g) cos g + sin g)
 * and the 9 terms give E9(g) = pi/4 + pi/3 cos g + 5 pi/64 (3 cos^2 g - 1) / 2
 * (the lobe's own SH coefficients are A_l Y_lm(d), so each band contributes
 * A_l^2 (2l+1)/(4 pi) P_l(cos g)); the error E9 - E is largest, -pi/192
 * = -0.0164 (0.78% of the peak 2 pi / 3), at both ends: g = pi (E9 =
 * -0.0164 where E = 0: why engines clamp) and g = 0 (2.0780 against
 * 2.0944). */
#ifndef GTLAB_ENVIRONMENT_SH_IRRADIANCE_H
#define GTLAB_ENVIRONMENT_SH_IRRADIANCE_H

#include "environment/environment_equirect.h"

enum { SH9_COEFFICIENTS = 9 };

/* Coefficients per colour channel, in the order of the header's basis
 * (l = 0; l = 1: m = -1, 0, 1; l = 2: m = -2 .. 2). */
typedef struct {
    double c[SH9_COEFFICIENTS][3];
} sh9_rgb;

/* The convolution weight A_l of band l = 0, 1, 2. */
double sh9_cosine_band(int l);

/* Y_lm(w) for the nine (l, m). */
void sh9_basis(const double w[3], double y[SH9_COEFFICIENTS]);

/* The exact per-texel projection of an environment. */
void sh9_project_equirect(const environment_equirect *env, sh9_rgb *out);

/* E(n) = sum A_l L_lm Y_lm(n) per channel (may be slightly negative where
 * the truncation rings; engines clamp, so does sh9_irradiance_clamped). */
void sh9_irradiance(const sh9_rgb *sh, const double n[3], double e[3]);
void sh9_irradiance_clamped(const sh9_rgb *sh, const double n[3], double e[3]);

#endif
