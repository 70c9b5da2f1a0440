/* The NDF fit with spherical Gaussians of Kaplanyan's CryENGINE 3 talk
 * (SIGGRAPH 2010, "Anisotropic deferred materials, part I": "Approximate NDF
 * with Spherical Gaussians [WRGSG09] - need only ~7 lobes for anisotropic
 * Ward NDF"): a sum of k lobes (core/optics/spherical_gaussian.h)
 *
 *   S(m) = sum_j mu_j exp(lambda_j (m.p_j - 1))
 *
 * fitted to a target D(m) on the upper hemisphere by Ceres
 * (fitters/ceres_bridge.h). Parameters per lobe: the axis in gnomonic
 * coordinates (a, b) (p = (a, b, 1)/sqrt(1 + a^2 + b^2), smooth at the
 * normal), lambda and mu. The objective is least squares in D with
 * solid-angle weights, relative to the target's L2 norm:
 *
 *   E^2 = int_{H^2} (S(m) - D(m))^2 dm / int_{H^2} D(m)^2 dm
 *
 * on a midpoint product grid in (u, phi) with theta(u) = atan(c tan(pi u / 2)),
 * c = sqrt(alpha_x alpha_y): half of the theta nodes lie inside the lobe's
 * slope scale, and the weights are the exact Jacobian sin theta dtheta/du
 * dphi. Reported errors: E (the "L2 error") and max |S - D| / max D on the grid.
 *
 * Initialisation (deterministic, greedy): k = 1 starts at the normal with
 * lambda = 2 / (alpha_x alpha_y) (the small-angle match exp(-theta^2/alpha^2)
 * = exp(-lambda theta^2 / 2)) and mu = D(n); lobe k + 1 starts from the k-lobe
 * solution plus a lobe at the grid node of largest deficit D - S, with the
 * sharpest existing lambda and half the deficit as amplitude.
 *
 * Checks (a fit's status; a series stops at the first fit that is not OK,
 * because its number would mean something else): a parameter on a bound of
 * its range (a lobe with mu = 0 is dead: k - 1 lobes in disguise), two lobes
 * collapsed onto each other (axes within 1e-3 of a lobe width and lambdas
 * within 0.1%: the Jacobian is rank-deficient and the k-lobe number is a
 * (k-1)-lobe fit), no convergence, or an error larger than the (k-1)-lobe fit's.
 *
 * Standard errors of the parameters come from Ceres' covariance scaled by
 * the residual variance (ceres_bridge.h). The residuals are model misfit,
 * not noise, so they measure how well the grid determines each parameter
 * (flat directions of the cost), not a statistical uncertainty. */
#ifndef GTLAB_SG_NDF_FIT_H
#define GTLAB_SG_NDF_FIT_H

#include "core/error.h"
#include "core/optics/spherical_gaussian.h"

enum { SG_NDF_MAX_LOBES = 12, SG_NDF_LOBE_PARAMS = 4 };

typedef double (*sg_target_fn)(const double m[3], const void *ctx);

/* The function to fit: D(m) for unit m with m.z > 0, and its slope scales
 * (they place the grid and the first lobe). */
typedef struct {
    sg_target_fn evaluate;
    const void *ctx;
    double alpha_x, alpha_y;
} sg_target;

typedef struct {
    int theta_count, phi_count; /* grid nodes, >= 4 each */
    int threads;                /* residual evaluation threads (OpenMP), >= 1: the bits do not depend on it */
} sg_fit_options;

/* 64 x 128 nodes, 1 thread. */
sg_fit_options sg_fit_default_options(void);

typedef enum {
    SG_FIT_OK = 0,
    SG_FIT_AT_BOUND,      /* a parameter ended on its range's bound */
    SG_FIT_COLLAPSED,     /* two lobes coincide */
    SG_FIT_NOT_CONVERGED, /* Ceres' iteration limit */
    SG_FIT_WORSE,         /* E above the (k-1)-lobe fit's */
    SG_FIT_NOT_RUN        /* a series stopped before this k */
} sg_fit_status;

const char *sg_fit_status_name(sg_fit_status s);

typedef struct {
    int lobe_count;
    spherical_gaussian lobes[SG_NDF_MAX_LOBES];
    double params[SG_NDF_MAX_LOBES * SG_NDF_LOBE_PARAMS]; /* (a, b, lambda, mu) per lobe */
    double stderr_[SG_NDF_MAX_LOBES * SG_NDF_LOBE_PARAMS];
    int has_stderr;           /* 0 when Ceres finds the covariance undefined */
    double l2_error;          /* E, relative */
    double max_error;         /* max |S - D| / max D on the grid */
    double projected_area;    /* int S (m.n) dm, exact per lobe (sg_projected_area_integral) */
    double grid_normalisation;/* int D (m.n) dm on the grid: 1 up to the grid's error */
    double target_norm;       /* (int D^2 dm)^(1/2) on the grid: E times it is the absolute L2 error */
    int iterations;
    sg_fit_status status;
    char note[160];           /* why the status is not OK */
} sg_fit;

/* One fit of k lobes; previous = the (k-1)-lobe fit to grow from (NULL for
 * k = 1). Returns 0 (check out->status) or -1 with e (bad options, Ceres
 * failure, out of memory). */
int sg_fit_lobes(const sg_target *target, int k, const sg_fit *previous, const sg_fit_options *options,
                 sg_fit *out, gt_error *e);

/* Fits k = 1 .. max_lobes into out[0 .. max_lobes-1], each grown from the
 * last; after the first fit whose status is not OK the rest are SG_FIT_NOT_RUN.
 * Returns 0 or -1 with e. */
int sg_fit_series(const sg_target *target, int max_lobes, const sg_fit_options *options, sg_fit *out, gt_error *e);

#endif
