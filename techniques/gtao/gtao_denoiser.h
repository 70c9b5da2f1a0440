/* The denoisers of the GTAO talk (seeds/001, "Spatial Denoiser Details",
 * "Temporal Denoiser Details"): a 4x4 bilateral filter whose window is
 * shifted by one pixel every other frame (top/left on odd frames,
 * bottom/right on even ones), and temporal accumulation, here for a static
 * camera: every history sample is valid (reprojection is the identity and
 * the depth test passes), so the accumulation is the running mean over
 * frames, the exponential accumulator with weight 1 / (frame + 1). The
 * frame loop of every screen-space technique (GTAO, HBAO, VO) lives here:
 * it sits above the G-buffer view (screen_space.h), which knows no denoiser. */
#ifndef GTLAB_GTAO_GTAO_DENOISER_H
#define GTLAB_GTAO_GTAO_DENOISER_H

#include <stddef.h>

#include "realtime/screen_space.h"

/* Bilateral 4x4 filter of `in` into `out` (both width*height, background 0).
 * Weights: a neighbour counts with 1 - |z - z_plane| / (0.1 z), clamped to
 * [0, 1], where z_plane extends the centre's depth along its first
 * derivatives (linear depth + first derivatives, Bavoil 2012's 10% ramp). */
void gtao_spatial_denoise(const ss_gbuffer *g, int frame, const float *in, float *out);
/* out = (frame * out + in) / (frame + 1): the running mean of frames 0..frame. */
void gtao_temporal_accumulate(const float *in, int frame, size_t count, float *out);
/* Normalises the direction planes d[0..2] where the mask is set. */
void gtao_normalize_directions(const ss_gbuffer *g, float *const *d);

/* The frame loop every screen-space technique shares: `frames` frames of
 * `frame_fn` (writing `planes` planes, at most 4), each through the 4x4
 * bilateral filter above if `denoise`, averaged by the temporal accumulation
 * into out[0..planes-1]. Returns 0, or -1 when out of memory. */
typedef void (*gtao_frame_fn)(const ss_gbuffer *g, const void *params, int frame, float *const *planes);
int gtao_denoised_frames(const ss_gbuffer *g, gtao_frame_fn frame_fn, const void *params, int frames, int denoise,
                         int planes, float *const *out);

#endif
