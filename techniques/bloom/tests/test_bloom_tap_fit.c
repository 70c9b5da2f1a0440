/* The 13 -> 9 bilinear bloom tap refit (bloom/bloom_tap_fit.c,
 * bloom/bloom_downsample.c):
 *  - Jimenez's 13 taps reproduce the talk's table of texel weights x 128
 *    (integers 1, 1, 2, ... 8) exactly, and the weights sum to 1 at any phase;
 *  - the fitted kernels reproduce their own weights when convolved as
 *    bilinear fetches: a source image holding one 1 at each texel in turn,
 *    downsampled by bloom_downsample at exact half resolution (a floor-based
 *    bilinear sampler, not the tent products the fit uses), gives the fit's
 *    texel weight at the output pixel, for both targets;
 *  - (a) the 13-tap target: the fit's worst error equals the least-squares
 *    optimum of the corner block alone, found independently by a scan of the
 *    bilinear fraction with the weight in closed form (the blocks are
 *    disjoint, so the 27-parameter problem separates); edge and centre
 *    blocks exact; no parameter on its bound; the same with the weights
 *    held at the block sums (total 1);
 *  - (b) a Gaussian target (sigma 1.3, sampled at the texel centres,
 *    normalised) is separable, so rank one per block: met to 1e-9. */
#include <math.h>
#include <string.h>

#include "bloom/bloom_tap_fit.h"
#include "tests/check.h"

enum { SRC = 16, DST = 8 };

static void check_jimenez_table(void)
{
    static const int table[3][6] = {{1, 1, 2, 2, 1, 1}, {1, 5, 6, 6, 5, 1}, {2, 6, 8, 8, 6, 2}};
    bloom_tap taps[BLOOM_JIMENEZ_TAPS];
    double w[BLOOM_FOOTPRINT][BLOOM_FOOTPRINT], grid[BLOOM_GRID][BLOOM_GRID];
    bloom_jimenez13(taps);
    bloom_footprint_weights(taps, BLOOM_JIMENEZ_TAPS, w);
    for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 6; ++i)
            CHECK(w[j][i] * 128.0 == table[j < 3 ? j : 5 - j][i]);
    for (double p = 0.0; p < 1.0; p += 0.37) {
        double sum = 0.0;
        bloom_texel_weights(taps, BLOOM_JIMENEZ_TAPS, p, 1.0 - p, grid);
        for (int j = 0; j < BLOOM_GRID; ++j)
            for (int i = 0; i < BLOOM_GRID; ++i)
                sum += grid[j][i];
        CHECK_NEAR(sum, 1.0, 1e-12);
    }
}

/* Output pixel (4, 4) of a 16^2 -> 8^2 downsample sits at (9, 9): texel
 * (9 - 3 + i, 9 - 3 + j) is footprint texel (i, j). */
static void check_reproduces_own_weights(const bloom_fit_result *fit)
{
    static float src[SRC * SRC], dst[DST * DST];
    double w[BLOOM_FOOTPRINT][BLOOM_FOOTPRINT];
    bloom_footprint_weights(fit->taps, BLOOM_FIT_TAPS, w);
    for (int j = 0; j < BLOOM_FOOTPRINT; ++j)
        for (int i = 0; i < BLOOM_FOOTPRINT; ++i) {
            memset(src, 0, sizeof src);
            src[(6 + j) * SRC + 6 + i] = 1.0f;
            bloom_downsample(src, SRC, SRC, dst, DST, DST, fit->taps, BLOOM_FIT_TAPS);
            CHECK_NEAR(dst[4 * DST + 4], w[j][i], 1e-6);
        }
}

/* Least squares of the corner block [[1, 1], [1, 5]] / 128 by one rank-one
 * tap, its weight free (held < 0) or held at `held`. */
static double corner_block_worst(double held)
{
    static const double t[4] = {1.0 / 128, 1.0 / 128, 1.0 / 128, 5.0 / 128};
    double best = INFINITY, worst = 0.0;
    for (int s = 1; s < 200000; ++s) {
        double a = s / 200000.0, v[4] = {(1 - a) * (1 - a), a * (1 - a), a * (1 - a), a * a}, vt = 0, vv = 0, c = 0;
        for (int k = 0; k < 4; ++k)
            vt += v[k] * t[k], vv += v[k] * v[k];
        double w = held < 0 ? vt / vv : held, m = 0;
        for (int k = 0; k < 4; ++k)
            c += (w * v[k] - t[k]) * (w * v[k] - t[k]), m = fmax(m, fabs(w * v[k] - t[k]));
        if (c < best)
            best = c, worst = m;
    }
    return worst;
}

static void gaussian_target(double sigma, double target[BLOOM_FOOTPRINT][BLOOM_FOOTPRINT])
{
    double g[BLOOM_FOOTPRINT], sum = 0.0;
    for (int i = 0; i < BLOOM_FOOTPRINT; ++i)
        sum += g[i] = exp(-0.5 * (i - 2.5) * (i - 2.5) / (sigma * sigma));
    for (int j = 0; j < BLOOM_FOOTPRINT; ++j)
        for (int i = 0; i < BLOOM_FOOTPRINT; ++i)
            target[j][i] = g[i] * g[j] / (sum * sum);
}

int main(void)
{
    check_jimenez_table();
    double target[BLOOM_FOOTPRINT][BLOOM_FOOTPRINT];
    bloom_tap taps[BLOOM_JIMENEZ_TAPS];
    bloom_fit_result fit;
    gt_error e;
    bloom_jimenez13(taps);
    bloom_footprint_weights(taps, BLOOM_JIMENEZ_TAPS, target);
    CHECK(bloom_fit_9tap(target, 0, &fit, &e) == 0);
    check_reproduces_own_weights(&fit);
    CHECK_NEAR(fit.worst_error, corner_block_worst(-1.0), 1e-7);
    CHECK_MSG(fit.at_bound == 0, "on bounds: %s", fit.bound_names);
    CHECK_NEAR(fit.taps[1].x, 0.0, 1e-6); /* the top tap: between the two middle columns */
    CHECK(bloom_fit_9tap(target, 1, &fit, &e) == 0); /* weights held at the block sums: the total stays 1 */
    check_reproduces_own_weights(&fit);
    CHECK_NEAR(fit.worst_error, corner_block_worst(8.0 / 128), 1e-7);
    double total = 0.0;
    for (int k = 0; k < BLOOM_FIT_TAPS; ++k)
        total += fit.taps[k].w;
    CHECK_NEAR(total, 1.0, 1e-12);
    gaussian_target(1.3, target);
    CHECK(bloom_fit_9tap(target, 0, &fit, &e) == 0);
    check_reproduces_own_weights(&fit);
    CHECK_MSG(fit.worst_error < 1e-9, "gaussian worst %g", fit.worst_error);
    CHECK_MSG(fit.at_bound == 0, "on bounds: %s", fit.bound_names);
    return check_report("test_bloom_tap_fit");
}
