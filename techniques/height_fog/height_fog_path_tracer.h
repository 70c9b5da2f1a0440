/* Light scattered by the height fog towards a camera, by Monte Carlo
 * volumetric path tracing: the multiple-scattering reference of issue 16
 * (and, limited to one scattering, an estimator of the same integral as the
 * quadrature of techniques/height_fog/height_fog_single_scatter.h, which tests both).
 *
 * Free flights are sampled exactly in the exponential medium: a channel c*
 * is drawn uniformly, an optical depth -ln(1 - u) / beta_t,c* is drawn, and
 * the distance that reaches it comes from the closed-form inverse
 * height_fog_distance_at. The pdf is the average over the three channels
 * (spectral "one-sample MIS"), so a collision at density integral D weighs
 *
 *   w_c = beta_t,c e^{-beta_t,c D} / ((1/3) sum_k beta_t,k e^{-beta_t,k D})
 *
 * (rho cancels), and a path leaving the segment weighs e^{-beta_t,c D} over
 * the average of the same. The camera's own segment is the exception: its
 * collision is forced inside the medium (truncated exponentials, the leaving
 * event integrated out; forced_flight in the .c), because a path that
 * leaves it carries no in-scattered light: that event only adds variance,
 * and where it is rare (a thick but finite layer along a rising ray) the
 * per-pixel standard error would not see it. At each collision:
 *   - the sun is added by next-event estimation: w_c E_c S_sun,c(mu) T_sun,c
 *     V_sun / beta_t,c (S_sun: core/optics/height_fog_medium.h; T_sun the fog's
 *     transmittance towards the sun when sun_extinction, V_sun a shadow ray
 *     when occluders);
 *   - single scattering (max_scatterings = 1) adds the model's ambient term
 *     w_c beta_s,c L_amb,c / beta_t,c and stops;
 *   - multiple scattering continues in a direction drawn from the mixture
 *     q HG(g) + (1 - q) uniform, q = beta_Ms / (beta_Ms + mean beta_Rs), the
 *     throughput times (beta_Rs,c p_R + beta_Ms p_HG) / (beta_t,c pdf); a path
 *     that leaves the medium (no collision up to infinity) without meeting
 *     the scene sees the sky, L_amb. Surfaces absorb (their own radiance is
 *     the background the model attenuates by T, not part of the in-scatter).
 * Russian roulette after 8 scatterings on the largest throughput (unbiased);
 * a path stops after max_scatterings (1024 in `render fog`), which drops the
 * light scattered more often than that: a bias, towards less fog.L, not
 * measured here.
 *
 * Random numbers come from a counter-based hash of (seed, sample index,
 * dimension): a sample depends only on them, so renders are bit-identical
 * for any thread count. */
#ifndef GTLAB_HEIGHT_FOG_PATH_TRACER_H
#define GTLAB_HEIGHT_FOG_PATH_TRACER_H

#include <stdint.h>

#include "height_fog/height_fog_single_scatter.h"

typedef struct {
    height_fog_lighting lighting; /* medium, sun extinction, occluders (NULL: no scene beyond the camera segment) */
    int max_scatterings;   /* 1: single scattering; e.g. 1024: multiple */
} height_fog_path_settings;

/* One sample of the in-scattered radiance along o + s w, s in [0, distance]
 * (distance may be +infinity), drawn from (seed, index). Returns the rays
 * traced (shadow and continuation rays). */
int height_fog_path_sample(const height_fog_path_settings *s, vec3 o, vec3 w, double distance, uint32_t seed, uint32_t index,
                    double radiance[3]);

#endif
