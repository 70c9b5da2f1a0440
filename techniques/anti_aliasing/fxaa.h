/* FXAA 3.11, PC quality path (Lottes 2011, "FXAA 3.11", NVIDIA; the
 * FxaaPixelShader of Fxaa3_11.h with FXAA_PC 1 and the default
 * FXAA_QUALITY__PRESET 12), written from its published description for
 * images held in memory: positions in pixels (centres at +0.5), texture
 * fetches bilinear with clamp to edge, luma from the display-encoded colour
 * (the usual prepass: dot(rgb, (0.299, 0.587, 0.114))).
 *
 * Per pixel: the local luma range of the 4 neighbours against
 * max(edge_threshold_min, edge_threshold x max luma) decides whether the pixel is
 * on an edge; the 3 x 3 second differences choose a horizontal or vertical
 * edge and the side of the steeper gradient; from half a pixel towards that
 * side it searches both ways along the edge (preset 12's steps 1, 1.5, 2,
 * 4, 12 pixels) for the end where the luma leaves the edge's mean, and
 * shifts the sampling position across the edge by 0.5 - (distance to the
 * nearer end) / (span length) when that end bends the right way; a
 * subpixel term (the 3 x 3 low-pass against the centre, smoothed as
 * (3 - 2c) c^2, squared, times `subpix`) sets the least shift. The result is
 * the bilinear colour at the shifted position. */
#ifndef GTLAB_ANTI_ALIASING_FXAA_H
#define GTLAB_ANTI_ALIASING_FXAA_H

typedef struct {
    double subpix;             /* fxaaQualitySubpix, default 0.75 */
    double edge_threshold;     /* fxaaQualityEdgeThreshold, default 0.166 */
    double edge_threshold_min; /* fxaaQualityEdgeThresholdMin, default 0.0833 */
} fxaa_settings;

fxaa_settings fxaa_default_settings(void);

/* FXAA of a W x H RGB image of display values (3 floats a pixel) into out
 * (not the input). 0, or -1 if out of memory (out untouched). */
int fxaa_apply(const fxaa_settings *s, const float *rgb, int width, int height, int threads, float *out);

#endif
