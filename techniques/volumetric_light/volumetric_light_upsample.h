/* The half-resolution path and temporal accumulation of INSIDE's volume
 * light (Gjoel & Svendsen, GDC 2016, seed 002, "Half Resolution" .. "Temporal
 * Anti-Aliasing to the Rescue"):
 *
 *   half    the ray-march at (w + 1) / 2 x (h + 1) / 2 pixels, half pixel
 *           (i, j) on the full-resolution ray of pixel (2 i, 2 j) with its
 *           depth (a point-sampled downsample), the noise tiled over the
 *           half-resolution grid;
 *   upsample, depth-aware: full pixel (x, y) reads the four half pixels
 *           around (x / 2, y / 2) with bilinear weights, discarding a tap
 *           whose distance differs from the pixel's by more than
 *           UPSAMPLE_DEPTH_TOLERANCE of it (the talk's "depth-discard per
 *           sample"); if all four are discarded, the tap of nearest
 *           distance;
 *   noisy upsample, the talk's "noisy blur during depth-weighted upsample"
 *           (after Stachowiak's stochastic SSR, which it cites): the same four
 *           taps moved together by a per-pixel, per-frame offset of up to half
 *           a half-resolution pixel each way (blue noise, two decorrelated
 *           reads of the texture), each read at its nearest half pixel and
 *           averaged with equal weights after the same depth discard; over
 *           frames the taps cover a 2 x 2 half-pixel box, which breaks up the
 *           half-resolution grid for TAA;
 *   history exponential accumulation with a static camera (no reprojection,
 *           no neighbourhood clamp: nothing moves), h_f = (1 - a) h_{f-1} + a x_f,
 *           h_0 = x_0. TAA's usual a = 0.1. */
#ifndef GTLAB_VOLUMETRIC_LIGHT_UPSAMPLE_H
#define GTLAB_VOLUMETRIC_LIGHT_UPSAMPLE_H

#include "volumetric_light/volumetric_light_raymarch.h"

#define UPSAMPLE_DEPTH_TOLERANCE 0.1

/* One half-resolution frame: out[(h + 1) / 2 * (w + 1) / 2] and the
 * distances it marched to, half_distance[] (either may be reused by the
 * upsample). */
void raymarch_image_half(const raymarch_lighting *l, const raymarch_view *view, int steps, raymarch_noise noise,
                         const blue_noise_texture *blue, int frame, int threads, float *out, float *half_distance);

/* The depth-aware upsample of a half-resolution image to view's size. */
void raymarch_upsample(const float *half, const float *half_distance, const raymarch_view *view, float *out);

/* The noisy upsample of frame `frame` (offsets from `blue`, 1 channel or more). */
void raymarch_upsample_noisy(const float *half, const float *half_distance, const raymarch_view *view,
                             const blue_noise_texture *blue, int frame, float *out);

/* history[p] = first ? frame[p] : (1 - alpha) history[p] + alpha frame[p]. */
void raymarch_accumulate(float *history, const float *frame, long count, double alpha, int first);

#endif
