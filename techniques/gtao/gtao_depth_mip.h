/* The GTAO talk's half resolution and depth MIP chain (seeds/001,
 * "Achieving the Performance Target"): "Traverse a depth mipmap chain during
 * sampling. Near samples: use half-res depth. Further away samples:
 * progressively use lower mips. D3D11_FILTER_MINIMUM_*: gets closest to
 * camera height on 2x2 bilinear block; for small offsets: closest height ~=
 * max horizon; improves samples per direction (4x). Alternative:
 * min(Gather4())".
 *
 * The chain: level 0 is the G-buffer's depth (background: +infinity), level
 * l + 1 the minimum (closest to the camera) of each 2x2 block of level l.
 * A sample at screen distance t pixels reads level
 *     l = clamp(floor(log2 t - 3.3), 0, levels - 1)
 * (XeGTAO's DepthMIPSamplingOffset 3.3: Intel's open GTAO, 2021), either
 * point-sampled (the texel under the sample) or MIN-filtered: the minimum of
 * the 2x2 texels of its bilinear footprint at that level. A MINIMUM
 * comparison filter with linear min/mag returns exactly that minimum, and so
 * does min(Gather4()) at that level: one code path stands for both.
 *
 * A sample's position is its screen point's eye ray at the fetched depth
 * (what a shader reconstructs from a depth texel; the full-resolution search
 * of gtao.c uses the pixel's tangent plane instead, so the point-sampled
 * full-resolution search here is the like-for-like baseline). Moving a point
 * along its eye ray towards the camera raises its elevation seen from any
 * other point, so a MIN fetch never lowers a horizon below the point-sampled
 * one: tests/test_gtao_depth_mip.c. */
#ifndef GTLAB_GTAO_GTAO_DEPTH_MIP_H
#define GTLAB_GTAO_GTAO_DEPTH_MIP_H

#include "gtao/gtao.h"

enum { SS_DEPTH_MIP_MAX_LEVELS = 5 };
#define GTAO_MIP_SAMPLING_OFFSET 3.3f /* XeGTAO's DepthMIPSamplingOffset */

typedef struct {
    int levels;
    int width[SS_DEPTH_MIP_MAX_LEVELS], height[SS_DEPTH_MIP_MAX_LEVELS];
    float *depth[SS_DEPTH_MIP_MAX_LEVELS]; /* +infinity where no covered pixel lies below */
} ss_depth_mip;

/* The MIN chain of g's depth, `levels` levels (1..SS_DEPTH_MIP_MAX_LEVELS).
 * Returns 0, or -1 when out of memory (m freed). */
int ss_depth_mip_build(const ss_gbuffer *g, int levels, ss_depth_mip *m);
void ss_depth_mip_free(ss_depth_mip *m);

typedef enum {
    GTAO_FETCH_POINT,    /* level 0, the texel under the sample */
    GTAO_FETCH_MIP,      /* level by distance, the texel under the sample */
    GTAO_FETCH_MIP_MIN   /* level by distance, MIN of the bilinear footprint (= min(Gather4)) */
} gtao_depth_fetch;

/* The level a sample t pixels from the centre reads. */
int gtao_mip_level(float distance_px, int levels);
/* The depth at screen point (fx, fy) (level-0 pixels) of `fetch`;
 * +infinity when nothing is covered there. */
float gtao_fetch_depth(const ss_depth_mip *m, gtao_depth_fetch fetch, float fx, float fy, float distance_px);

/* gtao_search_slice with the samples' depths fetched from the chain
 * (p->steps >= 1 regular samples per side; the cosine hemisphere clamp, the
 * attenuation and the fast math of p as in gtao.c, no thickness). */
void gtao_mip_search_slice(const ss_gbuffer *g, const ss_depth_mip *m, gtao_depth_fetch fetch, int x, int y,
                           const gtao_params *p, float phi, float offset, gtao_slice *s);
/* Cosine-weighted GTAO of every pixel with p->slices regular slices (no
 * pattern, no denoiser), depths from the chain. Background pixels get 0. */
void gtao_mip_frame(const ss_gbuffer *g, const ss_depth_mip *m, gtao_depth_fetch fetch, const gtao_params *p,
                    float *ao);

/* Half resolution: each 2x2 block of `full` becomes the block's covered
 * pixel closest to the camera (its depth, normal and coverage: the MIN
 * chain's level 1 with the geometry that goes with it); the camera is
 * unchanged. Sizes round up. */
typedef struct {
    ss_gbuffer g;
    float *storage;
} ss_half_gbuffer;
int ss_half_resolution(const ss_gbuffer *full, ss_half_gbuffer *half);
void ss_half_free(ss_half_gbuffer *half);
/* Each full-resolution pixel takes its block's half-resolution value. */
void ss_upsample_nearest(const ss_gbuffer *full, const ss_gbuffer *half, const float *half_values, float *out);

#endif
