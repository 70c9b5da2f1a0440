/* Pixelwise error statistics between two images of one quantity (RMSE, mean
 * and maximum absolute error), and what every comparison of two gtlab EXR
 * images sets up first: the channel compared, the mask both images agree on,
 * and the checks that make the pair comparable (same size, finite values).
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

/* The mask channel of gtlab images (DESIGN.md: 1 where a surface was hit). */
#define METRICS_MASK_CHANNEL "mask.A"

/* Channels compared when none is named, in order of preference; NULL-terminated. */
extern const char *const metrics_default_channels[];

/* One channel of two images, ready to compare. */
typedef struct {
    char channel[IMAGE_NAME_MAX];
    int width, height;
    const float *a, *b; /* the channel's planes, owned by the images */
    float *mask;        /* owned: 1 where both images' mask.A is inside (an image
                           without mask.A counts as all inside), else 0 */
} metrics_pair;

/* Sets up the comparison of image a (named what_a in errors, usually its
 * path) with image b. `channel` NULL chooses the first of
 * metrics_default_channels present in both. Returns 0, or -1 with e naming
 * the file at fault: sizes differ; the channel is missing (the message lists
 * the file's channels); a value of the channel is NaN or infinite (every
 * pixel is checked, since SSIM windows reach outside the mask); out of memory.
 * On failure nothing needs freeing. */
int metrics_pair_init(metrics_pair *pair, const image *a, const char *what_a, const image *b, const char *what_b,
                      const char *channel, gt_error *e);
void metrics_pair_free(metrics_pair *pair);

#endif
