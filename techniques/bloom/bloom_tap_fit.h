/* The 9-tap bilinear refit of a bloom downsampling kernel (INSIDE, Gjoel
 * GDC 2016: "fitting the samplepoint to utilise bilinear filtering to only
 * sample each texel once"), by Ceres (fitters/ceres_bridge.h).
 *
 * Parameters: the 27 numbers (x_k, y_k, w_k) of the taps of
 * bloom_downsample.h's 3 x 3 layout, each position bounded to its
 * 2 x 2 block (|x_k - X_k| <= 1/2, |y_k - Y_k| <= 1/2: each texel read once);
 * weights free. Residuals: the 36 texel weights of the footprint at half
 * resolution (bloom_texel_weights at phase 0) minus the target's, least
 * squares. Start: taps at the block centres with the target's block sums.
 * A parameter ending on its bound is counted and named in the result: a fit
 * there is constrained by the layout, not by the target. */
#ifndef GTLAB_BLOOM_BLOOM_TAP_FIT_H
#define GTLAB_BLOOM_BLOOM_TAP_FIT_H

#include "bloom/bloom_downsample.h"
#include "core/error.h"

typedef struct {
    bloom_tap taps[BLOOM_FIT_TAPS];
    double worst_error, rms_error; /* over the 36 texel weights */
    int iterations, converged;
    int at_bound;                  /* parameters on a bound */
    char bound_names[128];         /* "x3 y3 ..." or "" */
} bloom_fit_result;

/* target[j][i]: the 6 x 6 texel weights (texel centres at (i - 5/2, j - 5/2)).
 * hold_weights != 0 keeps each tap's weight at its block's target sum (the
 * kernel keeps the target's total, and each block's): positions only. */
int bloom_fit_9tap(const double target[BLOOM_FOOTPRINT][BLOOM_FOOTPRINT], int hold_weights, bloom_fit_result *out,
                   gt_error *e);

/* The 36 texel weights of the taps at half resolution (the grid's inner 6 x 6). */
void bloom_footprint_weights(const bloom_tap *taps, int count, double out[BLOOM_FOOTPRINT][BLOOM_FOOTPRINT]);

#endif
