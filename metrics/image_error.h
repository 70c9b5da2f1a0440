/* Pixelwise error statistics between two images of one quantity (RMSE, mean
 * and maximum absolute error).
 *
 * Masks: a pixel is inside a mask when mask[i] >= 0.5 (gtlab masks hold
 * exactly 0 or 1; the threshold gives other coverage masks the majority
 * rule); a NULL mask means every pixel. Only pixels inside the mask are
 * compared. */
#ifndef GTLAB_METRICS_IMAGE_ERROR_H
#define GTLAB_METRICS_IMAGE_ERROR_H

#include <stddef.h>

#include "core/error.h"
#include "core/image.h"

static inline int metrics_in_mask(const float *mask, size_t i) { return !mask || mask[i] >= 0.5f; }

typedef struct {
    size_t pixels;      /* pixels compared (inside the mask) */
    double rmse;        /* sqrt(mean (a - b)^2) */
    double mean_abs;    /* mean |a - b| */
    double max_abs;     /* max |a - b| */
    int max_x, max_y;   /* the first pixel in row-major order where max_abs occurs */
    double mean_a, mean_b;
} image_error_stats;

/* Statistics of a - b over the pixels of planes a and b (width*height floats,
 * row-major) inside `mask`, summed in double. Returns 0, or -1 with
 * e = "<what>: ..." when no pixel is inside the mask. */
int image_error_compute(const float *a, const float *b, const float *mask, int width, int height, const char *what,
                        image_error_stats *out, gt_error *e);

/* The p-th percentile, 0 < p <= 100, of the values inside the mask by the
 * nearest-rank rule: the ceil(p/100 * n)-th smallest of the n values (NaN
 * values, such as an SSIM map's border, are left out). Used to scale
 * heatmaps so a few outliers do not wash out the rest. Returns 0, or -1 with
 * e = "<what>: ..." (no value inside the mask, out of memory). */
int metrics_percentile(const float *values, const float *mask, size_t count, double p, const char *what,
                       float *out, gt_error *e);

#endif
