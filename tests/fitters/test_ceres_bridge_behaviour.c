/* The Ceres bridge's behaviour at the edges: callbacks that cannot evaluate
 * (everywhere, or in part of the domain), covariances that do not exist,
 * held parameters, iteration limits, threads, bad arguments, and silence:
 * Ceres and glog print nothing, on stdout or stderr, even when things fail. */
#define _POSIX_C_SOURCE 200809L

#include "fitters/ceres_bridge.h"
#include "tests/check.h"

#include <string.h>
#include <unistd.h>

static int starts_with(const char *s, const char *prefix) { return strncmp(s, prefix, strlen(prefix)) == 0; }

/* ---- models ---- */

static const double kX[8] = {0.1, 0.2, 0.3, 0.45, 0.6, 0.7, 0.85, 1.0};

/* y = p0 x + p1 x^2 through (x, 1 + x): any residual callback over kX with
 * two parameters and exact data. */
static int line_residual(void *user, const double *p, double *r, double *jacobian)
{
    const double *x = user;
    r[0] = p[0] * x[0] + p[1] * x[0] * x[0] - (1.0 + x[0]) * x[0];
    if (jacobian) {
        jacobian[0] = x[0];
        jacobian[1] = x[0] * x[0];
    }
    return 0;
}

static int refuse_everywhere(void *user, const double *p, double *r, double *jacobian)
{
    (void)user, (void)p, (void)r, (void)jacobian;
    return 1;
}

static int nan_residual(void *user, const double *p, double *r, double *jacobian)
{
    (void)user, (void)p;
    r[0] = NAN;
    if (jacobian)
        jacobian[0] = jacobian[1] = 0.0;
    return 0;
}

/* r = log p - log 0.01, defined for p > 0 only: from p = 1 the Gauss-Newton
 * step (-4.6) lands at p < 0, which the callback refuses. */
static int log_refusals = 0;
static int log_residual(void *user, const double *p, double *r, double *jacobian)
{
    (void)user;
    if (!(p[0] > 0.0)) {
        ++log_refusals;
        return 1;
    }
    r[0] = log(p[0]) - log(0.01);
    if (jacobian)
        jacobian[0] = 1.0 / p[0];
    return 0;
}

/* y = (p0 + p1) x: only the sum is determined by the data. */
static int sum_residual(void *user, const double *p, double *r, double *jacobian)
{
    const double *x = user;
    r[0] = (p[0] + p[1]) * x[0] - 2.0 * x[0] - 0.01 * sin(40.0 * x[0]);
    if (jacobian)
        jacobian[0] = jacobian[1] = x[0];
    return 0;
}

/* A fit of two parameters with one block per kX point. */
static gt_fit *two_parameter_fit(double p[2], gt_fit_residual_fn f, gt_fit_derivatives d)
{
    gt_error e = {{0}};
    gt_fit *fit = gt_fit_create(2, p, &e);
    gt_fit_block_options o = {d, GT_FIT_LOSS_NONE, 0.0};
    for (int i = 0; i < 8 && fit; ++i)
        CHECK(gt_fit_add_block(fit, 1, f, (void *)&kX[i], &o, &e) == 0);
    return fit;
}

/* ---- tests ---- */

static void test_callback_failing_everywhere_is_an_error(void)
{
    const gt_fit_derivatives modes[2] = {GT_FIT_ANALYTIC, GT_FIT_NUMERIC};
    for (int k = 0; k < 2; ++k) {
        double p[2] = {0.0, 0.0};
        gt_fit *fit = two_parameter_fit(p, refuse_everywhere, modes[k]);
        gt_error e = {{0}};
        gt_fit_result r;
        CHECK(gt_fit_solve(fit, NULL, &r, &e) == -1);
        CHECK(starts_with(e.message, "fit: the solver failed"));
        CHECK(r.termination == GT_FIT_FAILURE && !r.success);
        CHECK(p[0] == 0.0 && p[1] == 0.0);
        double se[2];
        CHECK(gt_fit_covariance(fit, NULL, se, NULL, &e) == -1);
        gt_fit_destroy(fit);
    }
    double p[2] = {0.0, 0.0};
    gt_fit *fit = two_parameter_fit(p, nan_residual, GT_FIT_ANALYTIC);
    gt_error e = {{0}};
    CHECK(gt_fit_solve(fit, NULL, NULL, &e) == -1); /* a NaN residual counts as a failure */
    gt_fit_destroy(fit);
}

/* Ceres takes a refused step as an unsuccessful one and shrinks it. */
static void test_callback_refusing_part_of_the_domain(void)
{
    double p = 1.0;
    gt_error e = {{0}};
    gt_fit *fit = gt_fit_create(1, &p, &e);
    CHECK(gt_fit_add_block(fit, 1, log_residual, NULL, NULL, &e) == 0);
    gt_fit_result r;
    log_refusals = 0;
    CHECK(gt_fit_solve(fit, NULL, &r, &e) == 0);
    CHECK(r.success);
    CHECK(log_refusals > 0); /* the refusal path was taken */
    CHECK_NEAR(p, 0.01, 1e-9);
    gt_fit_destroy(fit);
}

static void test_rank_deficient_covariance_is_an_error(void)
{
    double p[2] = {0.5, 0.5};
    gt_fit *fit = two_parameter_fit(p, sum_residual, GT_FIT_ANALYTIC);
    gt_error e = {{0}};
    gt_fit_result r;
    CHECK(gt_fit_solve(fit, NULL, &r, &e) == 0); /* the sum is found... */
    CHECK_NEAR(p[0] + p[1], 2.0, 0.01);
    double cov[4] = {-1, -1, -1, -1};
    CHECK(gt_fit_covariance(fit, cov, NULL, NULL, &e) == -1); /* ... but not each */
    CHECK(strstr(e.message, "rank-deficient") != NULL);
    /* Holding one makes the other determined. */
    CHECK(gt_fit_hold(fit, 1, 1, &e) == 0);
    double se[2];
    CHECK(gt_fit_covariance(fit, cov, se, NULL, &e) == 0);
    CHECK(se[0] > 0.0 && se[1] == 0.0);
    gt_fit_destroy(fit);
}

/* 2 residuals, 2 parameters: an exact fit with no residual variance to
 * estimate. */
static void test_too_few_residuals_for_a_covariance(void)
{
    double p[2] = {0, 0};
    gt_error e = {{0}};
    gt_fit *fit = gt_fit_create(2, p, &e);
    CHECK(gt_fit_add_block(fit, 1, line_residual, (void *)&kX[0], NULL, &e) == 0);
    CHECK(gt_fit_add_block(fit, 1, line_residual, (void *)&kX[1], NULL, &e) == 0);
    CHECK(gt_fit_solve(fit, NULL, NULL, &e) == 0);
    CHECK(gt_fit_covariance(fit, NULL, NULL, NULL, &e) == -1);
    CHECK(strstr(e.message, "more residuals than free parameters") != NULL);
    gt_fit_destroy(fit);
}

/* All parameters held: nothing moves, the covariance is zero and the
 * residual variance is the mean square (no free parameter to subtract). */
static void test_all_parameters_held(void)
{
    double p[2] = {0.5, 0.25};
    gt_fit *fit = two_parameter_fit(p, line_residual, GT_FIT_ANALYTIC);
    gt_error e = {{0}};
    CHECK(gt_fit_hold(fit, 0, 1, &e) == 0 && gt_fit_hold(fit, 1, 1, &e) == 0);
    gt_fit_result r;
    CHECK(gt_fit_solve(fit, NULL, &r, &e) == 0);
    CHECK(p[0] == 0.5 && p[1] == 0.25);
    CHECK(r.free_parameter_count == 0);
    double cov[4], se[2], variance, ss = 0.0;
    CHECK(gt_fit_covariance(fit, cov, se, &variance, &e) == 0);
    CHECK(cov[0] == 0.0 && cov[1] == 0.0 && cov[2] == 0.0 && cov[3] == 0.0 && se[0] == 0.0 && se[1] == 0.0);
    for (int i = 0; i < 8; ++i) {
        double res = p[0] * kX[i] + p[1] * kX[i] * kX[i] - (1.0 + kX[i]) * kX[i];
        ss += res * res;
    }
    CHECK_NEAR(variance, ss / 8.0, 1e-15);
    CHECK_NEAR(r.rmse, sqrt(ss / 8.0), 1e-15);
    /* Released, they reach the exact fit (1, 1). */
    CHECK(gt_fit_hold(fit, 0, 0, &e) == 0 && gt_fit_hold(fit, 1, 0, &e) == 0);
    CHECK(gt_fit_solve(fit, NULL, &r, &e) == 0);
    CHECK_NEAR(p[0], 1.0, 1e-9);
    CHECK_NEAR(p[1], 1.0, 1e-9);
    CHECK(r.free_parameter_count == 2);
    gt_fit_destroy(fit);
}

/* y = A exp(-k x) from far away, stopped after one iteration. */
static int exp_residual(void *user, const double *p, double *r, double *jacobian)
{
    const double *x = user;
    double e = exp(-p[1] * x[0]);
    r[0] = p[0] * e - 2.0 * exp(-3.0 * x[0]);
    if (jacobian) {
        jacobian[0] = e;
        jacobian[1] = -p[0] * x[0] * e;
    }
    return 0;
}

static void test_iteration_limit(void)
{
    double p[2] = {0.5, 0.5};
    gt_fit *fit = two_parameter_fit(p, exp_residual, GT_FIT_ANALYTIC);
    gt_fit_options o = gt_fit_default_options();
    o.max_iterations = 1;
    gt_error e = {{0}};
    gt_fit_result r;
    CHECK(gt_fit_solve(fit, &o, &r, &e) == 0); /* usable, not final */
    CHECK(!r.success && r.termination == GT_FIT_NO_CONVERGENCE);
    CHECK_MSG(r.iterations == 1, "%d iterations: %s", r.iterations, r.message);
    CHECK(r.final_cost < r.initial_cost);
    CHECK(gt_fit_solve(fit, NULL, &r, &e) == 0); /* continuing from there converges */
    CHECK(r.success && r.termination == GT_FIT_CONVERGENCE);
    CHECK_NEAR(p[0], 2.0, 1e-8);
    CHECK_NEAR(p[1], 3.0, 1e-8);
    gt_fit_destroy(fit);
}

/* Two evaluation threads give the one-thread answer. */
static void test_threads(void)
{
    double p1[2] = {0.5, 0.5}, p2[2] = {0.5, 0.5}, se1[2], se2[2];
    gt_fit *a = two_parameter_fit(p1, exp_residual, GT_FIT_NUMERIC);
    gt_fit *b = two_parameter_fit(p2, exp_residual, GT_FIT_NUMERIC);
    gt_fit_options o = gt_fit_default_options();
    o.threads = 2;
    gt_error e = {{0}};
    CHECK(gt_fit_solve(a, NULL, NULL, &e) == 0 && gt_fit_solve(b, &o, NULL, &e) == 0);
    CHECK(gt_fit_covariance(a, NULL, se1, NULL, &e) == 0 && gt_fit_covariance(b, NULL, se2, NULL, &e) == 0);
    for (int i = 0; i < 2; ++i) {
        CHECK_NEAR(p1[i], p2[i], 1e-12 * fabs(p1[i]));
        CHECK_NEAR(se1[i], se2[i], 1e-6 * se1[i]);
    }
    gt_fit_destroy(a);
    gt_fit_destroy(b);
}

/* Every misuse is an error value naming the fit, never a crash or abort. */
static void test_bad_arguments(void)
{
    gt_error e = {{0}};
    double p[2] = {0.0, 0.0}, x = 0.5;
    CHECK(gt_fit_create(0, p, &e) == NULL && starts_with(e.message, "fit: "));
    CHECK(gt_fit_create(2, NULL, &e) == NULL);
    gt_fit *fit = gt_fit_create(2, p, &e);
    CHECK(fit != NULL);
    CHECK(gt_fit_solve(fit, NULL, NULL, &e) == -1 && strstr(e.message, "no residual blocks"));
    CHECK(gt_fit_hold(fit, 2, 1, &e) == -1);
    CHECK(gt_fit_hold(fit, -1, 1, &e) == -1);
    CHECK(gt_fit_set_bounds(fit, 2, 0.0, 1.0, &e) == -1);
    CHECK(gt_fit_set_bounds(fit, 0, 1.0, 1.0, &e) == -1);
    CHECK(gt_fit_set_bounds(fit, 0, NAN, 1.0, &e) == -1);
    CHECK(gt_fit_set_bounds(fit, 0, INFINITY, INFINITY, &e) == -1);
    CHECK(gt_fit_add_block(fit, 0, line_residual, &x, NULL, &e) == -1);
    CHECK(gt_fit_add_block(fit, 1, NULL, &x, NULL, &e) == -1);
    CHECK(gt_fit_add_block(NULL, 1, line_residual, &x, NULL, &e) == -1);
    gt_fit_block_options bad_scale = {GT_FIT_ANALYTIC, GT_FIT_LOSS_CAUCHY, 0.0};
    CHECK(gt_fit_add_block(fit, 1, line_residual, &x, &bad_scale, &e) == -1 && strstr(e.message, "loss scale"));
    gt_fit_block_options bad_loss = {GT_FIT_ANALYTIC, (gt_fit_loss)42, 1.0};
    CHECK(gt_fit_add_block(fit, 1, line_residual, &x, &bad_loss, &e) == -1);
    gt_fit_block_options bad_mode = {(gt_fit_derivatives)7, GT_FIT_LOSS_NONE, 0.0};
    CHECK(gt_fit_add_block(fit, 1, line_residual, &x, &bad_mode, &e) == -1);
    for (int i = 0; i < 8; ++i)
        CHECK(gt_fit_add_block(fit, 1, line_residual, (void *)&kX[i], NULL, &e) == 0);

    gt_fit_options o = gt_fit_default_options();
    o.threads = 0;
    CHECK(gt_fit_solve(fit, &o, NULL, &e) == -1 && strstr(e.message, "threads"));
    o = gt_fit_default_options();
    o.function_tolerance = -1.0;
    CHECK(gt_fit_solve(fit, &o, NULL, &e) == -1);
    o = gt_fit_default_options();
    o.linear_solver = (gt_fit_linear_solver)9;
    CHECK(gt_fit_solve(fit, &o, NULL, &e) == -1);
    o = gt_fit_default_options();
    o.max_iterations = -1;
    CHECK(gt_fit_solve(fit, &o, NULL, &e) == -1);

    /* A start outside the bounds, or not finite. */
    CHECK(gt_fit_set_bounds(fit, 1, 0.5, INFINITY, &e) == 0);
    CHECK(gt_fit_solve(fit, NULL, NULL, &e) == -1);
    CHECK(strcmp(e.message, "fit: parameter 1 starts at 0, outside its bounds [0.5, 1.79769e+308]") == 0);
    p[1] = 0.5;
    p[0] = NAN;
    CHECK(gt_fit_solve(fit, NULL, NULL, &e) == -1 && strstr(e.message, "parameter 0 starts at nan"));
    p[0] = 0.0;
    CHECK(gt_fit_solve(fit, NULL, NULL, &e) == 0);
    CHECK_NEAR(p[0], 1.0, 1e-9);

    CHECK(gt_fit_solve(NULL, NULL, NULL, &e) == -1);
    CHECK(gt_fit_covariance(NULL, NULL, NULL, NULL, &e) == -1);
    CHECK(gt_fit_hold(NULL, 0, 1, &e) == -1);
    CHECK(gt_fit_set_bounds(NULL, 0, 0, 1, &e) == -1);
    gt_fit_destroy(fit);
    gt_fit_destroy(NULL);
}

/* Runs the failure cases above with stdout and stderr sent to a file, and
 * checks the file stays empty: Ceres' warnings (evaluation failures, rank
 * deficiency, invalid options) must not reach the terminal. */
static void test_silence(void)
{
    char path[512];
    snprintf(path, sizeof path, "%s/fitters_silence.txt", check_tmp_dir());
    fflush(stdout);
    fflush(stderr);
    int saved_out = dup(1), saved_err = dup(2);
    FILE *sink = fopen(path, "w");
    CHECK(sink != NULL && saved_out >= 0 && saved_err >= 0);
    if (!sink)
        return;
    dup2(fileno(sink), 1);
    dup2(fileno(sink), 2);
    int failures_before = check_failures;
    test_callback_failing_everywhere_is_an_error();
    test_callback_refusing_part_of_the_domain();
    test_rank_deficient_covariance_is_an_error();
    test_iteration_limit();
    fflush(stdout);
    fflush(stderr);
    dup2(saved_out, 1);
    dup2(saved_err, 2);
    close(saved_out);
    close(saved_err);
    fclose(sink);
    CHECK(check_failures == failures_before); /* their own checks passed (their messages went to the file) */
    FILE *f = fopen(path, "r");
    char text[512] = {0};
    size_t n = f ? fread(text, 1, sizeof text - 1, f) : 0;
    if (f)
        fclose(f);
    CHECK_MSG(n == 0, "the fits printed: %s", text);
    remove(path);
}

int main(void)
{
    test_silence(); /* first: glog's once-per-process messages would appear here */
    test_callback_failing_everywhere_is_an_error();
    test_callback_refusing_part_of_the_domain();
    test_rank_deficient_covariance_is_an_error();
    test_too_few_residuals_for_a_covariance();
    test_all_parameters_held();
    test_iteration_limit();
    test_threads();
    test_bad_arguments();
    return check_report("fitters_ceres_bridge_behaviour");
}
