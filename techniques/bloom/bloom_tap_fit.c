/* The 9-tap bilinear bloom refit: see bloom_tap_fit.h. */
#include "bloom/bloom_tap_fit.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fitters/ceres_bridge.h"

enum { PARAMS = 3 * BLOOM_FIT_TAPS, RESIDUALS = BLOOM_FOOTPRINT * BLOOM_FOOTPRINT };

void bloom_footprint_weights(const bloom_tap *taps, int count, double out[BLOOM_FOOTPRINT][BLOOM_FOOTPRINT])
{
    double grid[BLOOM_GRID][BLOOM_GRID];
    bloom_texel_weights(taps, count, 0.0, 0.0, grid);
    for (int j = 0; j < BLOOM_FOOTPRINT; ++j)
        for (int i = 0; i < BLOOM_FOOTPRINT; ++i)
            out[j][i] = grid[j + 1][i + 1];
}

static void unpack(const double *p, bloom_tap taps[BLOOM_FIT_TAPS])
{
    for (int k = 0; k < BLOOM_FIT_TAPS; ++k)
        taps[k] = (bloom_tap){p[3 * k], p[3 * k + 1], p[3 * k + 2]};
}

static int residuals(void *user, const double *p, double *r, double *jacobian)
{
    const double(*target)[BLOOM_FOOTPRINT] = user;
    bloom_tap taps[BLOOM_FIT_TAPS];
    double w[BLOOM_FOOTPRINT][BLOOM_FOOTPRINT];
    (void)jacobian;
    unpack(p, taps);
    bloom_footprint_weights(taps, BLOOM_FIT_TAPS, w);
    for (int j = 0; j < BLOOM_FOOTPRINT; ++j)
        for (int i = 0; i < BLOOM_FOOTPRINT; ++i)
            r[j * BLOOM_FOOTPRINT + i] = w[j][i] - target[j][i];
    return 0;
}

/* Start: block centres, the target's block sums; bounds: the blocks. */
static int set_up(gt_fit *fit, double *p, const double target[BLOOM_FOOTPRINT][BLOOM_FOOTPRINT], int hold,
                  gt_error *e)
{
    for (int k = 0; k < BLOOM_FIT_TAPS; ++k) {
        double bx, by, sum = 0.0;
        bloom_block_centre(k, &bx, &by);
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i)
                sum += target[2 * (k / 3) + j][2 * (k % 3) + i];
        p[3 * k] = bx, p[3 * k + 1] = by, p[3 * k + 2] = sum;
        if (gt_fit_set_bounds(fit, 3 * k, bx - 0.5, bx + 0.5, e) != 0 ||
            gt_fit_set_bounds(fit, 3 * k + 1, by - 0.5, by + 0.5, e) != 0 || gt_fit_hold(fit, 3 * k + 2, hold, e) != 0)
            return -1;
    }
    gt_fit_block_options numeric = {GT_FIT_NUMERIC, GT_FIT_LOSS_NONE, 0.0};
    return gt_fit_add_block(fit, RESIDUALS, residuals, (void *)target, &numeric, e);
}

static void note_bounds(const double *p, bloom_fit_result *out)
{
    out->at_bound = 0;
    out->bound_names[0] = '\0';
    for (int k = 0; k < BLOOM_FIT_TAPS; ++k)
        for (int a = 0; a < 2; ++a) {
            double bx, by;
            bloom_block_centre(k, &bx, &by);
            if (fabs(fabs(p[3 * k + a] - (a ? by : bx)) - 0.5) < 1e-9) {
                size_t len = strlen(out->bound_names);
                snprintf(out->bound_names + len, sizeof out->bound_names - len, "%s%c%d", len ? " " : "", a ? 'y' : 'x', k);
                ++out->at_bound;
            }
        }
}

int bloom_fit_9tap(const double target[BLOOM_FOOTPRINT][BLOOM_FOOTPRINT], int hold_weights, bloom_fit_result *out,
                   gt_error *e)
{
    double p[PARAMS], r[RESIDUALS];
    memset(out, 0, sizeof *out);
    gt_fit *fit = gt_fit_create(PARAMS, p, e);
    if (!fit)
        return -1;
    gt_fit_result fr;
    int rc = set_up(fit, p, target, hold_weights, e) == 0 && gt_fit_solve(fit, NULL, &fr, e) == 0 ? 0 : -1;
    gt_fit_destroy(fit);
    if (rc != 0)
        return -1;
    unpack(p, out->taps);
    residuals((void *)target, p, r, NULL);
    for (int i = 0; i < RESIDUALS; ++i) {
        out->worst_error = fmax(out->worst_error, fabs(r[i]));
        out->rms_error += r[i] * r[i] / RESIDUALS;
    }
    out->rms_error = sqrt(out->rms_error);
    out->iterations = fr.iterations, out->converged = fr.success;
    note_bounds(p, out);
    return 0;
}
