/* The Ceres bridge against least-squares theory: fits of synthetic data with
 * Gaussian noise of known sigma recover the true coefficients within their
 * reported standard errors, and those standard errors equal the textbook
 * sigma * sqrt(diag((J^T J)^-1)) computed here independently of Ceres.
 * Also: analytic and numeric Jacobians agree, bounds and held parameters
 * behave as the constrained least-squares solutions computed here, robust
 * losses resist outliers, and a nonlinear model converges from a rough
 * start. */
#include "fitters/ceres_bridge.h"
#include "tests/check.h"

#include <stdint.h>
#include <string.h>

/* The cubic of the GTAO multi-bounce fit, y = ((a x + b) x + c) x, with the
 * talk's coefficients at albedo 0.5. */
static const double kTruth[3] = {2.0404 * 0.5 - 0.3324, -4.7951 * 0.5 + 0.6417, 2.7552 * 0.5 + 0.6903};
static const double kSigma = 0.01;

#include "tests/test_noise.h"

/* ---- the cubic model as residual blocks of one sample ---- */

typedef struct {
    double x, y, w; /* residual = w * (model(x) - y) */
} sample;

static double cubic(const double *p, double x) { return ((p[0] * x + p[1]) * x + p[2]) * x; }

static int cubic_residual(void *user, const double *p, double *r, double *jacobian)
{
    const sample *s = user;
    r[0] = s->w * (cubic(p, s->x) - s->y);
    if (jacobian) {
        jacobian[0] = s->w * s->x * s->x * s->x;
        jacobian[1] = s->w * s->x * s->x;
        jacobian[2] = s->w * s->x;
    }
    return 0;
}

/* n samples at x evenly spread over (0, 1], y = truth + sigma * N(0, 1). */
static sample *cubic_samples(size_t n, uint64_t seed, double w)
{
    sample *s = malloc(n * sizeof *s);
    for (size_t i = 0; i < n; ++i) {
        s[i].x = (i + 1.0) / (double)n;
        s[i].y = cubic(kTruth, s[i].x) + kSigma * gaussian(seed, i);
        s[i].w = w;
    }
    return s;
}

/* ---- independent least squares for a model linear in its parameters ---- */

/* The 3x3 inverse by cofactors; returns the determinant. */
static double invert3(const double m[9], double inv[9])
{
    inv[0] = m[4] * m[8] - m[5] * m[7];
    inv[1] = m[2] * m[7] - m[1] * m[8];
    inv[2] = m[1] * m[5] - m[2] * m[4];
    inv[3] = m[5] * m[6] - m[3] * m[8];
    inv[4] = m[0] * m[8] - m[2] * m[6];
    inv[5] = m[2] * m[3] - m[0] * m[5];
    inv[6] = m[3] * m[7] - m[4] * m[6];
    inv[7] = m[1] * m[6] - m[0] * m[7];
    inv[8] = m[0] * m[4] - m[1] * m[3];
    double det = m[0] * inv[0] + m[1] * inv[3] + m[2] * inv[6];
    for (int i = 0; i < 9; ++i)
        inv[i] /= det;
    return det;
}

/* (J^T J)^-1 of the cubic's (weighted) Jacobian. */
static void cubic_normal_inverse(const sample *s, size_t n, double inv[9])
{
    double jtj[9] = {0};
    for (size_t k = 0; k < n; ++k) {
        double x = s[k].x, w = s[k].w;
        double row[3] = {w * x * x * x, w * x * x, w * x};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                jtj[3 * i + j] += row[i] * row[j];
    }
    invert3(jtj, inv);
}

/* The least-squares fit of the cubic with parameter `fixed` held at `value`,
 * from the 2x2 normal equations of the other two. */
static void cubic_fit_with_fixed(const sample *s, size_t n, int fixed, double value, double p[3])
{
    int f[2], k = 0;
    for (int i = 0; i < 3; ++i)
        if (i != fixed)
            f[k++] = i;
    double a00 = 0, a01 = 0, a11 = 0, b0 = 0, b1 = 0;
    for (size_t i = 0; i < n; ++i) {
        double x = s[i].x;
        double basis[3] = {x * x * x, x * x, x};
        double target = s[i].y - value * basis[fixed];
        a00 += basis[f[0]] * basis[f[0]];
        a01 += basis[f[0]] * basis[f[1]];
        a11 += basis[f[1]] * basis[f[1]];
        b0 += basis[f[0]] * target;
        b1 += basis[f[1]] * target;
    }
    double det = a00 * a11 - a01 * a01;
    p[f[0]] = (a11 * b0 - a01 * b1) / det;
    p[f[1]] = (a00 * b1 - a01 * b0) / det;
    p[fixed] = value;
}

/* ---- fitting through the bridge ---- */

typedef struct {
    int hold;                 /* index of a held parameter, or -1 */
    int bound;                /* index of a bounded parameter, or -1 */
    double lower, upper;
    gt_fit_block_options block;
    const gt_fit_options *solver; /* NULL: defaults */
} cubic_setup;

static const cubic_setup kPlain = {-1, -1, 0, 0, {GT_FIT_ANALYTIC, GT_FIT_LOSS_NONE, 0}, NULL};

typedef struct {
    double p[3], se[3], cov[9], variance;
    gt_fit_result result;
} cubic_outcome;

/* Fits the cubic to s from the start (1, -1, 1); 0 on success. */
static int fit_cubic(sample *s, size_t n, const cubic_setup *setup, cubic_outcome *out)
{
    gt_error e = {{0}};
    memset(out, 0, sizeof *out);
    out->p[0] = 1.0;
    out->p[1] = setup->hold == 1 ? 0.0 : -1.0;
    out->p[2] = 1.0;
    gt_fit *fit = gt_fit_create(3, out->p, &e);
    int status = fit ? 0 : -1;
    for (size_t i = 0; i < n && status == 0; ++i)
        status = gt_fit_add_block(fit, 1, cubic_residual, &s[i], &setup->block, &e);
    if (status == 0 && setup->hold >= 0)
        status = gt_fit_hold(fit, setup->hold, 1, &e);
    if (status == 0 && setup->bound >= 0)
        status = gt_fit_set_bounds(fit, setup->bound, setup->lower, setup->upper, &e);
    if (status == 0)
        status = gt_fit_solve(fit, setup->solver, &out->result, &e);
    if (status == 0)
        status = gt_fit_covariance(fit, out->cov, out->se, &out->variance, &e);
    if (status != 0)
        fprintf(stderr, "fit failed: %s\n", e.message);
    gt_fit_destroy(fit);
    return status;
}

static double relative_difference(double a, double b) { return fabs(a - b) / fmax(fabs(a), fabs(b)); }

/* ---- the tests ---- */

static void test_recovers_truth_with_textbook_standard_errors(void)
{
    const size_t n = 2000;
    sample *s = cubic_samples(n, 1, 1.0);
    cubic_outcome o;
    CHECK(fit_cubic(s, n, &kPlain, &o) == 0);
    CHECK(o.result.success);
    CHECK(o.result.residual_count == n);
    CHECK(o.result.free_parameter_count == 3);

    /* The estimates, within 3 of their own standard errors of the truth. */
    for (int i = 0; i < 3; ++i)
        CHECK_MSG(fabs(o.p[i] - kTruth[i]) < 3.0 * o.se[i], "p[%d] = %.6f, truth %.6f, se %.6f", i, o.p[i],
                  kTruth[i], o.se[i]);

    /* The estimates are the least-squares solution: the normal equations,
     * solved here, give the same coefficients (to a small fraction of the
     * standard error: the solver stops at the default tolerances). */
    double inv[9], jty[3] = {0}, ls[3] = {0};
    cubic_normal_inverse(s, n, inv);
    for (size_t k = 0; k < n; ++k) {
        double x = s[k].x;
        jty[0] += x * x * x * s[k].y;
        jty[1] += x * x * s[k].y;
        jty[2] += x * s[k].y;
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            ls[i] += inv[3 * i + j] * jty[j];
    for (int i = 0; i < 3; ++i)
        CHECK_NEAR(o.p[i], ls[i], 1e-3 * o.se[i]);

    /* The standard errors, against the theory with the true sigma: equal up
     * to the sampling error of the variance estimate (~1.6% at n = 2000). */
    for (int i = 0; i < 3; ++i) {
        double theory = kSigma * sqrt(inv[4 * i]);
        CHECK_MSG(relative_difference(o.se[i], theory) < 0.05, "se[%d] = %.6g, theory %.6g", i, o.se[i], theory);
    }

    /* ... and exactly sigma_hat^2 (J^T J)^-1 with the variance estimated here
     * from the residuals at the solution: sum r^2 / (n - 3). */
    double ss = 0.0, max_abs = 0.0;
    for (size_t k = 0; k < n; ++k) {
        double r = cubic(o.p, s[k].x) - s[k].y;
        ss += r * r;
        max_abs = fmax(max_abs, fabs(r));
    }
    double variance = ss / (double)(n - 3);
    CHECK(relative_difference(o.variance, variance) < 1e-9);
    for (int i = 0; i < 9; ++i) {
        double scale = sqrt(o.cov[4 * (i / 3)] * o.cov[4 * (i % 3)]);
        CHECK_NEAR(o.cov[i] / scale, variance * inv[i] / scale, 1e-6);
    }
    CHECK(relative_difference(o.result.rmse, sqrt(ss / (double)n)) < 1e-9);
    CHECK(relative_difference(o.result.max_abs_residual, max_abs) < 1e-9);
    CHECK(relative_difference(o.result.final_cost, 0.5 * ss) < 1e-9);
    free(s);
}

/* Weighting every residual by the same w rescales the noise estimate by w^2
 * and J^T J by w^2: the standard errors must not change. */
static void test_standard_errors_ignore_residual_scale(void)
{
    const size_t n = 1000;
    const double weights[2] = {1e-3, 1e3};
    sample *s = cubic_samples(n, 2, 1.0);
    cubic_outcome unit, scaled;
    CHECK(fit_cubic(s, n, &kPlain, &unit) == 0);
    for (int k = 0; k < 2; ++k) {
        for (size_t i = 0; i < n; ++i)
            s[i].w = weights[k];
        CHECK(fit_cubic(s, n, &kPlain, &scaled) == 0);
        for (int i = 0; i < 3; ++i) {
            CHECK_NEAR(scaled.p[i], unit.p[i], 1e-3 * unit.se[i]);
            CHECK_MSG(relative_difference(scaled.se[i], unit.se[i]) < 1e-6, "w = %g: se[%d] %.9g vs %.9g",
                      weights[k], i, scaled.se[i], unit.se[i]);
        }
        CHECK(relative_difference(scaled.variance, unit.variance * weights[k] * weights[k]) < 1e-6);
    }
    free(s);
}

/* Four times the samples over the same range: standard errors halve. */
static void test_standard_errors_shrink_as_one_over_sqrt_n(void)
{
    const size_t n = 1000;
    sample *small = cubic_samples(n, 3, 1.0);
    sample *large = cubic_samples(4 * n, 4, 1.0);
    cubic_outcome a, b;
    CHECK(fit_cubic(small, n, &kPlain, &a) == 0);
    CHECK(fit_cubic(large, 4 * n, &kPlain, &b) == 0);
    for (int i = 0; i < 3; ++i) {
        double ratio = a.se[i] / b.se[i];
        CHECK_MSG(fabs(ratio - 2.0) < 0.2, "se[%d] ratio %.4f for 4x the samples", i, ratio);
    }
    free(small);
    free(large);
}

static void test_numeric_and_analytic_jacobians_agree_on_the_cubic(void)
{
    const size_t n = 500;
    sample *s = cubic_samples(n, 5, 1.0);
    gt_fit_options tight = gt_fit_default_options();
    tight.function_tolerance = 1e-15;
    tight.gradient_tolerance = 1e-15;
    tight.parameter_tolerance = 1e-15;
    cubic_setup analytic = kPlain, numeric = kPlain;
    analytic.solver = numeric.solver = &tight;
    numeric.block.derivatives = GT_FIT_NUMERIC;
    cubic_outcome a, b;
    CHECK(fit_cubic(s, n, &analytic, &a) == 0);
    CHECK(fit_cubic(s, n, &numeric, &b) == 0);
    for (int i = 0; i < 3; ++i) {
        CHECK_MSG(relative_difference(a.p[i], b.p[i]) < 1e-8, "p[%d]: %.15g vs %.15g", i, a.p[i], b.p[i]);
        CHECK_MSG(relative_difference(a.se[i], b.se[i]) < 1e-6, "se[%d]: %.15g vs %.15g", i, a.se[i], b.se[i]);
    }
    free(s);
}

/* Holding b at 0: b does not move, has no variance, and a and c are the
 * least-squares fit of the other two alone. */
static void test_held_parameter(void)
{
    const size_t n = 1000;
    sample *s = cubic_samples(n, 6, 1.0);
    cubic_setup held = kPlain;
    held.hold = 1;
    cubic_outcome o;
    CHECK(fit_cubic(s, n, &held, &o) == 0);
    CHECK(o.p[1] == 0.0);
    CHECK(o.se[1] == 0.0);
    CHECK(o.result.free_parameter_count == 2);
    for (int i = 0; i < 3; ++i)
        CHECK(o.cov[3 * 1 + i] == 0.0 && o.cov[3 * i + 1] == 0.0);
    CHECK(o.se[0] > 0.0 && o.se[2] > 0.0);
    double ls[3];
    cubic_fit_with_fixed(s, n, 1, 0.0, ls);
    CHECK_NEAR(o.p[0], ls[0], 1e-3 * o.se[0]);
    CHECK_NEAR(o.p[2], ls[2], 1e-3 * o.se[2]);
    free(s);
}

/* A bound the unconstrained optimum violates: the fit ends exactly on it,
 * and the other parameters are the least-squares fit with that one fixed
 * there (the solution of the constrained problem, as the bound is active). */
static void test_bounds(void)
{
    const size_t n = 1000;
    sample *s = cubic_samples(n, 7, 1.0);
    struct {
        int index;
        double lower, upper;
    } cases[2] = {{2, -INFINITY, 1.5}, {0, 1.0, INFINITY}};
    for (int k = 0; k < 2; ++k) {
        cubic_setup bounded = kPlain;
        bounded.bound = cases[k].index;
        bounded.lower = cases[k].lower;
        bounded.upper = cases[k].upper;
        cubic_outcome o;
        CHECK(fit_cubic(s, n, &bounded, &o) == 0);
        double edge = isinf(cases[k].upper) ? cases[k].lower : cases[k].upper;
        CHECK_MSG(o.p[cases[k].index] == edge, "p[%d] = %.17g, bound %g", cases[k].index, o.p[cases[k].index],
                  edge);
        double ls[3];
        cubic_fit_with_fixed(s, n, cases[k].index, edge, ls);
        for (int i = 0; i < 3; ++i)
            CHECK_MSG(fabs(o.p[i] - ls[i]) <= 1e-3 * o.se[i], "bound case %d: p[%d] = %.9g, expected %.9g", k, i,
                      o.p[i], ls[i]);
    }
    free(s);
}

/* 5% of the samples displaced by gross errors (+0.2 to +0.5, twenty to fifty
 * sigma, all upwards so they bias a plain fit). */
static void test_robust_losses_resist_outliers(void)
{
    const size_t n = 2000;
    sample *s = cubic_samples(n, 8, 1.0);
    for (size_t i = 0; i < n; ++i)
        if (uniform01(0xBAD0000ull + i) < 0.05)
            s[i].y += 0.2 + 0.3 * uniform01(0xBAD1000000ull + i);
    const gt_fit_loss losses[3] = {GT_FIT_LOSS_NONE, GT_FIT_LOSS_HUBER, GT_FIT_LOSS_CAUCHY};
    const char *names[3] = {"none", "huber", "cauchy"};
    double worst[3];
    for (int k = 0; k < 3; ++k) {
        cubic_setup robust = kPlain;
        robust.block.loss = losses[k];
        robust.block.loss_scale = 3.0 * kSigma;
        cubic_outcome o;
        CHECK(fit_cubic(s, n, &robust, &o) == 0);
        worst[k] = 0.0;
        double z = 0.0;
        for (int i = 0; i < 3; ++i) {
            worst[k] = fmax(worst[k], fabs(o.p[i] - kTruth[i]) / fabs(kTruth[i]));
            z = fmax(z, fabs(o.p[i] - kTruth[i]) / o.se[i]);
        }
        printf("loss %-6s: largest relative coefficient error %.4f, %.2f standard errors\n", names[k], worst[k], z);
        if (losses[k] == GT_FIT_LOSS_CAUCHY)
            CHECK(z < 3.0); /* unbiased by the outliers, within its own error */
    }
    CHECK(worst[0] > 0.05);            /* the outliers do spoil a plain fit */
    CHECK(worst[1] < 0.25 * worst[0]); /* Huber: at least 4x better */
    CHECK(worst[2] < 0.1 * worst[0]);  /* Cauchy, redescending: at least 10x better */
    free(s);
}

/* ---- a nonlinear model: y = A exp(-k x) ---- */

static const double kExpTruth[2] = {2.0, 3.0};

static int exp_residual(void *user, const double *p, double *r, double *jacobian)
{
    const sample *s = user;
    double e = exp(-p[1] * s->x);
    r[0] = p[0] * e - s->y;
    if (jacobian) {
        jacobian[0] = e;
        jacobian[1] = -p[0] * s->x * e;
    }
    return 0;
}

static int fit_exp(const sample *s, size_t n, gt_fit_derivatives d, double p[2], double se[2], double *variance)
{
    gt_error e = {{0}};
    p[0] = 0.5; /* a rough start: A off by 4x, k by 6x */
    p[1] = 0.5;
    gt_fit_block_options bo = {d, GT_FIT_LOSS_NONE, 0.0};
    gt_fit *fit = gt_fit_create(2, p, &e);
    int status = fit ? 0 : -1;
    for (size_t i = 0; i < n && status == 0; ++i)
        status = gt_fit_add_block(fit, 1, exp_residual, (void *)&s[i], &bo, &e);
    gt_fit_result result;
    if (status == 0)
        status = gt_fit_solve(fit, NULL, &result, &e);
    if (status == 0 && !result.success)
        status = gt_error_set(&e, "test", "no convergence: %s", result.message);
    if (status == 0)
        status = gt_fit_covariance(fit, NULL, se, variance, &e);
    if (status != 0)
        fprintf(stderr, "exp fit failed: %s\n", e.message);
    gt_fit_destroy(fit);
    return status;
}

/* sqrt(diag((J^T J)^-1)) of the exponential model at p. */
static void exp_unit_standard_errors(const sample *s, size_t n, const double p[2], double out[2])
{
    double a = 0, b = 0, c = 0;
    for (size_t i = 0; i < n; ++i) {
        double j0 = exp(-p[1] * s[i].x), j1 = -p[0] * s[i].x * j0;
        a += j0 * j0;
        b += j0 * j1;
        c += j1 * j1;
    }
    double det = a * c - b * b;
    out[0] = sqrt(c / det);
    out[1] = sqrt(a / det);
}

static void test_nonlinear_model_converges_from_a_rough_start(void)
{
    const size_t n = 2000;
    sample *s = malloc(n * sizeof *s);
    for (size_t i = 0; i < n; ++i) {
        s[i].x = 2.0 * (i + 0.5) / (double)n;
        s[i].y = kExpTruth[0] * exp(-kExpTruth[1] * s[i].x) + kSigma * gaussian(9, i);
        s[i].w = 1.0;
    }
    double pa[2], sa[2], va, pn[2], sn[2], vn;
    CHECK(fit_exp(s, n, GT_FIT_ANALYTIC, pa, sa, &va) == 0);
    CHECK(fit_exp(s, n, GT_FIT_NUMERIC, pn, sn, &vn) == 0);
    double at_truth[2], at_estimate[2];
    exp_unit_standard_errors(s, n, kExpTruth, at_truth);
    exp_unit_standard_errors(s, n, pa, at_estimate);
    for (int i = 0; i < 2; ++i) {
        CHECK_MSG(fabs(pa[i] - kExpTruth[i]) < 3.0 * sa[i], "p[%d] = %.6f, truth %g, se %.3g", i, pa[i],
                  kExpTruth[i], sa[i]);
        /* The linearised theory with the true sigma at the truth... */
        CHECK_MSG(relative_difference(sa[i], kSigma * at_truth[i]) < 0.05, "se[%d] = %.6g, theory %.6g", i, sa[i],
                  kSigma * at_truth[i]);
        /* ... and exactly, with the estimated sigma at the estimate. */
        CHECK(relative_difference(sa[i], sqrt(va) * at_estimate[i]) < 1e-6);
        /* Ceres' central differences reach the same optimum. */
        CHECK_MSG(relative_difference(pa[i], pn[i]) < 1e-8, "analytic %.15g vs numeric %.15g", pa[i], pn[i]);
        CHECK(relative_difference(sa[i], sn[i]) < 1e-6);
    }
    free(s);
}

int main(void)
{
    test_recovers_truth_with_textbook_standard_errors();
    test_standard_errors_ignore_residual_scale();
    test_standard_errors_shrink_as_one_over_sqrt_n();
    test_numeric_and_analytic_jacobians_agree_on_the_cubic();
    test_held_parameter();
    test_bounds();
    test_robust_losses_resist_outliers();
    test_nonlinear_model_converges_from_a_rough_start();
    return check_report("fitters_ceres_bridge_statistics");
}
