#include "sphere_light/sphere_light_fit.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/statistics/sample_mean.h"
#include "fitters/ceres_bridge.h"

double sphere_light_residual(sphere_light_model model, const decima_sphere_constants *k,
                             const sphere_light_sample *s)
{
    double value = model == SPHERE_MODEL_KARIS ? karis_sphere_ggx(s->v, s->lc, s->sin_sigma, s->alpha)
                   : model == SPHERE_MODEL_DECIMA
                       ? decima_sphere_ggx_local_radii(s->v, s->lc, s->sin_sigma,
                                                       s->norm_radius > 0.0f ? s->norm_radius : s->sin_sigma,
                                                       s->alpha, k, 1)
                       : decima_sphere_ggx_horizon_local(s->v, s->lc, s->sin_sigma, s->alpha, k, 1);
    return log((value + SPHERE_FIT_FLOOR) / (s->reference + SPHERE_FIT_FLOOR));
}

void sphere_light_error_add(sphere_light_error_sums *s, double r)
{
    s->n += 1.0;
    s->sum_abs += fabs(r), s->sum_abs2 += r * r;
    s->sum_sq += r * r, s->sum_sq2 += r * r * r * r;
}

void sphere_light_error_finish(const sphere_light_error_sums *s, sphere_light_errors *out)
{
    double n = s->n;
    double mean_abs = s->sum_abs / n, mean_sq = s->sum_sq / n;
    out->mean_abs = mean_abs;
    out->mean_abs_stderr = sqrt(fmax(0.0, s->sum_abs2 / n - mean_abs * mean_abs) / (n - 1.0));
    out->rms = sqrt(mean_sq);
    double mean_sq_stderr = sqrt(fmax(0.0, s->sum_sq2 / n - mean_sq * mean_sq) / (n - 1.0));
    out->rms_stderr = out->rms > 0.0 ? mean_sq_stderr / (2.0 * out->rms) : 0.0;
}

void sphere_light_measure(sphere_light_model model, const decima_sphere_constants *k,
                          const sphere_light_sample *samples, size_t count, sphere_light_errors *out)
{
    sphere_light_error_sums sums = {0};
    for (size_t i = 0; i < count; ++i)
        sphere_light_error_add(&sums, sphere_light_residual(model, k, &samples[i]));
    sphere_light_error_finish(&sums, out);
}

void sphere_light_paired_abs(sphere_light_model a, const decima_sphere_constants *ka, sphere_light_model b,
                             const decima_sphere_constants *kb, const sphere_light_sample *samples, size_t count,
                             double *mean, double *stderr_)
{
    double *d = malloc(sizeof *d * (count ? count : 1));
    *mean = *stderr_ = NAN;
    if (!d)
        return;
    for (size_t i = 0; i < count; ++i)
        d[i] = fabs(sphere_light_residual(a, ka, &samples[i])) - fabs(sphere_light_residual(b, kb, &samples[i]));
    sample_mean_se(d, (int)count, mean, stderr_);
    free(d);
}

#define FIT_BLOCK 256 /* residuals per Ceres block (ceres_bridge.h: many per block is faster) */

typedef struct {
    const sphere_light_sample *samples;
    int count;
    decima_sphere_constants base;
} fit_block;

static decima_sphere_constants with_params(const decima_sphere_constants *base, const double *p)
{
    decima_sphere_constants k = *base;
    k.radius_reduction = (float)p[0], k.norm_scale = (float)p[1], k.norm_alpha = (float)p[2];
    return k;
}

/* The model computes in float, as a shader: Ceres' numeric step (1e-6
 * relative) is a few float ulps of the constants and would give
 * derivatives of rounding noise. So the Jacobian is our own central
 * difference with a step of 1e-3 (relative, at least 1e-3 absolute), where
 * float rounding is ~1e-4 of the difference. */
#define FIT_STEP 1e-3

static void residuals_at(const fit_block *b, const double *params, double *residuals)
{
    decima_sphere_constants k = with_params(&b->base, params);
    for (int i = 0; i < b->count; ++i)
        residuals[i] = sphere_light_residual(SPHERE_MODEL_DECIMA, &k, &b->samples[i]);
}

static int block_residuals(void *user, const double *params, double *residuals, double *jacobian)
{
    const fit_block *b = user;
    residuals_at(b, params, residuals);
    if (!jacobian)
        return 0;
    double plus[FIT_BLOCK], minus[FIT_BLOCK];
    for (int j = 0; j < SPHERE_FIT_PARAMS; ++j) {
        double p[SPHERE_FIT_PARAMS] = {params[0], params[1], params[2]};
        double h = FIT_STEP * fmax(1.0, fabs(params[j]));
        p[j] = params[j] + h;
        residuals_at(b, p, plus);
        p[j] = params[j] - h;
        residuals_at(b, p, minus);
        for (int i = 0; i < b->count; ++i)
            jacobian[i * SPHERE_FIT_PARAMS + j] = (plus[i] - minus[i]) / (2.0 * h);
    }
    return 0;
}

/* One Levenberg-Marquardt solve from p (overwritten with the solution);
 * with out != NULL also the covariance and the result's figures. */
static int solve_from(const sphere_light_sample *samples, size_t count, const decima_sphere_constants *base,
                      int threads, int hold_reduction, double p[SPHERE_FIT_PARAMS], double *cost,
                      sphere_light_fit_result *out, gt_error *e)
{
    size_t block_count = (count + FIT_BLOCK - 1) / FIT_BLOCK;
    fit_block *blocks = calloc(block_count, sizeof *blocks);
    gt_fit *fit = blocks ? gt_fit_create(SPHERE_FIT_PARAMS, p, e) : NULL;
    int rc = -1;
    if (!blocks) {
        gt_error_set(e, "fit sphere-light", "out of memory");
        goto done;
    }
    if (!fit)
        goto done;
    /* Bounds keep the model meaningful: a radius cannot grow with roughness
     * here, and the normalisation must stay in (0, 1]. */
    const double upper[SPHERE_FIT_PARAMS] = {4.0, 100.0, 100.0};
    for (int j = 0; j < SPHERE_FIT_PARAMS; ++j)
        if (gt_fit_set_bounds(fit, j, 0.0, upper[j], e) != 0)
            goto done;
    gt_fit_block_options own_differences = {GT_FIT_ANALYTIC, GT_FIT_LOSS_NONE, 0.0};
    for (size_t b = 0; b < block_count; ++b) {
        blocks[b].samples = samples + b * FIT_BLOCK;
        blocks[b].count = (int)(count - b * FIT_BLOCK < FIT_BLOCK ? count - b * FIT_BLOCK : FIT_BLOCK);
        blocks[b].base = *base;
        if (gt_fit_add_block(fit, blocks[b].count, block_residuals, &blocks[b], &own_differences, e) != 0)
            goto done;
    }
    if (hold_reduction && gt_fit_hold(fit, 0, 1, e) != 0)
        goto done;
    gt_fit_options options = gt_fit_default_options();
    options.threads = threads;
    gt_fit_result result;
    if (gt_fit_solve(fit, &options, &result, e) != 0)
        goto done;
    *cost = result.final_cost;
    if (out) {
        if (gt_fit_covariance(fit, out->covariance, out->stderr_, NULL, e) != 0)
            goto done;
        for (int j = 0; j < SPHERE_FIT_PARAMS; ++j)
            out->value[j] = p[j];
        out->constants = with_params(base, p);
        out->iterations = result.iterations;
        out->converged = result.success;
        out->rmse = result.rmse;
    }
    rc = 0;
done:
    if (fit)
        gt_fit_destroy(fit);
    free(blocks);
    return rc;
}

/* Least-squares parabola cost = a + b r + c r^2 through n profile points:
 * returns its vertex and curvature 2c (0 if not convex). */
static double parabola_vertex(const double *r, const double *cost, int n, double *curvature)
{
    /* Normal equations in centred r for conditioning. */
    double mean = 0.0;
    for (int i = 0; i < n; ++i)
        mean += r[i] / n;
    double s[5] = {0, 0, 0, 0, 0}, t[3] = {0, 0, 0};
    for (int i = 0; i < n; ++i) {
        double x = r[i] - mean, p = 1.0;
        for (int k = 0; k < 5; ++k) {
            if (k < 3)
                t[k] += p * cost[i];
            s[k] += p, p *= x;
        }
    }
    /* [s0 s1 s2; s1 s2 s3; s2 s3 s4] (a b c)' = t, by Cramer's rule. */
    double det = s[0] * (s[2] * s[4] - s[3] * s[3]) - s[1] * (s[1] * s[4] - s[3] * s[2]) +
                 s[2] * (s[1] * s[3] - s[2] * s[2]);
    double b = (s[0] * (t[1] * s[4] - s[3] * t[2]) - t[0] * (s[1] * s[4] - s[3] * s[2]) +
                s[2] * (s[1] * t[2] - t[1] * s[2])) / det;
    double c = (s[0] * (s[2] * t[2] - t[1] * s[3]) - s[1] * (s[1] * t[2] - t[1] * s[2]) +
                t[0] * (s[1] * s[3] - s[2] * s[2])) / det;
    *curvature = c > 0.0 ? 2.0 * c : 0.0;
    return c > 0.0 ? mean - b / (2.0 * c) : NAN;
}

/* Fills points first .. first + n - 1 of the profile: the radius reduction
 * held at r0 + k step, the normalisation fitted. Returns the best index. */
static int profile_points(const sphere_light_sample *samples, size_t count, const decima_sphere_constants *start,
                          int threads, double r0, double step, int n, double *r, double *cost, gt_error *e)
{
    int best = -1;
    for (int k = 0; k < n; ++k) {
        double p[SPHERE_FIT_PARAMS] = {fmax(0.0, r0 + step * k), start->norm_scale, start->norm_alpha};
        if (solve_from(samples, count, start, threads, 1, p, &cost[k], NULL, e) != 0)
            return -1;
        r[k] = p[0];
        if (best < 0 || cost[k] < cost[best])
            best = k;
    }
    return best;
}

int sphere_light_fit(const sphere_light_sample *samples, size_t count, const decima_sphere_constants *start,
                     int threads, sphere_light_fit_result *out, gt_error *e)
{
    /* The cost is rugged in the radius reduction: the Newton step of
     * GetNoHSquared jumps where f''(0) changes sign, and max() clamps the
     * radius, so Levenberg-Marquardt stops in whichever small local minimum
     * lies near its start (from the published 0.25 it "converged" to 0.24 on
     * one data set and 0.09 on another), and cannot polish it either. So the
     * radius reduction is profiled (held on a grid while the normalisation
     * is fitted): coarsely over [0, 0.5], then finely around the best coarse
     * point, where a least-squares parabola gives its value (the vertex) and
     * standard error (the curvature). The normalisation is then fitted with
     * the radius reduction held at the vertex. */
    const int n = SPHERE_FIT_PROFILE / 2;
    double *r = out->profile_reduction, *cost = out->profile_cost;
    int coarse = profile_points(samples, count, start, threads, 0.0, 0.05, n, r, cost, e);
    if (coarse < 0)
        return -1;
    int fine = profile_points(samples, count, start, threads, r[coarse] - 0.05, 0.01, SPHERE_FIT_PROFILE - n, r + n,
                              cost + n, e);
    if (fine < 0)
        return -1;
    double curvature, vertex = parabola_vertex(r + n, cost + n, SPHERE_FIT_PROFILE - n, &curvature);
    if (!(vertex >= r[n] && vertex <= r[SPHERE_FIT_PROFILE - 1]))
        vertex = r[n + fine]; /* not convex there: the best fine point */
    double p[SPHERE_FIT_PARAMS] = {vertex, start->norm_scale, start->norm_alpha}, final_cost;
    if (solve_from(samples, count, start, threads, 1, p, &final_cost, out, e) != 0)
        return -1;
    double sigma2 = 2.0 * final_cost / ((double)count - SPHERE_FIT_PARAMS);
    out->stderr_[0] = curvature > 0.0 ? sqrt(sigma2 / curvature) : NAN;
    out->covariance[0] = out->stderr_[0] * out->stderr_[0]; /* its covariances with the others: not estimated */
    return 0;
}
