/* The multi-bounce cubic refitted under the shader's clamp (issue 25, item
 * 4): the talk's model (a, b, c linear in rho) constrained to V'_d(1) = 1
 * and V'_d >= V_d on the whole unit square of (V_d, rho), so that
 * max(V_d, .) never binds. The constraints are not penalties: the fit moves
 * the parameters s of multibounce/multibounce.h's constrained form
 *     V'_d = x + x (1 - x) g(x, rho),  g bilinear with corner values s_ij^2,
 * in which they hold for every s by construction; Levenberg-Marquardt
 * through the Ceres bridge, analytic Jacobian, the weighted samples of
 * multibounce/multibounce_fit.h. Against the unconstrained fit of the same form
 * (multibounce_fit_model, degree 1, scored with the shader's max), leave one
 * scene out: is the constraint free? */
#ifndef GTLAB_MULTIBOUNCE_MULTIBOUNCE_FIT_CONSTRAINED_H
#define GTLAB_MULTIBOUNCE_MULTIBOUNCE_FIT_CONSTRAINED_H

#include "multibounce/multibounce_fit.h"

typedef struct {
    double s[MULTIBOUNCE_CONSTRAINED_PARAMETERS];      /* the fitted parameters */
    double corner[MULTIBOUNCE_CONSTRAINED_PARAMETERS]; /* g at (x, rho) = (0,0), (0,1), (1,0), (1,1): s^2 */
    multibounce_model model;                           /* the same cubic, a, b, c linear in rho */
    gt_fit_result solver;
} multibounce_constrained_fit;

/* Least squares of the constrained form on the weighted samples; 0 or -1 with
 * e (too few samples, solver failure). */
int multibounce_fit_constrained(const multibounce_data *d, multibounce_constrained_fit *out, gt_error *e);

/* The weighted RMSE of the constrained form itself (not its degree-1 copy). */
double multibounce_constrained_rmse(const multibounce_data *d, const double s[MULTIBOUNCE_CONSTRAINED_PARAMETERS]);

/* One held-out scene: both fits made without it, scored on it. */
typedef struct {
    int scene;
    double rmse_unconstrained; /* with the shader's max, as the shader runs it */
    double rmse_constrained;
} multibounce_constrained_heldout;

typedef struct {
    multibounce_constrained_fit fit;           /* on all the data */
    double rmse_constrained, rmse_unconstrained; /* on all the data (the latter with max) */
    int heldout_count;                         /* scenes, when 2+ */
    multibounce_constrained_heldout heldout[MBFIT_MAX_SCENES];
    /* held-out RMSE constrained - unconstrained: mean over the scenes and its
     * standard error (sample s.d. / sqrt(scenes); NAN with fewer than 2) */
    double mean_difference, difference_se;
} multibounce_constrained_analysis;

/* The fit on all the data and leave-one-scene-out; needs 2+ albedos. */
int multibounce_analyse_constrained(const multibounce_data *d, multibounce_constrained_analysis *out, gt_error *e);

/* Where the clamp binds for a model: the fraction of the grid
 * x = i/n (i = 1..n), rho = j/n (j = 0..n) where the cubic < x. */
double multibounce_clamp_domain_fraction(const multibounce_model *m, int n);

#endif
