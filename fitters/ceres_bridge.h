/* Nonlinear least squares for C: a thin bridge to Ceres Solver 2.1
 * (http://ceres-solver.org/nnls_modeling.html, .../nnls_solving.html,
 * .../nnls_covariance.html). Every fit in gtlab goes through it.
 *
 * A gt_fit minimises
 *
 *     cost(p) = 1/2 * sum over blocks b of rho_b(|r_b(p)|^2)
 *
 * over one parameter vector p of n doubles, where each residual block b is a
 * C callback returning m_b residuals r_b(p) (and optionally their Jacobian),
 * and rho_b is the block's loss (the identity unless a robust loss is chosen).
 * This is Ceres' own formulation with all parameters in one Ceres parameter
 * block.
 *
 * Typical use (see tests/fitters/ for complete fits):
 *
 *     double p[3] = {0, 0, 1};
 *     gt_fit *fit = gt_fit_create(3, p, &e);
 *     for (size_t i = 0; i < count; ++i)
 *         gt_fit_add_block(fit, 1, my_residual, &samples[i], NULL, &e);
 *     gt_fit_solve(fit, NULL, &result, &e);            -> p holds the solution
 *     gt_fit_covariance(fit, cov, se, NULL, &e);        -> standard errors
 *     gt_fit_destroy(fit);
 *
 * Cost of many blocks: each block is one Ceres residual block (one small
 * object, one virtual call per evaluation, about 400 bytes in all). For a
 * million samples of a 3-parameter model on one core
 * (`gtlab bench fit` measures them):
 *   one block per sample:     about 2 s (0.3 s to add the blocks, 1 s to
 *                             solve, 0.6 s for the covariance; the first
 *                             such fit in a process pays ~0.5 s more for
 *                             fresh memory), 430 MB at its peak;
 *   blocks of 1024 samples:   about 0.25 s in all, 8x faster.
 * So give a block many samples unless each sample needs its own robust
 * loss: a loss acts on the whole block's |r_b|^2.
 *
 * Ceres never prints: solver logging is off and glog's threshold is raised
 * to FATAL on first use (gtlab uses no glog logging of its own). Problems
 * come back as gt_error values; no C++ exception crosses this interface. */
#ifndef GTLAB_FITTERS_CERES_BRIDGE_H
#define GTLAB_FITTERS_CERES_BRIDGE_H

#include <stddef.h>

#include "core/error.h"

typedef struct gt_fit gt_fit;

/* A residual block: writes the block's m residuals at params (all n
 * parameters) and, when jacobian is not NULL, d residual_i / d param_j at
 * jacobian[i * n + j] (row-major m x n, Ceres' layout). Ceres asks for the
 * Jacobian only sometimes; a NULL jacobian means residuals only.
 * Returns 0 on success, non-zero for "cannot evaluate here" (outside the
 * model's domain): Ceres then rejects the step and tries a shorter one; a
 * failure at the starting point or at every point ends the solve with an
 * error. With threads > 1 in gt_fit_options, callbacks run concurrently and
 * must not write shared state. */
typedef int (*gt_fit_residual_fn)(void *user, const double *params, double *residuals, double *jacobian);

typedef enum {
    GT_FIT_ANALYTIC = 0, /* the callback fills the Jacobian */
    GT_FIT_NUMERIC       /* Ceres differentiates: DynamicNumericDiffCostFunction, CENTRAL
                            differences with Ceres' default relative step (1e-6); the
                            callback is always called with jacobian = NULL, and may be
                            called slightly outside the bounds */
} gt_fit_derivatives;

/* Robust losses, Ceres' definitions with scale a > 0 on s = |r_b|^2 (the
 * squared norm of the whole block): rho(s) = a^2 rho1(s / a^2) with
 *   HUBER:   rho1(s) = s for s <= 1, 2 sqrt(s) - 1 beyond,
 *   CAUCHY:  rho1(s) = log(1 + s),
 *   SOFT_L1: rho1(s) = 2 (sqrt(1 + s) - 1).
 * So a is the residual size beyond which a sample counts less than a square. */
typedef enum {
    GT_FIT_LOSS_NONE = 0,
    GT_FIT_LOSS_HUBER,
    GT_FIT_LOSS_CAUCHY,
    GT_FIT_LOSS_SOFT_L1
} gt_fit_loss;

/* Per-block choices; NULL or all-zero means analytic derivatives, no loss. */
typedef struct {
    gt_fit_derivatives derivatives;
    gt_fit_loss loss;
    double loss_scale; /* a > 0, used when loss != GT_FIT_LOSS_NONE */
} gt_fit_block_options;

typedef enum {
    GT_FIT_DENSE_QR = 0,          /* Ceres' default for small dense problems: most accurate */
    GT_FIT_DENSE_NORMAL_CHOLESKY  /* forms J^T J: cheaper when there are many residuals
                                     and many parameters (with 3 parameters the solve is
                                     not where the time goes); squares the condition
                                     number */
} gt_fit_linear_solver;

/* Ceres' Solver::Options of the same meaning (Levenberg-Marquardt trust region). */
typedef struct {
    int max_iterations;         /* max_num_iterations, >= 0 */
    double function_tolerance;  /* stop when |d cost| < tol * cost */
    double gradient_tolerance;  /* stop when max |projected gradient| < tol */
    double parameter_tolerance; /* stop when |step| < tol * (|p| + tol) */
    gt_fit_linear_solver linear_solver;
    int threads;                /* residual evaluation threads, >= 1 */
} gt_fit_options;

/* 100 iterations; tolerances 1e-12 (function), 0 (gradient), 1e-10
 * (parameter); DENSE_QR; 1 thread. Ceres' defaults (50; 1e-6, 1e-10, 1e-8)
 * are changed on purpose:
 * - the function tolerance is relative to the cost, which grows with the
 *   number of residuals m, so stopping at 1e-6 can leave the parameters
 *   about sqrt(m * 1e-6) standard errors short of the optimum: a whole
 *   standard error at a million samples. 1e-12 keeps that below 0.001;
 * - the gradient tolerance is absolute, so it would stop a fit early or
 *   late depending on the scale of the residuals (e.g. weights): off, so
 *   that scaling every residual by a constant changes nothing. */
gt_fit_options gt_fit_default_options(void);

typedef enum {
    GT_FIT_CONVERGENCE = 0, /* a tolerance was met */
    GT_FIT_NO_CONVERGENCE,  /* max_iterations reached: the parameters are usable but not final */
    GT_FIT_FAILURE          /* Ceres could not proceed (e.g. the residuals cannot be evaluated) */
} gt_fit_termination;

typedef struct {
    int success;                    /* 1 iff termination == GT_FIT_CONVERGENCE */
    gt_fit_termination termination;
    char message[256];              /* Ceres' Summary::message */
    int iterations;                 /* Levenberg-Marquardt iterations (as Ceres counts them) */
    double initial_cost;            /* cost(p) above, with the losses */
    double final_cost;
    size_t residual_count;          /* m_total: residuals of all blocks */
    int free_parameter_count;       /* n minus the held parameters */
    double rmse;                    /* sqrt(mean r^2) over all residuals at the solution, no loss */
    double max_abs_residual;        /* max |r| at the solution, no loss */
    double seconds;                 /* Ceres' total solve time */
} gt_fit_result;

/* A fit of parameter_count parameters living in params (borrowed: it must
 * outlive the fit; its values are the start and receive the solution, as
 * in Ceres). Returns NULL with e on bad arguments or out of memory. */
gt_fit *gt_fit_create(int parameter_count, double *params, gt_error *e);
void gt_fit_destroy(gt_fit *fit);

/* Box constraints on parameter index: lower < upper; -INFINITY / INFINITY
 * remove a side. Ceres keeps every iterate inside the box (it projects each
 * step onto it), so a parameter whose unconstrained optimum lies outside
 * ends exactly on the bound. Projected steps crawl once a bound is active
 * and the parameters are correlated, so gt_fit_solve then re-solves with
 * the parameters found on a bound held there, until the Karush-Kuhn-Tucker
 * conditions hold: the result is the constrained least-squares optimum. The
 * start must lie inside the box (checked at solve). */
int gt_fit_set_bounds(gt_fit *fit, int index, double lower, double upper, gt_error *e);

/* held != 0 keeps parameter index at its current value (Ceres'
 * SubsetManifold, or a constant parameter block when all are held);
 * held == 0 frees it again. A held parameter has zero covariance. */
int gt_fit_hold(gt_fit *fit, int index, int held, gt_error *e);

/* Adds a block of residual_count >= 1 residuals computed by evaluate(user,
 * ...). user is passed through untouched and must stay valid for the
 * fit's life. options may be NULL. Returns 0 or -1 with e. */
int gt_fit_add_block(gt_fit *fit, int residual_count, gt_fit_residual_fn evaluate, void *user,
                     const gt_fit_block_options *options, gt_error *e);

/* Minimises the cost from the values in params and writes the solution
 * back. options may be NULL (defaults). result may be NULL. Returns 0 when
 * the solution is usable (GT_FIT_CONVERGENCE or GT_FIT_NO_CONVERGENCE: check
 * result->success), -1 with e otherwise (bad input, start outside the
 * bounds, residuals that cannot be evaluated, out of memory); result is
 * filled as far as Ceres got either way. */
int gt_fit_solve(gt_fit *fit, const gt_fit_options *options, gt_fit_result *result, gt_error *e);

/* The covariance of the parameters at their current values (normally the
 * solution), from Ceres' Covariance class (DENSE_SVD on the Jacobian of the
 * free parameters).
 * Ceres computes inverse(J^T J), which is the covariance only if every
 * residual has unit variance (ceres/covariance.h: scaling the residuals so
 * is "the user's responsibility"). gtlab's residuals have an unknown common
 * variance, so the matrix is scaled by its usual a-posteriori estimate
 *
 *     sigma^2 = 2 cost / (m_total - n_free)   (= sum r^2 / (m_total - n_free) without losses)
 *
 * (unbiased for a model linear in its parameters). The standard errors are
 * then independent of any overall scale of the residuals; a caller whose
 * residuals are already divided by known standard deviations can recover
 * Ceres' unscaled matrix as covariance / sigma^2.
 * With robust losses both the Jacobian (Ceres' apply_loss_function) and
 * the cost include the loss: an approximation, as for any M-estimator.
 * Bounds are not considered: a parameter resting on a bound gets the
 * standard error of the unconstrained local model.
 *
 * Outputs (each may be NULL): covariance, n x n row-major; standard_errors,
 * n values sqrt(diag); residual_variance, sigma^2. Held parameters have zero
 * rows, columns and standard errors. Returns -1 with e when the covariance
 * does not exist: the Jacobian is rank-deficient (the data do not determine
 * every free parameter: reciprocal condition number of J^T J below 1e-14),
 * there are no more residuals than free parameters, or the residuals cannot
 * be evaluated. */
int gt_fit_covariance(gt_fit *fit, double *covariance, double *standard_errors, double *residual_variance,
                      gt_error *e);

#endif
