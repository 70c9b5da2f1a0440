/* Fitting the GGX LTC table (ltc/ltc_ggx.h) with Ceres (fitters/ceres_bridge.h).
 *
 * Objective. Heitz et al. 2016 (their fitting code, fitLTC) minimise
 * an L3 error estimated by importance sampling the BRDF and the LTC. gtlab
 * minimises the L2 distance between the normalised target t(l) =
 * f_r(v, l)(n.l) / E and the LTC D(l), over the whole sphere,
 *
 *   cost(m) = 1/2 \int_S (D_m(l) - t(l))^2 dl
 *
 * estimated on a FIXED direction grid per cell (deterministic, so Ceres
 * sees a smooth function of m): LTC_FIT_BRDF_GRID^2 directions
 * l = reflect(v, h), h from GGX's visible normals (Heitz 2018) at the grid's
 * cell centres, and LTC_FIT_COSINE_GRID^2 cosine-distributed directions on
 * each hemisphere (the lower one penalises LTC mass below the horizon,
 * where t = 0). The grids are combined as one deterministic multiple-
 * importance quadrature, balance heuristic (Veach 1997): a direction l_i
 * weighs w_i = 1 / sum_k n_k p_k(l_i), and the residuals are sqrt(w_i)
 * (D_m(l_i) - t(l_i)). E is the DFG quadrature's (luts/dfg_lut.h, error
 * ~1e-7), not the grid's: then a target that is itself an LTC (the clamped
 * cosine) is fitted exactly, whatever the grid's own quadrature error. L2 (not Heitz's L3) because Ceres
 * minimises squares; both weigh the lobe's peak most.
 *
 * Parameters: m = (a, b, c, d) of M^-1 (ltc/ltc_ggx.h), a and c kept
 * positive (bounds [1e-6, 1e7]), derivatives by Ceres' central differences
 * (all in double). Warm start as Heitz's: the column at n.v ~ 1 starts from
 * the isotropic scaling M^-1 = diag(1/alpha, 1/alpha, 1) (GGX at normal
 * incidence is nearly a scaled cosine) turned to the lobe's mean direction,
 * and each row then marches towards grazing views, each cell starting from
 * its neighbour's solution turned by the change of that direction (without
 * the turn a smooth lobe moves by more than its width between cells and
 * the fit starts where the target is 0). Rows are independent, so the
 * table is the same for any thread count.
 *
 * The fit's error per cell: the total-variation distance between D and t,
 * 1/2 \int_S |D - t| dl on the same quadrature: the share of the lobe's
 * energy the LTC puts in the wrong place (0 exact, 1 disjoint). */
#ifndef GTLAB_LTC_LTC_FIT_H
#define GTLAB_LTC_LTC_FIT_H

#include "core/error.h"
#include "ltc/ltc_ggx.h"

#define LTC_FIT_BRDF_GRID 16
#define LTC_FIT_COSINE_GRID 12

/* The unnormalised target f(l) for l on the unit sphere (n = +z). */
typedef double (*ltc_target_fn)(void *user, const double l[3]);

typedef struct {
    double error;        /* total-variation distance, above */
    double integral;     /* the grid's quadrature of D (1 up to the grid's error) */
    double albedo;       /* the grid's quadrature of the target: E */
    int iterations;
} ltc_cell_fit;

/* Fits m (start in m, solution out) to target / norm (norm: the target's
 * integral over the sphere, known more accurately than the grid knows it),
 * on the grid of the view v = (sqrt(1 - n.v^2), 0, n.v) and GGX alpha
 * (which place the BRDF grid). Returns 0, or -1 with e. */
int ltc_fit_cell_target(double n_dot_v, double alpha, ltc_target_fn target, void *user, double norm, double m[4],
                        ltc_cell_fit *out, gt_error *e);

/* The same for gtlab's GGX (core/optics/ggx.h, no Fresnel) at (n.v, alpha),
 * normalised by its directional albedo `albedo`. */
int ltc_fit_cell(double n_dot_v, double alpha, double albedo, double m[4], ltc_cell_fit *out, gt_error *e);

/* The axis of GGX's lobe f_r (n.l) for the view at n.v: the angle from n
 * (towards +x, away from v) of its mean direction, on the fit's grid. */
double ltc_ggx_lobe_axis(double n_dot_v, double alpha);

/* m := the LTC turned by angle about y (its lobe turned from z towards +x):
 * M^-1 R_y(-angle), renormalised to a unit (2,2) entry. */
void ltc_rotate_about_y(double m[4], double angle);

/* Fits a size x size table (LTC_MIN_SIZE..LTC_MAX_SIZE) into *t: M^-1 by
 * the fit, the magnitude E and the Fresnel term B by quadrature
 * (dfg_integrate, luts/dfg_lut.h), the fit's error per texel. `threads`
 * OpenMP workers over the rows. Returns 0, or -1 with e (t left empty). */
int ltc_fit_table(ltc_table *t, int size, int threads, gt_error *e);

#endif
