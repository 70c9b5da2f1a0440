/* The point AO decal's refit: see ao_decals_fit.h. */
#include "fitters/ao_decals_fit.h"

#include <math.h>
#include <string.h>

#include "fitters/ceres_bridge.h"
#include "realtime/ao_decals.h"

static const double lower[AO_DECAL_PARAMS] = {0.5, 0.1, 0.0, 0.0}, upper[AO_DECAL_PARAMS] = {20.0, 8.0, 4.0, 2.0};

double ao_decal_fit_visibility(const ao_decal_samples *s, size_t i, const double *params)
{
    vec3 pos = v3_scale(v3_sub(s->centre, s->p[i]), (float)(1.0 / params[0]));
    return 1.0 - params[3] * ao_point_decal(pos, s->n[i], (float)params[1], (float)params[2]);
}

static int residuals(void *user, const double *params, double *r, double *jacobian)
{
    const ao_decal_samples *s = user;
    (void)jacobian;
    for (size_t i = 0; i < s->count; ++i)
        r[i] = ao_decal_fit_visibility(s, i, params) - s->visibility[i];
    return 0;
}

int ao_decal_fit(const ao_decal_samples *s, double start_radius, ao_decal_fit_result *out, gt_error *e)
{
    double p[AO_DECAL_PARAMS] = {start_radius, 2.0, 1.0, 1.0};
    memset(out, 0, sizeof *out);
    gt_fit *fit = gt_fit_create(AO_DECAL_PARAMS, p, e);
    if (!fit)
        return -1;
    gt_fit_block_options numeric = {GT_FIT_NUMERIC, GT_FIT_LOSS_NONE, 0.0};
    int rc = 0;
    for (int k = 0; k < AO_DECAL_PARAMS && rc == 0; ++k)
        rc = gt_fit_set_bounds(fit, k, lower[k], upper[k], e);
    gt_fit_result fr;
    rc = rc == 0 ? gt_fit_add_block(fit, (int)s->count, residuals, (void *)s, &numeric, e) : rc;
    rc = rc == 0 ? gt_fit_solve(fit, NULL, &fr, e) : rc;
    gt_fit_destroy(fit);
    if (rc != 0)
        return -1;
    memcpy(out->params, p, sizeof p);
    out->rmse = fr.rmse, out->converged = fr.success;
    for (int k = 0; k < AO_DECAL_PARAMS; ++k) {
        double margin = fmin(p[k] - lower[k], upper[k] - p[k]);
        out->at_bound += margin < 1e-9;
        out->near_bound += margin < 0.01 * (upper[k] - lower[k]);
    }
    return 0;
}
