#include "fitters/fit_sphere_light.h"

#include <math.h>
#include <stdlib.h>

#include "fitters/ceres_bridge.h"

double sphere_light_residual(sphere_light_model model, const decima_sphere_constants *k,
                             const sphere_light_sample *s)
{
    double value = model == SPHERE_MODEL_KARIS ? karis_sphere_ggx(s->v, s->lc, s->sin_sigma, s->alpha)
                                               : decima_sphere_ggx_local(s->v, s->lc, s->sin_sigma, s->alpha, k, 1);
    return log((value + SPHERE_FIT_FLOOR) / (s->reference + SPHERE_FIT_FLOOR));
}

void sphere_light_measure(sphere_light_model model, const decima_sphere_constants *k,
                          const sphere_light_sample *samples, size_t count, sphere_light_errors *out)
{
    double sum_abs = 0, sum_abs2 = 0, sum_sq = 0, sum_sq2 = 0;
    for (size_t i = 0; i < count; ++i) {
        double r = sphere_light_residual(model, k, &samples[i]);
        sum_abs += fabs(r), sum_abs2 += r * r;
        sum_sq += r * r, sum_sq2 += r * r * r * r;
    }
    double n = (double)count;
    double mean_abs = sum_abs / n, mean_sq = sum_sq / n;
    out->mean_abs = mean_abs;
    out->mean_abs_stderr = sqrt(fmax(0.0, sum_abs2 / n - mean_abs * mean_abs) / (n - 1.0));
    out->rms = sqrt(mean_sq);
    double mean_sq_stderr = sqrt(fmax(0.0, sum_sq2 / n - mean_sq * mean_sq) / (n - 1.0));
    out->rms_stderr = out->rms > 0.0 ? mean_sq_stderr / (2.0 * out->rms) : 0.0;
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

int sphere_light_fit(const sphere_light_sample *samples, size_t count, const decima_sphere_constants *start,
                     int threads, sphere_light_fit_result *out, gt_error *e)
{
    double p[SPHERE_FIT_PARAMS] = {start->radius_reduction, start->norm_scale, start->norm_alpha};
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
        blocks[b].base = *start;
        if (gt_fit_add_block(fit, blocks[b].count, block_residuals, &blocks[b], &own_differences, e) != 0)
            goto done;
    }
    gt_fit_options options = gt_fit_default_options();
    options.threads = threads;
    gt_fit_result result;
    if (gt_fit_solve(fit, &options, &result, e) != 0 ||
        gt_fit_covariance(fit, out->covariance, out->stderr_, NULL, e) != 0)
        goto done;
    for (int j = 0; j < SPHERE_FIT_PARAMS; ++j)
        out->value[j] = p[j];
    out->constants = with_params(start, p);
    out->iterations = result.iterations;
    out->converged = result.success;
    out->rmse = result.rmse;
    rc = 0;
done:
    if (fit)
        gt_fit_destroy(fit);
    free(blocks);
    return rc;
}
