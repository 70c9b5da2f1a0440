/* The talk's 2-frame edge-sample TAA (Decima / Horizon Zero Dawn, SIGGRAPH
 * 2017, "AA in 1080p"; issue 19). No accumulated history: only the current
 * and the previous raw renders are used. Each frame is rendered with its
 * samples on pixel edges (taa_edge_jitter: odd frames at (i + 1, j + 0.5),
 * horizontally between pixel centres, even frames at (i + 0.5, j + 1)),
 * then
 *   1. FXAA 3.11 (anti_aliasing/fxaa.h) on those samples, as an ordinary image;
 *   2. a 1-D resample from the edges to the pixel centres along the frame's
 *      direction, the centre lying halfway between samples b and c with a
 *      and d one further out:
 *          plain      P = (b + c) / 2
 *          sharpened  S = P + w ((b - a) + (c - d)),   weights (-w, 1/2 + w, 1/2 + w, -w),
 *      a 4-tap kernel with negative lobes; w = w0 (1 - contrast), contrast
 *      the luma range max - min of the four taps (Rec. 601 luma of the
 *      display values, clamped to [0, 1]), w0 = 1/16 the Catmull-Rom
 *      weights at the midpoint (-1/16, 9/16, 9/16, -1/16): sharpest in flat
 *      texture, a plain 2-tap average across strong edges. The slides say
 *      only "like Catmull-Rom, but cheaper, the amount of sharpening
 *      determined by local contrast": w0, the contrast measure, and one w
 *      for all channels are our choices; S is clamped to the display range
 *      [0, 1] only, so the halo the talk shows remains;
 *   3. the resolve: the previous frame's S fetched bilinearly at the pixel
 *      centre plus its motion vector is accepted when it lies inside the
 *      current S's 3 x 3 per-channel min / max box (the talk's "more
 *      traditional" neighbourhood rejection; the box test is our choice)
 *      and the position is inside the image: out = (S + S_prev) / 2, the
 *      4 edge samples; otherwise out = P, the current frame unsharpened. */
#ifndef GTLAB_ANTI_ALIASING_TAA_EDGE_H
#define GTLAB_ANTI_ALIASING_TAA_EDGE_H

#include "anti_aliasing/fxaa.h"

typedef struct {
    double sharpen; /* w0, 1/16 */
    int fxaa;       /* 1: FXAA on the samples (the talk) */
    fxaa_settings fx;
} edge_taa_settings;

edge_taa_settings edge_taa_default_settings(void);

/* Steps 1 and 2 for frame `frame` (its parity picks the direction): samples
 * W x H RGB (sample (i, j) is pixel (i, j)'s, at its edge), into sharpened
 * and plain (W x H RGB). 0, or -1 if out of memory. */
int edge_taa_resample(const edge_taa_settings *s, const float *samples, int frame, int width, int height, int threads,
                      float *sharpened, float *plain);

/* Step 3: previous_sharpened NULL on the first frame (out = plain). */
void edge_taa_resolve(const float *sharpened, const float *plain, const float *previous_sharpened, const float *motion,
                      int width, int height, int threads, float *out);

#endif
