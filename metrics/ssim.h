/* SSIM and DSSIM exactly as Wang, Bovik, Sheikh and Simoncelli, "Image
 * quality assessment: from error visibility to structural similarity",
 * IEEE Transactions on Image Processing 13(4), 2004:
 *
 *   SSIM(x, y) = (2 mu_x mu_y + C1)(2 sigma_xy + C2)
 *              / ((mu_x^2 + mu_y^2 + C1)(sigma_x^2 + sigma_y^2 + C2)),
 *   C1 = (K1 L)^2, C2 = (K2 L)^2, K1 = 0.01, K2 = 0.03, L = 1,
 *
 * with the means, variances and covariance taken under an 11x11
 * circular-symmetric Gaussian window (sigma = 1.5, weights normalised to sum
 * 1; section III-C of the paper), the variances and covariance being the
 * population (biased) ones: sigma_x^2 = sum w (x - mu_x)^2. The map is
 * evaluated at every window centre whose window lies wholly inside the image
 * (the "valid" region: no padding), and the mean SSIM averages the map over
 * those centres. DSSIM = (1 - SSIM) / 2.
 *
 * L = 1 is the dynamic range of the quantities gtlab compares (visibilities,
 * occlusion, normalised radiance); values are not clamped, so HDR values
 * simply weigh C1 and C2 less. Not included: the automatic downsampling of
 * the authors' later MATLAB ssim.m (images over 256 pixels rescaled), which is
 * not part of the paper.
 *
 * Masks (same convention as metrics/image_error.h): a pixel is inside the
 * mask when mask[i] >= 0.5; a NULL mask means every pixel. The mask selects
 * which window CENTRES enter the mean; each window's statistics still use all
 * 121 pixels under it, inside the mask or not (masking inside the window
 * would no longer be Wang et al.'s SSIM). gtlab images hold 0 in background
 * pixels, so windows straddling a silhouette compare those zeros in both
 * images. A centre must be inside the mask AND in the valid region to count.
 *
 * Sums are accumulated in double in a fixed order per output row, so the
 * result does not depend on the number of OpenMP threads. Input values must
 * be finite (metrics_pair_init checks this for files).
 */
#ifndef GTLAB_METRICS_SSIM_H
#define GTLAB_METRICS_SSIM_H

#include <stddef.h>

#include "core/error.h"
#include "core/image.h"

#define SSIM_WINDOW 11 /* window side */
#define SSIM_RADIUS 5  /* (SSIM_WINDOW - 1) / 2 */
#define SSIM_SIGMA 1.5
#define SSIM_K1 0.01
#define SSIM_K2 0.03
#define SSIM_DYNAMIC_RANGE 1.0 /* L */

typedef struct {
    double ssim;    /* mean SSIM over the counted centres */
    double dssim;   /* (1 - ssim) / 2 */
    size_t centres; /* window centres averaged: valid and inside the mask */
} ssim_result;

/* The normalised 1-D Gaussian g[k] proportional to exp(-(k - 5)^2 / (2 sigma^2)),
 * summing to 1. The 2-D window is w(i, j) = g[i] g[j], which sums to 1 too. */
void ssim_gaussian_weights(double g[SSIM_WINDOW]);

/* Whether pixel (x, y) is a valid window centre: its window lies inside the image. */
static inline int ssim_centre_valid(int x, int y, int width, int height)
{
    return x >= SSIM_RADIUS && x < width - SSIM_RADIUS && y >= SSIM_RADIUS && y < height - SSIM_RADIUS;
}

/* Mean SSIM of planes a and b (width*height floats each, row-major) over the
 * valid centres inside `mask` (may be NULL). If `map` is non-NULL it receives
 * width*height floats: the SSIM at every valid centre (whether inside the mask
 * or not) and NaN at the other pixels. `what` names the comparison in errors.
 * Returns 0, or -1 with e: image smaller than 11x11, no valid centre inside
 * the mask, out of memory. */
int ssim_compute(const float *a, const float *b, const float *mask, int width, int height, const char *what,
                 float *map, ssim_result *out, gt_error *e);

/* The noise floor of a gtlab reference render (DESIGN.md): the SSIM/DSSIM
 * between the means of its even-index samples and of its odd-index samples,
 * for one Monte Carlo quantity `channel`, rebuilt from the accumulator
 * channels (core/statistics/mc_film.h). As in the written mean channel, pixels outside
 * the mask hold 0 in both halves; the mean runs over the same centres as
 * ssim_compute with that mask. `what` names the file. Returns 0, or -1 with e:
 * not a reference render, `channel` not one of its quantities, a pixel inside
 * the mask with no sample in one of the halves, or as ssim_compute. */
int ssim_noise_floor(const image *reference, const char *what, const char *channel, const float *mask,
                     ssim_result *out, gt_error *e);

#endif
