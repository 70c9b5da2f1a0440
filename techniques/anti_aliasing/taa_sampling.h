/* What every temporal anti-aliasing pass here shares (issue 19): the
 * sub-pixel jitter sequences, bilinear fetches of an RGB image with clamp to
 * edge, and the 3 x 3 neighbourhood box used to reject or clamp history.
 * Images are W x H RGB display values (3 floats a pixel), positions in
 * pixels with pixel (i, j)'s centre at (i + 0.5, j + 0.5); motion vectors
 * (2 floats a pixel) give the previous frame's position of the surface a
 * pixel sees minus its own position, so history is read at centre + motion. */
#ifndef GTLAB_ANTI_ALIASING_TAA_SAMPLING_H
#define GTLAB_ANTI_ALIASING_TAA_SAMPLING_H

/* The radical inverse of index in base (2 or 3: Halton 1964). */
double taa_radical_inverse(unsigned index, unsigned base);

/* Frame k's jitter for the conventional TAA: Halton (2, 3) point k + 1
 * (index 0 is (0, 0)) minus 0.5, in (-0.5, 0.5) pixels, period `period`
 * (8 in the study, as UE4's default), so frame k and k + period coincide. */
void taa_halton_jitter(int frame, int period, float out[2]);

/* The talk's edge samples: odd frames sample horizontally between pixel
 * centres, at (i + 1, j + 0.5) (jitter (+0.5, 0)), even frames vertically,
 * at (i + 0.5, j + 1) (jitter (0, +0.5)). The slides leave the sign open:
 * +0.5 is our choice (either puts the union of two frames on all 4 edges). */
void taa_edge_jitter(int frame, float out[2]);

/* Bilinear colour at (x, y) with clamp to edge. */
void taa_bilinear(const float *rgb, int width, int height, double x, double y, float out[3]);

/* Per-channel min and max over the 3 x 3 pixels around (i, j) (clamped). */
void taa_neighbourhood_box(const float *rgb, int width, int height, int i, int j, float lo[3], float hi[3]);

/* 1 if (x, y) is inside the image [0, W] x [0, H]. */
int taa_inside(int width, int height, double x, double y);

#endif
