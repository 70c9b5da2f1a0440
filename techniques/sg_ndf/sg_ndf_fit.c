/* The spherical-Gaussian NDF fit (see sg_ndf_fit.h for the objective,
 * initialisation and checks). */
#include "sg_ndf/sg_ndf_fit.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fitters/ceres_bridge.h"

/* Parameter ranges: axes up to atan(20) = 87 degrees from the normal,
 * lobe widths from 2 rad down to 0.5 mrad, non-negative amplitudes. */
static const double param_lower[SG_NDF_LOBE_PARAMS] = {-20.0, -20.0, 0.5, 0.0};
static const double param_upper[SG_NDF_LOBE_PARAMS] = {20.0, 20.0, 1e7, 1e9};

sg_fit_options sg_fit_default_options(void)
{
    sg_fit_options o = {64, 128, 1};
    return o;
}

const char *sg_fit_status_name(sg_fit_status s)
{
    static const char *names[] = {"ok", "at-bound", "collapsed", "not-converged", "worse", "not-run"};
    return names[s];
}

/* The quadrature grid: node directions, sqrt of their solid angles divided
 * by the target's L2 norm (so that sum r^2 = E^2), and the target there. */
typedef struct {
    int rows, cols;
    double *dir, *sqrt_w, *target, *cos_w; /* cos_w: solid angle times m.z */
    double dmax, normalisation, norm;
} sg_grid;

typedef struct {
    const sg_grid *grid;
    int lobes, threads;
} row_block;

static void grid_free(sg_grid *g)
{
    free(g->dir);
    free(g->sqrt_w);
    free(g->target);
    free(g->cos_w);
}

/* theta(u) = atan(c tan(pi u / 2)) and dtheta/du. */
static double grid_theta(double u, double c, double *dtheta_du)
{
    double t = tan(0.5 * M_PI * u), sec2 = 1.0 + t * t;
    *dtheta_du = c * 0.5 * M_PI * sec2 / (1.0 + c * c * t * t);
    return atan(c * t);
}

static void grid_node(sg_grid *g, const sg_target *target, int i, int j, double c)
{
    double dtheta, theta = grid_theta((i + 0.5) / g->rows, c, &dtheta), phi = 2.0 * M_PI * (j + 0.5) / g->cols;
    int n = i * g->cols + j;
    double *m = g->dir + 3 * n, s = sin(theta);
    m[0] = s * cos(phi);
    m[1] = s * sin(phi);
    m[2] = cos(theta);
    double w = s * dtheta / g->rows * (2.0 * M_PI / g->cols);
    g->target[n] = target->evaluate(m, target->ctx);
    g->sqrt_w[n] = w;
    g->cos_w[n] = w * m[2];
}

static int grid_build(sg_grid *g, const sg_target *target, const sg_fit_options *o, gt_error *e)
{
    size_t count = (size_t)o->theta_count * (size_t)o->phi_count;
    g->rows = o->theta_count;
    g->cols = o->phi_count;
    g->dir = malloc(3 * count * sizeof(double));
    g->sqrt_w = malloc(count * sizeof(double));
    g->target = malloc(count * sizeof(double));
    g->cos_w = malloc(count * sizeof(double));
    if (!g->dir || !g->sqrt_w || !g->target || !g->cos_w)
        return gt_error_set(e, "fit sg-ndf", "out of memory for a %zu-node grid", count);
    double c = sqrt(target->alpha_x * target->alpha_y), norm2 = 0.0;
    g->dmax = 0.0;
    g->normalisation = 0.0;
    for (int i = 0; i < g->rows; ++i)
        for (int j = 0; j < g->cols; ++j) {
            grid_node(g, target, i, j, c);
            size_t n = (size_t)i * g->cols + j;
            norm2 += g->sqrt_w[n] * g->target[n] * g->target[n];
            g->dmax = fmax(g->dmax, g->target[n]);
            g->normalisation += g->cos_w[n] * g->target[n];
        }
    g->norm = sqrt(norm2);
    for (size_t n = 0; n < count; ++n)
        g->sqrt_w[n] = sqrt(g->sqrt_w[n] / norm2);
    return 0;
}

/* The lobe j of params as an SG; d_axis as in sg_axis_from_gnomonic. */
static spherical_gaussian lobe_of(const double *params, int j, double d_axis[6])
{
    const double *q = params + SG_NDF_LOBE_PARAMS * j;
    spherical_gaussian g;
    sg_axis_from_gnomonic(q[0], q[1], g.axis, d_axis);
    g.sharpness = q[2];
    g.amplitude = q[3];
    return g;
}

/* Writes lobe j's four Jacobian entries for node direction m. */
static double lobe_value_and_gradient(const spherical_gaussian *g, const double d_axis[6], const double m[3],
                                      double *grad)
{
    double t = g->axis[0] * m[0] + g->axis[1] * m[1] + g->axis[2] * m[2];
    double basis = exp(g->sharpness * (t - 1.0)), value = g->amplitude * basis;
    if (grad) {
        double da = d_axis[0] * m[0] + d_axis[1] * m[1] + d_axis[2] * m[2];
        double db = d_axis[3] * m[0] + d_axis[4] * m[1] + d_axis[5] * m[2];
        grad[0] = value * g->sharpness * da;
        grad[1] = value * g->sharpness * db;
        grad[2] = value * (t - 1.0);
        grad[3] = basis;
    }
    return value;
}

/* One node's residual and Jacobian row (row may be NULL). */
static double node_residual(const row_block *b, const spherical_gaussian *lobes, double (*d_axis)[6], int node,
                            double *row)
{
    const sg_grid *g = b->grid;
    double sum = 0.0;
    for (int j = 0; j < b->lobes; ++j)
        sum += lobe_value_and_gradient(&lobes[j], d_axis[j], g->dir + 3 * node,
                                       row ? row + SG_NDF_LOBE_PARAMS * j : NULL);
    for (int c = 0; row && c < SG_NDF_LOBE_PARAMS * b->lobes; ++c)
        row[c] *= g->sqrt_w[node];
    return g->sqrt_w[node] * (sum - g->target[node]);
}

/* All nodes in one block, evaluated by b->threads OpenMP threads: each
 * writes only its own rows, so the bits do not depend on the thread count
 * (Ceres' own threads would sum the cost in a varying order). */
static int grid_residuals(void *user, const double *params, double *residuals, double *jacobian)
{
    const row_block *b = user;
    int n = SG_NDF_LOBE_PARAMS * b->lobes, count = b->grid->rows * b->grid->cols;
    spherical_gaussian lobes[SG_NDF_MAX_LOBES];
    double d_axis[SG_NDF_MAX_LOBES][6];
    for (int j = 0; j < b->lobes; ++j)
        lobes[j] = lobe_of(params, j, d_axis[j]);
#pragma omp parallel for schedule(static) num_threads(b->threads)
    for (int node = 0; node < count; ++node)
        residuals[node] = node_residual(b, lobes, d_axis, node, jacobian ? jacobian + (size_t)node * n : NULL);
    return 0;
}

static double sum_at_node(const sg_grid *g, const double *params, int lobes, int node)
{
    double sum = 0.0;
    for (int j = 0; j < lobes; ++j) {
        spherical_gaussian l = lobe_of(params, j, NULL);
        sum += sg_evaluate(&l, g->dir + 3 * node);
    }
    return sum;
}

/* k = 1: the normal; else the previous lobes plus one at the largest deficit. */
static void initial_params(const sg_grid *g, const sg_target *target, int k, const sg_fit *previous, double *p)
{
    if (!previous) {
        double n[3] = {0.0, 0.0, 1.0};
        double start[4] = {0.0, 0.0, 2.0 / (target->alpha_x * target->alpha_y), target->evaluate(n, target->ctx)};
        memcpy(p, start, sizeof start);
        p[2] = fmin(fmax(p[2], 2 * param_lower[2]), 0.5 * param_upper[2]);
        return;
    }
    memcpy(p, previous->params, sizeof(double) * SG_NDF_LOBE_PARAMS * (k - 1));
    int best = 0;
    double deficit = -INFINITY, sharpest = 0.0;
    for (int node = 0; node < g->rows * g->cols; ++node) {
        double d = g->target[node] - sum_at_node(g, p, k - 1, node);
        if (d > deficit)
            deficit = d, best = node;
    }
    for (int j = 0; j < k - 1; ++j)
        sharpest = fmax(sharpest, p[SG_NDF_LOBE_PARAMS * j + 2]);
    const double *m = g->dir + 3 * best;
    double *q = p + SG_NDF_LOBE_PARAMS * (k - 1);
    q[0] = m[0] / m[2];
    q[1] = m[1] / m[2];
    q[2] = sharpest;
    q[3] = fmax(0.5 * deficit, 1e-9 * g->dmax);
}

/* Ceres on the grid, params in place; stderr_ filled when defined. */
static int solve_params(const sg_grid *g, int k, int threads, double *params, sg_fit *out, gt_error *e)
{
    int n = SG_NDF_LOBE_PARAMS * k, rc = -1;
    row_block block = {g, k, threads};
    gt_fit *fit = gt_fit_create(n, params, e);
    if (!fit)
        goto done;
    for (int i = 0; i < n; ++i)
        if (gt_fit_set_bounds(fit, i, param_lower[i % 4], param_upper[i % 4], e) != 0)
            goto done;
    if (gt_fit_add_block(fit, g->rows * g->cols, grid_residuals, &block, NULL, e) != 0)
        goto done;
    gt_fit_options o = gt_fit_default_options();
    o.max_iterations = 500;
    gt_fit_result result;
    if (gt_fit_solve(fit, &o, &result, e) != 0)
        goto done;
    out->iterations = result.iterations;
    out->status = result.success ? SG_FIT_OK : SG_FIT_NOT_CONVERGED;
    gt_error ignored = {{0}};
    out->has_stderr = gt_fit_covariance(fit, NULL, out->stderr_, NULL, &ignored) == 0;
    rc = 0;
done:
    gt_fit_destroy(fit);
    return rc;
}

static void measure_errors(const sg_grid *g, sg_fit *f)
{
    double e2 = 0.0, emax = 0.0;
    for (int node = 0; node < g->rows * g->cols; ++node) {
        double d = sum_at_node(g, f->params, f->lobe_count, node) - g->target[node];
        e2 += g->sqrt_w[node] * g->sqrt_w[node] * d * d;
        emax = fmax(emax, fabs(d));
    }
    f->l2_error = sqrt(e2);
    f->max_error = emax / g->dmax;
    f->grid_normalisation = g->normalisation;
    f->target_norm = g->norm;
    f->projected_area = 0.0;
    for (int j = 0; j < f->lobe_count; ++j) {
        f->lobes[j] = lobe_of(f->params, j, NULL);
        f->projected_area += sg_projected_area_integral(&f->lobes[j]);
    }
}

static int on_bound(double p, double bound) { return fabs(p - bound) <= 1e-9 * fmax(1.0, fabs(bound)); }

static int find_bound(sg_fit *f)
{
    static const char *names[SG_NDF_LOBE_PARAMS] = {"axis a", "axis b", "sharpness", "amplitude"};
    for (int i = 0; i < SG_NDF_LOBE_PARAMS * f->lobe_count; ++i) {
        int c = i % SG_NDF_LOBE_PARAMS;
        if (on_bound(f->params[i], param_lower[c]) || on_bound(f->params[i], param_upper[c])) {
            snprintf(f->note, sizeof f->note, "lobe %d's %s = %g is on its range's bound [%g, %g]%s",
                     i / SG_NDF_LOBE_PARAMS + 1, names[c], f->params[i], param_lower[c], param_upper[c],
                     c == 3 ? ": a dead lobe, so this is a fit of fewer lobes" : "");
            return 1;
        }
    }
    return 0;
}

static int find_collapse(sg_fit *f)
{
    for (int i = 0; i < f->lobe_count; ++i)
        for (int j = i + 1; j < f->lobe_count; ++j) {
            const spherical_gaussian *a = &f->lobes[i], *b = &f->lobes[j];
            double t = a->axis[0] * b->axis[0] + a->axis[1] * b->axis[1] + a->axis[2] * b->axis[2];
            double angle = 2.0 * asin(fmin(1.0, 0.5 * sqrt(fmax(0.0, 2.0 - 2.0 * t))));
            double width = 1.0 / sqrt(fmax(a->sharpness, b->sharpness));
            if (angle < 1e-3 * width && fabs(log(a->sharpness / b->sharpness)) < 1e-3) {
                snprintf(f->note, sizeof f->note, "lobes %d and %d coincide (axes %.3g rad apart, lambda %g and %g)",
                         i + 1, j + 1, angle, a->sharpness, b->sharpness);
                return 1;
            }
        }
    return 0;
}

static void check_status(sg_fit *f, const sg_fit *previous)
{
    f->note[0] = '\0';
    if (f->status == SG_FIT_NOT_CONVERGED)
        snprintf(f->note, sizeof f->note, "Ceres stopped at its iteration limit (%d)", f->iterations);
    else if (find_bound(f))
        f->status = SG_FIT_AT_BOUND;
    else if (find_collapse(f))
        f->status = SG_FIT_COLLAPSED;
    else if (previous && f->l2_error > previous->l2_error * (1.0 + 1e-9)) {
        f->status = SG_FIT_WORSE;
        snprintf(f->note, sizeof f->note, "E = %.6g above the %d-lobe fit's %.6g", f->l2_error, f->lobe_count - 1,
                 previous->l2_error);
    }
}

static int check_options(const sg_target *target, int k, const sg_fit_options *o, gt_error *e)
{
    if (k < 1 || k > SG_NDF_MAX_LOBES)
        return gt_error_set(e, "fit sg-ndf", "lobe count %d outside 1..%d", k, SG_NDF_MAX_LOBES);
    if (o->theta_count < 4 || o->phi_count < 4 || o->threads < 1)
        return gt_error_set(e, "fit sg-ndf", "grid %d x %d or threads %d below the minimum (4, 4, 1)",
                            o->theta_count, o->phi_count, o->threads);
    if (!(target->alpha_x > 0.0) || !(target->alpha_y > 0.0))
        return gt_error_set(e, "fit sg-ndf", "roughness (%g, %g) must be positive", target->alpha_x, target->alpha_y);
    return 0;
}

int sg_fit_lobes(const sg_target *target, int k, const sg_fit *previous, const sg_fit_options *options,
                 sg_fit *out, gt_error *e)
{
    sg_fit_options o = options ? *options : sg_fit_default_options();
    if (check_options(target, k, &o, e) != 0)
        return -1;
    if (previous && previous->lobe_count != k - 1)
        return gt_error_set(e, "fit sg-ndf", "grows %d lobes from a %d-lobe fit", k, previous->lobe_count);
    sg_grid g = {0};
    memset(out, 0, sizeof *out);
    out->lobe_count = k;
    int rc = grid_build(&g, target, &o, e);
    if (rc == 0) {
        initial_params(&g, target, k, previous, out->params);
        rc = solve_params(&g, k, o.threads, out->params, out, e);
    }
    if (rc == 0) {
        measure_errors(&g, out);
        check_status(out, previous);
    }
    grid_free(&g);
    return rc;
}

int sg_fit_series(const sg_target *target, int max_lobes, const sg_fit_options *options, sg_fit *out, gt_error *e)
{
    int stopped = 0;
    for (int k = 1; k <= max_lobes; ++k) {
        if (stopped) {
            memset(&out[k - 1], 0, sizeof out[k - 1]);
            out[k - 1].lobe_count = k;
            out[k - 1].status = SG_FIT_NOT_RUN;
            continue;
        }
        if (sg_fit_lobes(target, k, k > 1 ? &out[k - 2] : NULL, options, &out[k - 1], e) != 0)
            return -1;
        stopped = out[k - 1].status != SG_FIT_OK;
    }
    return 0;
}
