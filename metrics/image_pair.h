/* What every comparison of two gtlab EXR images sets up first: the channel
 * compared, the mask both images agree on (mask.A; see image_error.h for the
 * mask convention), and the checks that make the pair comparable (same size,
 * finite values). */
#ifndef GTLAB_METRICS_IMAGE_PAIR_H
#define GTLAB_METRICS_IMAGE_PAIR_H

#include "core/error.h"
#include "core/image.h"
#include "metrics/flip.h"
#include "metrics/image_error.h"
#include "metrics/ssim.h"

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

/* The figures of a comparison (what `gtlab compare` prints). */
typedef struct {
    image_error_stats error; /* RMSE, mean and max |A-B|, means (image_error.h) */
    ssim_result ssim;        /* SSIM and DSSIM of A against B (ssim.h) */
    flip_result flip;        /* mean FLIP of B with A the reference, over the mask (flip.h: flip_grey) */
    int has_floor_a, has_floor_b;
    ssim_result floor_a, floor_b; /* DSSIM of the even- against the odd-sample means */
} metrics_pair_figures;

/* Whether img is a gtlab reference render holding the accumulators of
 * `channel` (its CH_SUFFIX_SUM channel), so that its noise floor exists. */
int metrics_is_reference_of(const image *img, const char *channel);

/* The error statistics, the SSIM and the mean FLIP of the pair (a and b are the images the
 * pair was set up from); with `noise_floor`, the noise floor of a (which must
 * be a reference render) and of b when it is one. ssim_map, when not NULL,
 * receives the per-window SSIM (width x height; NaN where no window is
 * centred). Returns 0, or -1 with e set. */
int metrics_pair_measure(const metrics_pair *pair, const image *a, const char *what_a, const image *b,
                         const char *what_b, int noise_floor, float *ssim_map, metrics_pair_figures *out,
                         gt_error *e);

/* How an error heatmap's full scale was chosen. */
typedef enum {
    HEATMAP_SCALE_PERCENTILE, /* the requested percentile of the values inside */
    HEATMAP_SCALE_MAXIMUM,    /* that percentile is 0: the maximum */
    HEATMAP_SCALE_ARBITRARY   /* every value is 0: 1 */
} metrics_heatmap_scale;

/* An error heatmap's values, ready to colour: values and mask are owned,
 * width x height; values are 0 outside the mask. */
typedef struct {
    float *values, *mask;
    float vmax; /* the full scale */
    metrics_heatmap_scale scale;
} metrics_heatmap;

/* The heatmap of the pair: with ssim_map NULL, |A-B| inside the pair's mask;
 * else the per-window DSSIM (1 - SSIM) / 2 at the valid window centres
 * (non-NaN ssim_map) inside it. Full scale: the `percentile` percentile of
 * the values inside (metrics_percentile), else their maximum if that is 0,
 * else 1. Returns 0, or -1 with e naming `what`. */
int metrics_pair_heatmap(const metrics_pair *pair, const float *ssim_map, double percentile, const char *what,
                         metrics_heatmap *out, gt_error *e);
void metrics_heatmap_free(metrics_heatmap *h);

#endif
