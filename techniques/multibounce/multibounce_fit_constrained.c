#include "multibounce/multibounce_fit_constrained.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    const multibounce_sample *samples;
    int count;
} constrained_block;

/* d V'_d / d s_k = x (1 - x) 2 s_k B_k(x, rho), B the bilinear corner weights. */
static void constrained_gradient(const double *s, double x, double rho, double *g)
{
    const double bilinear[MULTIBOUNCE_CONSTRAINED_PARAMETERS] = {(1.0 - x) * (1.0 - rho), (1.0 - x) * rho,
                                                                 x * (1.0 - rho), x * rho};
    for (int k = 0; k < MULTIBOUNCE_CONSTRAINED_PARAMETERS; ++k)
        g[k] = x * (1.0 - x) * 2.0 * s[k] * bilinear[k];
}

static int constrained_residuals(void *user, const double *params, double *residuals, double *jacobian)
{
    const constrained_block *b = user;
    for (int i = 0; i < b->count; ++i) {
        const multibounce_sample *sample = &b->samples[i];
        const double root_w = sqrt((double)sample->weight);
        residuals[i] =
            root_w * (multibounce_constrained_eval(params, sample->visibility, sample->albedo) - sample->multibounce);
        if (!jacobian)
            continue;
        double g[MULTIBOUNCE_CONSTRAINED_PARAMETERS];
        constrained_gradient(params, sample->visibility, sample->albedo, g);
        for (int k = 0; k < MULTIBOUNCE_CONSTRAINED_PARAMETERS; ++k)
            jacobian[(size_t)i * MULTIBOUNCE_CONSTRAINED_PARAMETERS + (size_t)k] = root_w * g[k];
    }
    return 0;
}

/* ---- The starting point: the exact optimum over the corner values ------------------ */

/* The form is linear in the corner values G = s^2 >= 0: V'_d - x = phi . G
 * with phi_k = x (1 - x) B_k(x, rho). So the fit is non-negative least
 * squares in 4 unknowns, solved exactly by trying every support (the
 * optimum is the unconstrained optimum on its support, feasible, and of
 * least cost among the feasible ones). Ceres then starts at s = sqrt(G), a
 * stationary point of the squared form, and confirms it. */
typedef struct {
    double m[MULTIBOUNCE_CONSTRAINED_PARAMETERS][MULTIBOUNCE_CONSTRAINED_PARAMETERS];
    double v[MULTIBOUNCE_CONSTRAINED_PARAMETERS];
} normal_equations;

static void accumulate_normal_equations(const multibounce_data *d, normal_equations *n)
{
    memset(n, 0, sizeof *n);
    const double unit[MULTIBOUNCE_CONSTRAINED_PARAMETERS] = {1.0, 1.0, 1.0, 1.0};
    for (size_t i = 0; i < d->count; ++i) {
        const multibounce_sample *sample = &d->samples[i];
        double phi[MULTIBOUNCE_CONSTRAINED_PARAMETERS];
        constrained_gradient(unit, sample->visibility, sample->albedo, phi); /* 2 phi at s = 1 */
        const double t = (double)sample->multibounce - sample->visibility;
        for (int j = 0; j < MULTIBOUNCE_CONSTRAINED_PARAMETERS; ++j) {
            n->v[j] += sample->weight * 0.5 * phi[j] * t;
            for (int k = 0; k < MULTIBOUNCE_CONSTRAINED_PARAMETERS; ++k)
                n->m[j][k] += sample->weight * 0.25 * phi[j] * phi[k];
        }
    }
}

/* Solves the equations restricted to the corners in `support` (a bit set) by
 * Gauss-Jordan elimination with partial pivoting; 0, or -1 when singular. */
static int solve_support(const normal_equations *n, unsigned support, double *g)
{
    int idx[MULTIBOUNCE_CONSTRAINED_PARAMETERS], m = 0;
    double a[MULTIBOUNCE_CONSTRAINED_PARAMETERS][MULTIBOUNCE_CONSTRAINED_PARAMETERS + 1];
    for (int k = 0; k < MULTIBOUNCE_CONSTRAINED_PARAMETERS; ++k)
        if (support & (1u << k))
            idx[m++] = k;
    for (int r = 0; r < m; ++r) {
        for (int c = 0; c < m; ++c)
            a[r][c] = n->m[idx[r]][idx[c]];
        a[r][m] = n->v[idx[r]];
    }
    for (int c = 0; c < m; ++c) {
        int pivot = c;
        for (int r = c + 1; r < m; ++r)
            pivot = fabs(a[r][c]) > fabs(a[pivot][c]) ? r : pivot;
        if (!(fabs(a[pivot][c]) > 1e-300))
            return -1;
        for (int k = 0; k <= m; ++k) {
            double swap = a[c][k];
            a[c][k] = a[pivot][k];
            a[pivot][k] = swap;
        }
        for (int r = 0; r < m; ++r)
            for (int k = m; k >= c && r != c; --k)
                a[r][k] -= a[r][c] / a[c][c] * a[c][k];
    }
    memset(g, 0, sizeof(double) * MULTIBOUNCE_CONSTRAINED_PARAMETERS);
    for (int r = 0; r < m; ++r)
        g[idx[r]] = a[r][m] / a[r][r];
    return 0;
}

/* G^T M G - 2 G . v: the cost up to a constant. */
static double support_cost(const normal_equations *n, const double *g)
{
    double cost = 0.0;
    for (int j = 0; j < MULTIBOUNCE_CONSTRAINED_PARAMETERS; ++j) {
        cost -= 2.0 * g[j] * n->v[j];
        for (int k = 0; k < MULTIBOUNCE_CONSTRAINED_PARAMETERS; ++k)
            cost += g[j] * n->m[j][k] * g[k];
    }
    return cost;
}

/* s = sqrt(G) of the non-negative least-squares optimum. */
static void exact_start(const multibounce_data *d, double *s)
{
    normal_equations n;
    accumulate_normal_equations(d, &n);
    double best[MULTIBOUNCE_CONSTRAINED_PARAMETERS] = {0}, best_cost = 0.0;
    for (unsigned support = 1; support < (1u << MULTIBOUNCE_CONSTRAINED_PARAMETERS); ++support) {
        double g[MULTIBOUNCE_CONSTRAINED_PARAMETERS];
        int feasible = solve_support(&n, support, g) == 0;
        for (int k = 0; k < MULTIBOUNCE_CONSTRAINED_PARAMETERS; ++k)
            feasible &= g[k] >= 0.0;
        if (feasible && support_cost(&n, g) < best_cost) {
            best_cost = support_cost(&n, g);
            memcpy(best, g, sizeof best);
        }
    }
    for (int k = 0; k < MULTIBOUNCE_CONSTRAINED_PARAMETERS; ++k)
        s[k] = sqrt(best[k]);
}

static void finish_fit(const double *s, multibounce_constrained_fit *out)
{
    memcpy(out->s, s, sizeof out->s);
    for (int k = 0; k < MULTIBOUNCE_CONSTRAINED_PARAMETERS; ++k)
        out->corner[k] = s[k] * s[k];
    out->model = multibounce_model_constrained(s);
}

int multibounce_fit_constrained(const multibounce_data *d, multibounce_constrained_fit *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    if (d->count <= MULTIBOUNCE_CONSTRAINED_PARAMETERS)
        return gt_error_set(e, "multibounce fit", "%zu samples cannot determine the constrained cubic", d->count);
    const size_t block = MBFIT_DEFAULT_BLOCK, block_count = (d->count + block - 1) / block;
    constrained_block *blocks = malloc(block_count * sizeof *blocks);
    if (!blocks)
        return gt_error_set(e, "multibounce fit", "out of memory");
    double s[MULTIBOUNCE_CONSTRAINED_PARAMETERS];
    exact_start(d, s);
    gt_fit_options options = gt_fit_default_options();
    options.linear_solver = GT_FIT_DENSE_NORMAL_CHOLESKY;
    options.max_iterations = 200;
    gt_fit *fit = gt_fit_create(MULTIBOUNCE_CONSTRAINED_PARAMETERS, s, e);
    int rc = fit ? 0 : -1;
    for (size_t k = 0; k < block_count && rc == 0; ++k) {
        size_t first = k * block, count = d->count - first < block ? d->count - first : block;
        blocks[k] = (constrained_block){d->samples + first, (int)count};
        rc = gt_fit_add_block(fit, (int)count, constrained_residuals, &blocks[k], NULL, e);
    }
    if (rc == 0)
        rc = gt_fit_solve(fit, &options, &out->solver, e);
    if (rc == 0)
        finish_fit(s, out);
    gt_fit_destroy(fit);
    free(blocks);
    return rc;
}

double multibounce_constrained_rmse(const multibounce_data *d, const double s[MULTIBOUNCE_CONSTRAINED_PARAMETERS])
{
    double sum_w = 0.0, sum_wr2 = 0.0;
    for (size_t i = 0; i < d->count; ++i) {
        const multibounce_sample *sample = &d->samples[i];
        double r = multibounce_constrained_eval(s, sample->visibility, sample->albedo) - sample->multibounce;
        sum_w += sample->weight;
        sum_wr2 += sample->weight * r * r;
    }
    return sum_w > 0 ? sqrt(sum_wr2 / sum_w) : 0.0;
}

/* Both fits without `scene`, scored on it. */
static int hold_out(const multibounce_data *d, int scene, multibounce_constrained_heldout *h, gt_error *e)
{
    multibounce_data train, test;
    multibounce_data_init(&test);
    if (multibounce_data_select(d, scene, 1, -1, &train, e) != 0)
        return -1;
    int rc = multibounce_data_select(d, scene, 0, -1, &test, e);
    multibounce_fit free_fit;
    multibounce_constrained_fit bound_fit;
    const multibounce_fit_options model_only = {0, 1};
    if (rc == 0)
        rc = multibounce_fit_model(&train, 1, &model_only, &free_fit, e);
    if (rc == 0)
        rc = multibounce_fit_constrained(&train, &bound_fit, e);
    if (rc == 0) {
        multibounce_errors err;
        multibounce_measure(&test, &free_fit.model, 1, &err);
        *h = (multibounce_constrained_heldout){scene, err.rmse, multibounce_constrained_rmse(&test, bound_fit.s)};
    }
    multibounce_data_free(&train);
    multibounce_data_free(&test); /* freed and zeroed already if its selection failed */
    return rc;
}

/* Mean and standard error of the held-out differences constrained - unconstrained. */
static void difference_statistics(multibounce_constrained_analysis *a)
{
    const int n = a->heldout_count;
    double mean = 0.0, sum_sq = 0.0;
    for (int i = 0; i < n; ++i)
        mean += (a->heldout[i].rmse_constrained - a->heldout[i].rmse_unconstrained) / n;
    for (int i = 0; i < n; ++i) {
        double dev = a->heldout[i].rmse_constrained - a->heldout[i].rmse_unconstrained - mean;
        sum_sq += dev * dev;
    }
    a->mean_difference = n > 0 ? mean : NAN;
    a->difference_se = n > 1 ? sqrt(sum_sq / (n - 1) / n) : NAN;
}

int multibounce_analyse_constrained(const multibounce_data *d, multibounce_constrained_analysis *a, gt_error *e)
{
    memset(a, 0, sizeof *a);
    multibounce_fit free_fit;
    if (multibounce_fit_model(d, 1, NULL, &free_fit, e) != 0 || multibounce_fit_constrained(d, &a->fit, e) != 0)
        return -1;
    multibounce_errors err;
    multibounce_measure(d, &free_fit.model, 1, &err);
    a->rmse_unconstrained = err.rmse;
    a->rmse_constrained = multibounce_constrained_rmse(d, a->fit.s);
    for (int s = 0; s < d->scene_count && d->scene_count >= 2; ++s)
        if (hold_out(d, s, &a->heldout[a->heldout_count++], e) != 0)
            return -1;
    difference_statistics(a);
    return 0;
}

double multibounce_clamp_domain_fraction(const multibounce_model *m, int n)
{
    long below = 0;
    for (int j = 0; j <= n; ++j) {
        const multibounce_cubic c = multibounce_cubic_at(m, (double)j / n);
        for (int i = 1; i <= n; ++i)
            below += multibounce_cubic_eval(&c, (double)i / n) < (double)i / n;
    }
    return (double)below / ((double)n * (n + 1));
}
