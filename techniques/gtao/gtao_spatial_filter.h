/* The GTAO talk's 4x4 bilateral filter with its depth-test variants and
 * the temporal neighbourhood clamp (seeds/001, "Spatial Denoiser Details",
 * "Temporal Denoiser Details"), as options of the filter in
 * gtao_denoiser.h, which is the default here (tested equal):
 *  - depth test: a neighbour at offset (ox, oy) counts with
 *    w = clamp(1 - |z - z_model| / (t z_c), 0, 1), t = 0.1 ("pixels with
 *    depth delta bigger than 10% of current depth don't accumulate", a
 *    linear ramp), where z_model extends the centre's depth
 *      LINEAR_D1: z_c + z_x ox + z_y oy (first derivatives),
 *      LINEAR_D2: + (z_xx ox^2 + z_yy oy^2) / 2 (second derivatives, "for
 *                 slopes": linear depth along a tilted plane is not linear
 *                 in screen space, 1 / z is),
 *      LOG_D1:    the same as LINEAR_D1 in log z, |log z - model| / t (the
 *                 talk's "also tried log-space depth + first derivatives";
 *                 a relative difference of t is about t in log z);
 *    derivatives are one-sided, on the side of the smaller first difference
 *    (at a silhouette, the side on the same surface), the second difference
 *    two steps along that side;
 *  - alternate: the asymmetric window [-1, 2]^2 moves to [-2, 1]^2 on odd
 *    frames (the talk's compensation for the half-pixel shift that temporal
 *    accumulation would otherwise pile up), or stays put;
 *  - the neighbourhood clamp of the history: with a static camera both
 *    velocities agree, the velocity weight is 1, and the history is clamped
 *    to [min - c (max - min), max + c (max - min)] over the current frame's
 *    3x3 neighbourhood, c = clampWindowSize (0.5 in the talk). */
#ifndef GTLAB_GTAO_GTAO_SPATIAL_FILTER_H
#define GTLAB_GTAO_GTAO_SPATIAL_FILTER_H

#include <stddef.h>

#include "realtime/screen_space.h"

typedef enum { GTAO_DEPTH_LINEAR_D1, GTAO_DEPTH_LINEAR_D2, GTAO_DEPTH_LOG_D1, GTAO_DEPTH_TESTS } gtao_depth_test;
extern const char *const gtao_depth_test_names[GTAO_DEPTH_TESTS];

typedef struct {
    gtao_depth_test depth_test;
    int alternate;   /* 1: the window alternates (the talk's); 0: always [-1, 2]^2 */
    float threshold; /* 0.1 */
} gtao_spatial_options;
/* LINEAR_D1, alternating, 0.1: gtao_spatial_denoise. */
extern const gtao_spatial_options gtao_spatial_default;

/* The weight of neighbour (x + ox, y + oy) of pixel (x, y), both covered. */
float gtao_depth_test_weight(const ss_gbuffer *g, const gtao_spatial_options *o, int x, int y, int ox, int oy);
/* gtao_spatial_denoise with options. */
void gtao_spatial_filter(const ss_gbuffer *g, int frame, const gtao_spatial_options *o, const float *in, float *out);
/* The static-camera accumulation (running mean, frame 0 takes `in`) with the
 * history first clamped to the widened 3x3 range of `in`; clamp_window < 0:
 * no clamp (gtao_temporal_accumulate). */
void gtao_temporal_clamped(const ss_gbuffer *g, const float *in, int frame, float clamp_window, float *history);

#endif
