/* The published HeightFog()'s per-pixel steps (height_fog/height_fog.h), shared
 * by the one-pixel function and the batch so both run the same arithmetic.
 * Internal to height_fog/height_fog*.c. */
#ifndef GTLAB_HEIGHT_FOG_PUBLISHED_H
#define GTLAB_HEIGHT_FOG_PUBLISHED_H

#include <math.h>

#include "height_fog/height_fog.h"

#define HEIGHT_FOG_PI_F 3.14159265358979323846f

/* Rayleigh phase 3 / (16 pi) (1 + mu^2). */
static inline float height_fog_rayleigh(float mu)
{
    return 3.0f / 4.0f * 1.0f / (4.0f * HEIGHT_FOG_PI_F) * (1.0f + mu * mu);
}

/* Henyey-Greenstein (1 - g^2) / (4 pi (1 + g^2 - 2 g mu)^1.5), the power as
 * d sqrt(d): the same function (HLSL compilers expand pow into
 * exp2(1.5 log2(d)) anyway), without a general powf per pixel. */
static inline float height_fog_henyey_greenstein(const height_fog_uniforms *u, float mu)
{
    float d = u->hg_base - u->hg_slope * mu;
    return u->hg_numerator / ((4.0f * HEIGHT_FOG_PI_F) * (d * sqrtf(d)));
}

/* The single-scattering albedo-weighted phase sum of channel c. */
static inline float height_fog_single(const height_fog_uniforms *u, int c, float pr, float pm)
{
    return u->rayleigh_weight[c] * pr + u->mie_weight[c] * pm;
}

/* (E_sun S_sun(mu) + L_amb beta_s) / beta_t: the source over extinction. */
static inline float height_fog_source(const height_fog_uniforms *u, int c, float single)
{
    return (u->sun[c] * single + u->ambient[c]) / u->beta_t[c];
}

/* The published clamp t = max(1e-2, (y_c - y_w) / H), written as a select
 * (the same value, NaN included: fmaxf returns the number) so that a loop
 * around it still vectorises. */
static inline float height_fog_clamped_t(const height_fog_uniforms *u, float camera_y, float world_y)
{
    float t = (camera_y - world_y) / u->scale_height;
    return t > 1e-2f ? t : 1e-2f;
}

/* The published mean density factor (1 - e^-t) / t e^(-y_w / H). */
static inline float height_fog_published_density(const height_fog_uniforms *u, float t, float world_y)
{
    return (1.0f - expf(-t)) / t * expf(-world_y / u->scale_height);
}

#endif
