/* Resolving supersampled images to pixels (pbrt-v4 §8.8 "Image
 * Reconstruction"): pixel (i, j), centre (i + 0.5, j + 0.5), is the
 * weighted mean of the samples within the filter's radius,
 *     I(i, j) = sum_k w(x_k - c) f_k / sum_k w(x_k - c),
 * with the filter separable, w(dx, dy) = w1(dx) w1(dy):
 *   box              w1 = 1 on |d| <= 0.5 (each pixel its own samples)
 *   Blackman-Harris  w1(d) = a0 - a1 cos(2 pi t) + a2 cos(4 pi t) - a3 cos(6 pi t),
 *                    t = (d + r) / (2 r), |d| <= r = 1.5 pixels, a = 0.35875,
 *                    0.48829, 0.14128, 0.01168 (Harris 1978, the 4-term
 *                    window; the radius is Cycles' default filter width 1.5
 *                    as a half-width, a choice: see docs/decisions.md).
 * The samples of a (W s) x (H s) grid are used at their given positions, so
 * jittered samples get their exact weights; near the border only samples
 * inside the image count (the weights are renormalised). */
#ifndef GTLAB_CORE_SAMPLING_PIXEL_FILTER_H
#define GTLAB_CORE_SAMPLING_PIXEL_FILTER_H

typedef enum { PIXEL_FILTER_BOX, PIXEL_FILTER_BLACKMAN_HARRIS, PIXEL_FILTER_COUNT } pixel_filter;

const char *pixel_filter_name(int filter);
double pixel_filter_radius(pixel_filter f);
double pixel_filter_weight(pixel_filter f, double dx, double dy);

/* W x H RGB pixels from the (W s) x (H s) samples rgb at positions xy (2
 * floats each, image pixels). Deterministic for any thread count. */
void pixel_filter_resolve(pixel_filter f, const float *rgb, const float *xy, int width, int height, int s,
                          int threads, float *out);

#endif
