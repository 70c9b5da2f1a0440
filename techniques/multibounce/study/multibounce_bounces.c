/* The bounce count (multibounce/multibounce_study.h, multibounce_bounce_study; issue
 * 25, item 3): references at 1, 2, 4 and unlimited bounces, the joint
 * linear refit of each with its jackknife over scenes, and the distance of
 * the talk's curve to each refit. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "multibounce/multibounce_parts.h"
#include "multibounce/multibounce_quality.h"
#include "multibounce/multibounce_quantity.h"
#include "scene/scene_loaders.h"

static const int kBounces[MULTIBOUNCE_BOUNCE_COUNTS] = {1, 2, 4, MULTIBOUNCE_UNLIMITED};
enum { FOUR = 2 }; /* the row of the study's own references */

/* Scene `spec` at its default camera (as the study renders it) into d. */
static int render_into(const study_context *ctx, const reference_request *req, const char *spec,
                       multibounce_data *d, double *seconds, gt_error *e)
{
    scene s;
    if (scene_load(spec, &s, e) != 0)
        return -1;
    int size = multibounce_quality_of(ctx->quality)->image_width;
    camera cam;
    image img;
    render_stats stats;
    int rc = scene_choose_camera(&s, NULL, size, 0, &cam, e);
    if (rc == 0)
        rc = reference_render(&s, spec, &cam, req, &img, &stats, e);
    scene_free(&s);
    if (rc != 0)
        return -1;
    *seconds += stats.seconds;
    rc = multibounce_data_add_image(d, &img, spec, e);
    image_free(&img);
    return rc;
}

static int render_bounces(const study_context *ctx, const reference_request *base, int bounces,
                          const char *const *scenes, multibounce_data *d, double *seconds, gt_error *e)
{
    multibounce_render_settings mb = {{QUANTITY_MULTIBOUNCE}, *multibounce_settings_of(base)};
    mb.multibounce.bounces = bounces;
    reference_request req = *base;
    req.settings = &mb.header;
    multibounce_data_init(d);
    for (int k = 0; k < MULTIBOUNCE_STUDY_SCENES; ++k) {
        char spec[128];
        snprintf(spec, sizeof spec, "builtin:%s", scenes[k]);
        if (render_into(ctx, &req, spec, d, seconds, e) != 0)
            return -1;
    }
    multibounce_data_weigh(d);
    return 0;
}

/* RMS over V_d = i/100, rho = 0.1 .. 0.9 (step 0.01) of talk - m, both with the max. */
static double talk_distance(const multibounce_model *m)
{
    const multibounce_model talk = multibounce_model_jimenez2016();
    double sum = 0.0;
    int n = 0;
    for (int j = (int)lround(100 * MULTIBOUNCE_DISTANCE_ALBEDO_MIN); j <= (int)lround(100 * MULTIBOUNCE_DISTANCE_ALBEDO_MAX); ++j)
        for (int i = 0; i <= 100; ++i, ++n) {
            double r = gtao_multibounce(&talk, i / 100.0, j / 100.0) - gtao_multibounce(m, i / 100.0, j / 100.0);
            sum += r * r;
        }
    return sqrt(sum / n);
}

/* The weighted means of V'_d - V_d and RMSEs of V_d, the talk and the refit. */
static void measure_row(const multibounce_data *d, const multibounce_model *refit, multibounce_bounce_row *row)
{
    const multibounce_model talk = multibounce_model_jimenez2016(), identity = {.degree = 0, .c = {1.0}};
    multibounce_errors err;
    multibounce_measure(d, refit, 1, &err);
    row->rmse_refit = err.rmse;
    multibounce_measure(d, &talk, 1, &err);
    row->rmse_talk = err.rmse;
    multibounce_measure(d, &identity, 1, &err);
    row->rmse_v_d = err.rmse;
    double sum_w = 0.0, sum = 0.0;
    for (size_t i = 0; i < d->count; ++i) {
        sum_w += d->samples[i].weight;
        sum += d->samples[i].weight * (d->samples[i].multibounce - d->samples[i].visibility);
    }
    row->mean_gain = sum_w > 0 ? sum / sum_w : 0.0;
}

/* The refit without each scene: its coefficients and distance (jackknife replicas). */
static int leave_out(const multibounce_data *d, double params[][MULTIBOUNCE_COEFFICIENTS], double *distance,
                     gt_error *e)
{
    const multibounce_fit_options model_only = {0, 1};
    for (int s = 0; s < d->scene_count; ++s) {
        multibounce_data train;
        multibounce_fit fit;
        if (multibounce_data_select(d, s, 1, -1, &train, e) != 0)
            return -1;
        int rc = multibounce_fit_model(&train, 1, &model_only, &fit, e);
        multibounce_data_free(&train);
        if (rc != 0)
            return -1;
        multibounce_model_to_vector(&fit.model, params[s]);
        distance[s] = talk_distance(&fit.model);
    }
    return 0;
}

/* sqrt((S-1)/S sum (x_s - mean)^2) */
static double jackknife_se(const double *x, size_t stride, int n)
{
    double mean = 0.0, sum_sq = 0.0;
    for (int s = 0; s < n; ++s)
        mean += x[(size_t)s * stride] / n;
    for (int s = 0; s < n; ++s)
        sum_sq += (x[(size_t)s * stride] - mean) * (x[(size_t)s * stride] - mean);
    return sqrt((n - 1.0) / n * sum_sq);
}

typedef struct {
    double params[MBFIT_MAX_SCENES][MULTIBOUNCE_COEFFICIENTS];
    double distance[MBFIT_MAX_SCENES];
} bounce_replicas;

/* One bounce count's row from its data, and its jackknife replicas. */
static int analyse_row(const multibounce_data *d, multibounce_bounce_row *row, bounce_replicas *rep, gt_error *e)
{
    multibounce_fit fit;
    if (multibounce_fit_model(d, 1, &(multibounce_fit_options){0, 1}, &fit, e) != 0 ||
        leave_out(d, rep->params, rep->distance, e) != 0)
        return -1;
    multibounce_model_to_vector(&fit.model, row->coefficients);
    for (int k = 0; k < MULTIBOUNCE_COEFFICIENTS; ++k)
        row->jackknife_se[k] = jackknife_se(&rep->params[0][k], MULTIBOUNCE_COEFFICIENTS, d->scene_count);
    row->talk_distance = talk_distance(&fit.model);
    row->talk_distance_se = jackknife_se(rep->distance, 1, d->scene_count);
    measure_row(d, &fit.model, row);
    return 0;
}

/* Which refit the talk is closest to, and 4 bounces against the best other count. */
static void compare_counts(const bounce_replicas *rep, int scenes, multibounce_bounce_study *out)
{
    out->closest = 0;
    out->best_other = FOUR == 0 ? 1 : 0;
    for (int i = 0; i < MULTIBOUNCE_BOUNCE_COUNTS; ++i) {
        if (out->rows[i].talk_distance < out->rows[out->closest].talk_distance)
            out->closest = i;
        if (i != FOUR && out->rows[i].talk_distance < out->rows[out->best_other].talk_distance)
            out->best_other = i;
    }
    double diff[MBFIT_MAX_SCENES];
    for (int s = 0; s < scenes; ++s)
        diff[s] = rep[FOUR].distance[s] - rep[out->best_other].distance[s];
    out->four_minus_best_other = out->rows[FOUR].talk_distance - out->rows[out->best_other].talk_distance;
    out->four_minus_best_other_se = jackknife_se(diff, 1, scenes);
}

int multibounce_study_bounces(const study_context *ctx, const reference_request *req, const multibounce_state *st,
                              const char *const *scenes, multibounce_bounce_study *out, gt_error *e)
{
    bounce_replicas rep[MULTIBOUNCE_BOUNCE_COUNTS];
    memset(out, 0, sizeof *out);
    out->path_limit = MULTIBOUNCE_PATH_LIMIT;
    int rc = 0;
    for (int i = 0; i < MULTIBOUNCE_BOUNCE_COUNTS && rc == 0; ++i) {
        multibounce_bounce_row *row = &out->rows[i];
        multibounce_settings s = {.bounces = kBounces[i]};
        multibounce_bounces_text(&s, row->bounces, sizeof row->bounces);
        if (i == FOUR) {
            rc = analyse_row(&st->data, row, &rep[i], e);
            continue;
        }
        multibounce_data d;
        rc = render_bounces(ctx, req, kBounces[i], scenes, &d, &row->render_seconds, e);
        if (rc == 0)
            rc = analyse_row(&d, row, &rep[i], e);
        multibounce_data_free(&d);
    }
    if (rc == 0)
        compare_counts(rep, st->data.scene_count, out);
    return rc;
}
