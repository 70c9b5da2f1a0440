/* Means over an image's mask with a standard error that respects spatial
 * correlation: pixels are grouped into square blocks (8x8 in gtlab's
 * studies), each block a cluster, and the mean's variance is estimated from
 * the spread of the block totals (the cluster, or "ratio", estimator):
 *     mean = sum_i x_i / N,
 *     se^2 = B / (B - 1) sum_b (T_b - mean n_b)^2 / N^2,
 * with T_b the sum and n_b the count of block b's pixels inside the mask, B
 * the blocks holding any, N = sum_b n_b. Neighbouring pixels' errors are
 * correlated (shared samples, denoisers, smooth geometry), so a per-pixel
 * standard error would be too small; a block much larger than the
 * correlation length makes blocks nearly independent.
 *
 * Paired comparisons: the difference of two techniques' squared errors
 * against one Monte Carlo reference, (a - r)^2 - (b - r)^2
 * = (a - b)(a + b - 2 r), has the reference's zero-mean noise only in a term
 * of expectation 0, so its mean is unbiased for the difference of the
 * squared errors against the truth; the noise only widens the standard
 * error. Masks as in metrics/image_error.h. */
#ifndef GTLAB_METRICS_CLUSTER_MEAN_H
#define GTLAB_METRICS_CLUSTER_MEAN_H

#include <stddef.h>

#define CLUSTER_MEAN_SIDE 8 /* the block side of gtlab's studies, pixels */

typedef struct {
    double mean, se;
    size_t pixels; /* N */
    int blocks;    /* B */
} cluster_mean;

/* The mean of x over the mask with its block standard error (se = 0 with
 * fewer than two blocks). Returns 0, or -1 when no pixel is inside. */
int cluster_mean_compute(const float *x, const float *mask, int width, int height, int side, cluster_mean *out);

/* The mean over the mask of (a - r)^2 - (b - r)^2 with its block standard
 * error: negative when a is closer to r than b. Returns 0, or -1 when no
 * pixel is inside or out of memory. */
int cluster_mean_paired_sq_error(const float *a, const float *b, const float *r, const float *mask, int width,
                               int height, int side, cluster_mean *out);

/* A change between two images of the same quantity (a shortcut on against
 * off), over the mask with its block standard error: the mean of a - b, of
 * |a - b|,
 * and the fraction of pixels whose code in an 8-bit UNORM target differs
 * (code(x) = round(255 clamp(x, 0, 1)), the rounding of a GPU's float to
 * UNORM conversion). Return 0, or -1 when no pixel is inside or out of
 * memory. */
int cluster_mean_difference(const float *a, const float *b, const float *mask, int width, int height, int side,
                            cluster_mean *out);
int cluster_mean_abs_difference(const float *a, const float *b, const float *mask, int width, int height, int side,
                                cluster_mean *out);
int cluster_mean_code_changes(const float *a, const float *b, const float *mask, int width, int height, int side,
                              cluster_mean *out);
/* The 8-bit UNORM code of x. */
int unorm8_code(float x);

/* Block means of disjoint images pooled into one: the pixel-weighted mean,
 * and the standard error of independent parts combined,
 *     se^2 = sum_k (N_k se_k)^2 / (sum_k N_k)^2. */
cluster_mean cluster_mean_pool(const cluster_mean *parts, int count);

#endif
