/* The multi-bounce fit's figures as rows and numbers (multibounce/multibounce_study.h):
 * the joint linear coefficients against the talk's, the per-albedo cubics,
 * the leave-one-scene-out table, and what the findings say. */
#include <math.h>
#include <stdio.h>

#include "multibounce/multibounce_study.h"

/* The joint linear model's coefficients, the talk's beside them. */
static void coefficient_rows(const multibounce_analysis *a, multibounce_coefficient_row *rows)
{
    const multibounce_fit *f = &a->joint[MB_JOINT_LINEAR];
    const multibounce_model talk = multibounce_model_jimenez2016();
    double ours[MULTIBOUNCE_COEFFICIENTS], theirs[MULTIBOUNCE_COEFFICIENTS];
    multibounce_model_to_vector(&f->model, ours);
    multibounce_model_to_vector(&talk, theirs);
    for (int i = 0; i < MULTIBOUNCE_COEFFICIENTS; ++i) {
        multibounce_coefficient_row *r = &rows[i];
        multibounce_fit_parameter_name(f, i, r->name, sizeof r->name);
        r->rho_power = i % (f->model.degree + 1);
        r->ours = ours[i];
        r->standard_error = f->standard_errors[i];
        r->jackknife_se = a->jackknife_se[MB_JOINT_LINEAR][i];
        r->talk = theirs[i];
        r->talk_minus_ours_jackknife = (theirs[i] - ours[i]) / r->jackknife_se;
    }
}

static void albedo_row(const multibounce_albedo_result *r, multibounce_albedo_row *row)
{
    const multibounce_model talk = multibounce_model_jimenez2016();
    const multibounce_fit *f = &r->fit;
    multibounce_cubic t = multibounce_cubic_at(&talk, r->albedo);
    *row = (multibounce_albedo_row){.albedo = (double)r->albedo,
                                    .a = f->model.a[0], .se_a = f->standard_errors[0],
                                    .b = f->model.b[0], .se_b = f->standard_errors[1],
                                    .c = f->model.c[0], .se_c = f->standard_errors[2],
                                    .talk_a = t.a, .talk_b = t.b, .talk_c = t.c,
                                    .rmse_own = r->own.rmse, .rmse_joint = r->linear.rmse, .rmse_talk = r->talk.rmse,
                                    .fraction_talk_below = r->talk.below};
}

/* The held-out scenes' rows, then their mean; returns the row count. */
static int heldout_rows(const multibounce_data *d, const multibounce_analysis *a, multibounce_heldout_row *rows)
{
    for (int i = 0; i <= a->heldout_count; ++i) {
        const int mean = i == a->heldout_count;
        const multibounce_heldout *h = &a->heldout[mean ? 0 : i];
        multibounce_heldout_row *r = &rows[i];
        double rmse[MB_JOINT_COUNT];
        for (int j = 0; j < MB_JOINT_COUNT; ++j)
            rmse[j] = !a->has[j] ? NAN : mean ? a->heldout_mean[j] : h->err[j].rmse;
        snprintf(r->scene, sizeof r->scene, "%s", mean ? "mean" : d->scenes[h->scene]);
        r->is_mean = mean;
        r->rmse_linear = rmse[MB_JOINT_LINEAR];
        r->rmse_quadratic = rmse[MB_JOINT_QUADRATIC];
        r->rmse_anchored = rmse[MB_JOINT_ANCHORED];
        r->rmse_talk = mean ? a->heldout_mean_talk : h->talk.rmse;
        r->samples = mean ? d->count : h->talk.samples;
    }
    return a->heldout_count + 1;
}

static void fit_summary(const multibounce_data *d, const multibounce_analysis *a, multibounce_fit_summary *s)
{
    const multibounce_errors *ours = &a->joint_err[MB_JOINT_LINEAR][1], *talk = &a->talk_err[1];
    *s = (multibounce_fit_summary){
        .file = MULTIBOUNCE_FIT_FILE, .samples = d->count, .scenes = d->scene_count, .albedos = d->albedo_count,
        .rmse_ours = ours->rmse, .max_error_ours = ours->max_abs, .rmse_talk = talk->rmse,
        .max_error_talk = talk->max_abs, .rmse_talk_without_max = a->talk_err[0].rmse,
        .fraction_talk_cubic_below_v_d = a->talk_err[0].below, .heldout_scenes = a->heldout_count,
        .heldout_mean_rmse_linear = a->heldout_mean[MB_JOINT_LINEAR],
        .heldout_mean_rmse_quadratic = a->heldout_mean[MB_JOINT_QUADRATIC],
        .heldout_mean_rmse_anchored = a->heldout_mean[MB_JOINT_ANCHORED],
        .heldout_mean_rmse_talk = a->heldout_mean_talk, .chosen = multibounce_joint_names[a->chosen],
        .worst_albedo = (double)talk->worst.albedo, .worst_v_d = (double)talk->worst.visibility,
        .worst_v_prime_d = (double)talk->worst.multibounce};
    snprintf(s->worst_scene, sizeof s->worst_scene, "%s", d->scenes[talk->worst.scene]);
}

/* The coefficient farthest from the talk's, in our standard errors
 * (per-pixel, or jackknife over scenes). */
static int farthest_coefficient(const multibounce_coefficient_row *rows, int by_scene, double *sigmas)
{
    int worst = 0;
    *sigmas = 0.0;
    for (int i = 0; i < MULTIBOUNCE_COEFFICIENTS; ++i) {
        double z = fabs(rows[i].talk - rows[i].ours) / (by_scene ? rows[i].jackknife_se : rows[i].standard_error);
        if (z > *sigmas) {
            *sigmas = z;
            worst = i;
        }
    }
    return worst;
}

/* Largest difference between the joint linear coefficients and the talk's two-step lines. */
static double two_step_gap(const multibounce_analysis *a)
{
    double joint[MULTIBOUNCE_COEFFICIENTS], lines[MULTIBOUNCE_COEFFICIENTS], gap = 0.0;
    multibounce_model_to_vector(&a->joint[MB_JOINT_LINEAR].model, joint);
    multibounce_model_to_vector(&a->two_step, lines);
    for (int k = 0; k < MULTIBOUNCE_COEFFICIENTS; ++k)
        gap = fmax(gap, fabs(joint[k] - lines[k]));
    return gap;
}

/* How far our cubic falls below V_d: the worst of the data's albedos, and at albedo 0. */
static void our_shortfalls(const multibounce_data *d, const multibounce_model *ours, multibounce_findings *f)
{
    f->ours_worst_shortfall = -INFINITY;
    f->ours_worst_shortfall_albedo = 0.0;
    for (int k = 0; k < d->albedo_count; ++k) {
        double shortfall = multibounce_max_shortfall(ours, d->albedos[k]);
        if (shortfall > f->ours_worst_shortfall) {
            f->ours_worst_shortfall = shortfall;
            f->ours_worst_shortfall_albedo = d->albedos[k];
        }
    }
    f->ours_shortfall_zero = multibounce_max_shortfall(ours, 0.0);
}

static void findings(const multibounce_data *d, const multibounce_analysis *a,
                     const multibounce_coefficient_row *coefficients, multibounce_findings *f)
{
    const multibounce_model talk = multibounce_model_jimenez2016();
    f->farthest_pixels = farthest_coefficient(coefficients, 0, &f->farthest_pixels_sigmas);
    f->farthest_scenes = farthest_coefficient(coefficients, 1, &f->farthest_scenes_sigmas);
    f->talk_better_heldout = 0;
    for (int i = 0; i < a->heldout_count; ++i)
        f->talk_better_heldout += a->heldout[i].talk.rmse < a->heldout[i].err[MB_JOINT_LINEAR].rmse;
    f->talk_shortfall_lowest_albedo = multibounce_max_shortfall(&talk, d->albedos[0]);
    f->talk_shortfall_zero = multibounce_max_shortfall(&talk, 0.0);
    our_shortfalls(d, &a->joint[MB_JOINT_LINEAR].model, f);
    f->two_step_gap = two_step_gap(a);
}

void multibounce_study_fit_rows(const multibounce_data *d, const multibounce_analysis *a,
                                multibounce_study_result *out)
{
    fit_summary(d, a, &out->fit);
    coefficient_rows(a, out->coefficients);
    out->albedo_count = d->albedo_count;
    for (int k = 0; k < d->albedo_count; ++k)
        albedo_row(&a->per_albedo[k], &out->albedos[k]);
    out->heldout_rows = heldout_rows(d, a, out->heldout);
    findings(d, a, out->coefficients, &out->findings);
}
