/* The point AO decal's refit: see ao_decals_fit.h. */
#include "ao_decals/ao_decals_fit.h"

#include <math.h>
#include <string.h>

#include "fitters/ceres_bridge.h"

static const double lower[AO_DECAL_PARAMS] = {-3.0, 0.02, -0.9, 0.0}, upper[AO_DECAL_PARAMS] = {3.0, 20.0, 4.0, 1.0};

double ao_decal_falloff(double d, double shape, double length)
{
    double u = (d - AO_DECAL_FIT_D0) / length, x = shape * u;
    if (x <= -1.0)
        return shape > 0.0 ? HUGE_VAL : 0.0;
    /* log1p(xi u) / xi = u (1 - xi u / 2 + ...) */
    return exp(fabs(x) < 1e-6 ? -u * (1.0 - 0.5 * x) : -log1p(x) / shape);
}

void ao_decal_published_params(double params[AO_DECAL_PARAMS])
{
    params[AO_DECAL_SHAPE] = -0.5, params[AO_DECAL_LENGTH] = 0.5;
    params[AO_DECAL_WRAP] = 1.0, params[AO_DECAL_AMPLITUDE] = 1.0 / 9.0;
}

static double decal_occlusion(vec3 p, vec3 n, const ao_decal_volume *vol, const double *params)
{
    vec3 pos, norm;
    ao_decal_unit_space(p, n, vol, &pos, &norm);
    double d = v3_length(pos), w = params[AO_DECAL_WRAP];
    double cosine = d > 0.0 ? -v3_dot(pos, norm) / d : 1.0;
    double wrapped = fmax(0.0, (cosine + w) / (1.0 + w));
    if (wrapped == 0.0)
        return 0.0;
    return fmin(1.0, params[AO_DECAL_AMPLITUDE] * ao_decal_falloff(d, params[AO_DECAL_SHAPE], params[AO_DECAL_LENGTH]) *
                         wrapped);
}

double ao_decal_fit_visibility(const ao_decal_samples *s, size_t i, const double *params)
{
    double v = s->base ? s->base[i] : 1.0;
    for (int k = 0; k < s->occluder_count; ++k)
        v *= 1.0 - decal_occlusion(s->p[i], s->n[i], &s->occluders[k], params);
    return v;
}

typedef struct {
    const ao_decal_samples *set;
    double held_exponent;
} fit_block;

static int residuals(void *user, const double *params, double *r, double *jacobian)
{
    const fit_block *b = user;
    (void)jacobian;
    for (size_t i = 0; i < b->set->count; ++i)
        r[i] = ao_decal_fit_visibility(b->set, i, params) - b->set->visibility[i];
    return 0;
}

/* k = -1 / xi, s.e. |dk / dxi| se(xi) = se(xi) / xi^2. */
static void exponent_of(ao_decal_fit_result *out)
{
    double xi = out->params[AO_DECAL_SHAPE];
    out->exponent = xi < 0.0 ? -1.0 / xi : NAN;
    out->exponent_se = xi < 0.0 && out->has_covariance ? out->standard_errors[AO_DECAL_SHAPE] / (xi * xi) : NAN;
}

static void bounds_of(ao_decal_fit_result *out)
{
    for (int k = 0; k < AO_DECAL_PARAMS; ++k) {
        if (out->held_exponent > 0.0 && k == AO_DECAL_SHAPE)
            continue;
        double margin = fmin(out->params[k] - lower[k], upper[k] - out->params[k]);
        out->at_bound += margin < 1e-9;
        out->near_bound += margin < 0.01 * (upper[k] - lower[k]);
    }
}

static int setup(gt_fit *fit, const fit_block *blocks, int set_count, double held, gt_error *e)
{
    gt_fit_block_options numeric = {GT_FIT_NUMERIC, GT_FIT_LOSS_NONE, 0.0};
    int rc = 0;
    for (int k = 0; k < AO_DECAL_PARAMS && rc == 0; ++k)
        rc = gt_fit_set_bounds(fit, k, lower[k], upper[k], e);
    rc = rc == 0 && held > 0.0 ? gt_fit_hold(fit, AO_DECAL_SHAPE, 1, e) : rc;
    for (int k = 0; k < set_count && rc == 0; ++k)
        rc = gt_fit_add_block(fit, (int)blocks[k].set->count, residuals, (void *)&blocks[k], &numeric, e);
    return rc;
}

int ao_decal_fit(const ao_decal_samples *sets, int set_count, double held_exponent, ao_decal_fit_result *out,
                 gt_error *e)
{
    double p[AO_DECAL_PARAMS];
    fit_block blocks[AO_DECAL_FIT_SETS_MAX];
    memset(out, 0, sizeof *out);
    if (set_count < 1 || set_count > AO_DECAL_FIT_SETS_MAX)
        return gt_error_set(e, "ao decal fit", "%d sample sets (1 to %d)", set_count, AO_DECAL_FIT_SETS_MAX);
    ao_decal_published_params(p);
    if (held_exponent > 0.0)
        p[AO_DECAL_SHAPE] = -1.0 / held_exponent;
    for (int k = 0; k < set_count; ++k)
        blocks[k] = (fit_block){&sets[k], held_exponent};
    gt_fit *fit = gt_fit_create(AO_DECAL_PARAMS, p, e);
    if (!fit)
        return -1;
    gt_fit_result fr;
    int rc = setup(fit, blocks, set_count, held_exponent, e);
    rc = rc == 0 ? gt_fit_solve(fit, NULL, &fr, e) : rc;
    gt_error ignored;
    out->has_covariance = rc == 0 && gt_fit_covariance(fit, NULL, out->standard_errors, NULL, &ignored) == 0;
    gt_fit_destroy(fit);
    if (rc != 0)
        return -1;
    out->held_exponent = held_exponent;
    memcpy(out->params, p, sizeof p);
    out->rmse = fr.rmse, out->converged = fr.success;
    exponent_of(out);
    bounds_of(out);
    return 0;
}
