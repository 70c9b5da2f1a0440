/* `gtlab check dither`: the moments of the quantisation error of each
 * dither kind (dither.h) at `signals` values across one LSB, by
 * Monte Carlo with `samples` draws each (floor quantiser), against the
 * laws of nonsubtractive dither: E[e] = 0; Var[e] = 1/4 (TPDF of 2 LSB) or
 * f (1 - f) (RPDF); the talk's (u0 + u1) / 2 has no signal-independent law
 * and is reported only. Deviations are in standard errors of the run. */
#ifndef GTLAB_DITHER_DITHER_CHECK_H
#define GTLAB_DITHER_DITHER_CHECK_H

#include <stdio.h>

#include "core/error.h"
#include "dither/dither.h"

typedef struct {
    dither_kind kind;
    int has_law;              /* 0: the talk's average, no law to meet */
    double worst_bias_se;     /* max over signals of |mean| / SE */
    double worst_variance_se; /* max over signals of |var - law| / SE */
    double worst_bias;        /* max |mean|, LSB */
    double min_variance, max_variance; /* over the signals, LSB^2 */
} dither_check_row;

enum { DITHER_CHECK_KINDS = 4 };

typedef struct {
    int signals, samples;
    dither_check_row rows[DITHER_CHECK_KINDS];
} dither_check_result;

/* Returns 0 or -1 with e (signals < 2 or samples < 100). */
int dither_check_run(int signals, int samples, unsigned seed, dither_check_result *out, gt_error *e);

/* The table `gtlab check dither` prints; returns 1 if a kind with a law is
 * off by more than 5 standard errors, else 0. */
int dither_check_print(const dither_check_result *r, FILE *out);

#endif
