/* The time of the joint multi-bounce fit (`gtlab bench fit`): a, b, c
 * linear in the albedo, 6 coefficients, solve and covariance through the
 * Ceres bridge on one thread, over N synthetic samples (7 albedos, V_d
 * spread evenly over (0, 1], V'_d the talk's curve plus uniform noise of
 * width 0.02), with one residual block per sample against blocks of
 * MBFIT_DEFAULT_BLOCK (fitters/ceres_bridge.h). */
#ifndef GTLAB_MULTIBOUNCE_MULTIBOUNCE_FIT_TIMING_H
#define GTLAB_MULTIBOUNCE_MULTIBOUNCE_FIT_TIMING_H

#include "core/error.h"

enum { MULTIBOUNCE_FIT_TIMINGS = 2 }; /* blocks of 1 sample, of MBFIT_DEFAULT_BLOCK */

typedef struct {
    int block_size;       /* residuals per Ceres block */
    double best_seconds;  /* the whole fit, best of the repeats */
    double solve_seconds; /* Ceres' own solve time (last repeat) */
    int iterations;
} multibounce_fit_timing;

/* Times the fit of `samples` synthetic samples, `repeats` times per block size. */
int multibounce_fit_timing_run(long samples, long repeats, multibounce_fit_timing out[MULTIBOUNCE_FIT_TIMINGS],
                               gt_error *e);

#endif
