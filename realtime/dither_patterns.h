/* The dither patterns INSIDE compared (Gjoel, GDC 2016, seed 002), each as a
 * value in [0, 1[ per pixel with a flat histogram, to be shaped into RPDF or
 * TPDF dither by realtime/dither.h:
 *   - white: an independent uniform per pixel (luts/blue_noise.h's hash);
 *   - blue: a void-and-cluster texture tiled over the screen (Ulichney 1993);
 *   - interleaved gradient noise (Jimenez 2014, "Next Generation Post
 *     Processing in Call of Duty: Advanced Warfare", slide 123):
 *         frac(52.9829189 frac(0.06711056 x + 0.00583715 y));
 *   - Bayer's ordered dither (Bayer 1973): the 2^k x 2^k index matrix by the
 *     recursion M_2n = [[4 M, 4 M + 2], [4 M + 3, 4 M + 1]], value
 *     (M + 1/2) / 4^k. */
#ifndef GTLAB_REALTIME_DITHER_PATTERNS_H
#define GTLAB_REALTIME_DITHER_PATTERNS_H

#include <stdint.h>

#include "luts/blue_noise.h"

typedef enum {
    DITHER_PATTERN_WHITE = 0,
    DITHER_PATTERN_BLUE,
    DITHER_PATTERN_IGN,
    DITHER_PATTERN_BAYER,
    DITHER_PATTERN_COUNT
} dither_pattern;

const char *dither_pattern_name(dither_pattern p);

/* Interleaved gradient noise at pixel (x, y) (pixel indices, as Jimenez's
 * SV_Position minus 1/2). */
double dither_ign(int x, int y);

/* Bayer's 8 x 8 ordered dither at (x, y): (M(x mod 8, y mod 8) + 1/2) / 64. */
double dither_bayer8(int x, int y);

/* The pattern's value at (x, y); `stream` selects an independent copy where
 * the pattern has one (white: the hash's seed; blue: the texture's channel
 * stream mod channel_count; IGN and Bayer: offset by (5, 3) pixels per
 * stream). `blue` may be NULL except for DITHER_PATTERN_BLUE. */
double dither_pattern_value(dither_pattern p, const blue_noise_texture *blue, uint64_t stream, int x, int y);

#endif
