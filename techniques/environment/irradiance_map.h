/* The exact irradiance map: the cosine convolution of an environment by
 * direct quadrature over its texels, tabulated on an equirect map that a
 * shader samples with the normal (the "pre-convolved probe" of engines;
 * Ramamoorthi and Hanrahan 2001 call the same quantity an irradiance
 * environment map, and approximate it with 9 SH coefficients,
 * environment/sh_irradiance.h).
 *
 *   E(n) = \int L(w) max(0, n.w) dw
 *        = sum_t L_t \int_t max(0, n.w) dw          (L piecewise constant per texel t)
 *
 * For a texel wholly above n's horizon the integral is n . M_t with M_t =
 * \int_t w dw, its first moment, in closed form (environment/environment_equirect.h);
 * wholly below, 0; straddling the horizon, max(0, n . M_t) (the only
 * approximation: an error of at most L_t Omega_t times the texel's angular
 * size, on the ring of texels the horizon crosses). The same holds for a
 * block of texels: sum_t L_t (n . M_t) = n . (sum_t L_t M_t), so the
 * quadrature runs over blocks of 2^reduction x 2^reduction texels, each
 * holding the vector sum L_t M_t per channel, and is exact but for the
 * blocks the horizon crosses.
 *
 * Cost: (map texels) x (blocks) x 9 multiply-adds: a 64 x 32 map from a
 * 1024 x 512 environment at reduction 3 (128 x 64 blocks of 8 x 8 texels)
 * is 2048 x 8192 x 9 = 1.5e8 multiply-adds, ~0.1 s on one core; at
 * reduction 0, 64 times that.
 *
 * The lookup is bilinear (environment/environment_equirect.h): the map is smooth
 * (the convolution is a low-pass filter), so 64 x 32 texels interpolate it
 * well; tests/test_irradiance_map.c measures it. */
#ifndef GTLAB_ENVIRONMENT_IRRADIANCE_MAP_H
#define GTLAB_ENVIRONMENT_IRRADIANCE_MAP_H

#include "environment/environment_equirect.h"

typedef struct {
    int width, height; /* height = width / 2 */
    int reduction;     /* the blocks were 2^reduction texels wide (after clamping to the environment's size) */
    float *rgb;        /* E at the texel centres */
} irradiance_map;

/* Builds a width x width/2 map (width >= 2, even) from env, blocks of
 * 2^reduction texels (reduced while the environment's size is not a
 * multiple), OpenMP over `threads` (every texel alone: the bits do not
 * depend on it). Returns 0, or -1 when out of memory or a size is invalid. */
int irradiance_map_build(irradiance_map *m, const environment_equirect *env, int width, int reduction, int threads);
void irradiance_map_free(irradiance_map *m);

/* E(n) by the map's quadrature at any unit n, without tabulation (the map's
 * entries are this at their texel centres). */
void irradiance_map_quadrature(const environment_equirect *env, int reduction, const double n[3], double e[3]);

/* Bilinear lookup of the map at a unit normal. */
void irradiance_map_lookup(const irradiance_map *m, const double n[3], float e[3]);

#endif
