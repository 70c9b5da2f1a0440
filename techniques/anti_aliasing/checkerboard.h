/* The talk's checkerboard rendering (Decima / Horizon Zero Dawn on PS4 Pro,
 * SIGGRAPH 2017, "2160p checkerboard"; issue 19): each frame renders 50% of
 * the pixel CORNERS, corner (i, j) (at image position (i, j)) when
 * i + j + parity is even, parity = frame mod 2, so two frames render all
 * of them; no native-resolution hints.
 *   1. The corners of one frame, seen as the centres of their Voronoi
 *      diamonds, are square pixels of a grid rotated by 45 degrees:
 *          a = (x + y - parity) / 2,   b = (x - y - parity) / 2 + K,
 *      K = H / 2 + 1 keeping b >= 0. The talk packs this grid into a
 *      "tangram" texture (a lossless GPU memory layout); here it is stored
 *      as it is, an A x B image, A = (W + H) / 2 + 1, B = (W + 1) / 2 + K + 1,
 *      its cells outside the image holding the nearest rendered corner
 *      (clamp to edge for the fetches). The talk's YCoCg storage (4 lumas a
 *      gather) changes no value and is not modelled.
 *   2. FXAA 3.11 on the rotated grid (the talk: "removes jaggies from
 *      diagonal lines because of the tangram").
 *   3. The resolve: pixel (i, j)'s centre is halfway between its two
 *      rendered corners, so the bilinear fetch of the rotated grid there is
 *      their average (the talk's appendix code). The previous frame's grid
 *      is fetched the same way at the centre plus the motion vector (its two
 *      other corners when nothing moves); if accepted, out = (current +
 *      history) / 2, the 4 corners, else the current 2-corner average. The
 *      rejection ("standard criteria" in the talk): history outside the
 *      3 x 3 per-channel min / max box of the current frame's resolve, or
 *      fetched from outside the image (settings.reject = 0 accepts all).
 * A static scene is therefore exact after two frames: every pixel the mean
 * of its 4 corners (without FXAA, and with rejection where history passes). */
#ifndef GTLAB_ANTI_ALIASING_CHECKERBOARD_H
#define GTLAB_ANTI_ALIASING_CHECKERBOARD_H

#include "anti_aliasing/fxaa.h"

typedef struct {
    int fxaa;   /* 1: FXAA on the rotated grid (the talk) */
    int reject; /* 1: neighbourhood rejection of history */
    fxaa_settings fx;
} checkerboard_settings;

checkerboard_settings checkerboard_default_settings(void);

/* One frame's rotated grid. */
typedef struct {
    int width, height; /* the native image */
    int parity, k, a_count, b_count;
    float *rgb; /* a_count x b_count RGB */
} checkerboard_grid;

/* 1 if frame `frame` renders corner (i, j). */
int checkerboard_renders(int frame, int i, int j);

/* Steps 1 and 2: corners is a W x H RGB image whose pixel (i, j) holds the
 * sample at corner (i, j); only the corners the frame renders are read.
 * 0, or -1 if out of memory (grid empty). */
int checkerboard_grid_build(const checkerboard_settings *s, const float *corners, int width, int height, int frame,
                            int threads, checkerboard_grid *grid);
void checkerboard_grid_free(checkerboard_grid *grid);

/* Step 3 into out (W x H RGB); previous NULL on the first frame. 0, or -1
 * if out of memory. */
int checkerboard_resolve(const checkerboard_settings *s, const checkerboard_grid *current,
                         const checkerboard_grid *previous, const float *motion, int threads, float *out);

#endif
