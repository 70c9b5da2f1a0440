/* Report section: GTAO, HBAO and volumetric obscurance against the
 * height-field and the 3-D AO references (gtao_validation.h),
 * rendered into the report: per scene the variants' table, where the error
 * of the talk's configuration comes from and the heatmaps; the convergence
 * plot; GTAO's parameters tuned to the 3-D references. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gtao/gtao_section.h"

#include "metrics/noise_corrected.h"
#include "report/claim_thresholds.h"
#include "report/report_headline.h"
#include "gtao/gtao_shortcuts_section.h"
#include "gtao/gtao_params_json.h"
#include "report/gnuplot_plot.h"
#include "report/report_table.h"
#include "core/files/atomic_file.h"
#include "gtao/gtao_validation.h"

static const report_column variant_columns[] = {
    REPORT_TEXT(NULL, "scene", ao_variant_row, scene),
    REPORT_TEXT("technique", "technique", ao_variant_row, label),
    REPORT_REAL("DSSIM vs height field", "dssim_heightfield", "%.4f", ao_variant_row, dssim_hf),
    REPORT_REAL("RMSE vs height field", "rmse_heightfield", "%.4f", ao_variant_row, rmse_hf),
    REPORT_REAL("DSSIM vs 3-D", "dssim_3d", "%.4f", ao_variant_row, dssim_3d),
    REPORT_RANKED("RMSE vs 3-D", "rmse_3d", "%.4f", ao_variant_row, rmse_3d, REPORT_LOWEST_BEST),
    REPORT_REAL("FLIP vs 3-D", "flip_3d", "%.4f", ao_variant_row, flip_3d),
    REPORT_REAL("ms per frame", "ms_per_frame", "%.2f", ao_variant_row, ms_per_frame),
};

static void role_cell(const void *row, char *text, size_t size)
{
    snprintf(text, size, "%s", ((const gtao_fit_score *)row)->held_out ? "held out" : "training");
}

static const report_column fit_score_columns[] = {
    REPORT_TEXT("scene", NULL, gtao_fit_score, scene),
    REPORT_CELL("role", role_cell),
    REPORT_REAL("DSSIM before", NULL, "%.4f", gtao_fit_score, dssim_before),
    REPORT_REAL("DSSIM after", NULL, "%.4f", gtao_fit_score, dssim_after),
    REPORT_REAL("RMSE before", NULL, "%.4f", gtao_fit_score, rmse_before),
    REPORT_REAL("RMSE after", NULL, "%.4f", gtao_fit_score, rmse_after),
};

#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

static void render_introduction(report *doc, const gtao_validation_result *r)
{
    char budget[96] = "";
    if (r->heightfield_noise_budget > 0)
        snprintf(budget, sizeof budget, " at most, a pixel stopping at its noise budget, a standard error of %g",
                 r->heightfield_noise_budget);
    report_heading(doc, 2, "GTAO, HBAO and volumetric obscurance against two references");
    report_paragraph(doc,
                     "Each technique runs on the G-buffer of the AO references (same camera, same pixels) with no "
                     "radius limit (the references have none; the screen radius is the image width, no falloff), "
                     "VO with a sphere of a quarter of the camera's distance to its target. Scores are against (a) the height-field Monte Carlo reference (rays "
                     "blocked only by the depth buffer taken as a height field of infinite thickness; %d samples "
                     "per pixel%s), which GTAO computes exactly given enough slices and samples (tested), so the "
                     "distance to it is sampling and denoising error; and (b) the 3-D ray-traced reference, which "
                     "adds the height-field assumption's error. 'N frames' is the temporal accumulation over N frames "
                     "of the talk's pattern with a static camera (24 is its full cycle; the preview stops at 6); ms "
                     "are per frame on this machine, shared with other work. Brute-force GTAO (the reference "
                     "preset's exact horizons, one frame) runs at every quality, with fewer slices at preview; the "
                     "baselines' converged runs at production quality only.",
                     r->heightfield_spp, budget);
}

/* A noise-corrected RMSE, or the plain fact that it is within the noise. */
static void noise_corrected_text(double rmse, char *text, size_t size)
{
    if (rmse > 0.0)
        snprintf(text, size, "%.4f", rmse);
    else
        snprintf(text, size, "below the references' noise");
}

/* How brute-force GTAO stands against the height-field reference: within
 * its noise, above it by less than a viewer could see, or by more. */
typedef enum { EXACT_WITHIN_NOISE, EXACT_INVISIBLE, EXACT_UNEXPLAINED } exact_standing;

static const char *const exact_standing_names[] = {"within the noise", "below one 8-bit code value", "unexplained"};

static exact_standing exact_standing_of(const ao_error_split *x)
{
    if (x->exact_sampling_rmse <= 0.0)
        return EXACT_WITHIN_NOISE;
    return x->exact_sampling_rmse < CLAIM_ONE_CODE_VALUE_8BIT ? EXACT_INVISIBLE : EXACT_UNEXPLAINED;
}

static void exact_json(cJSON *list, const gtao_validation_scene *s, const char *run, exact_standing standing)
{
    const ao_error_split *x = &s->split;
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "scene", s->scene);
    cJSON_AddStringToObject(o, "run", run);
    cJSON_AddNumberToObject(o, "rmse_vs_heightfield", x->exact_rmse_hf);
    cJSON_AddNumberToObject(o, "rmse_less_noise", x->exact_sampling_rmse);
    cJSON_AddNumberToObject(o, "heightfield_noise_rmse", x->hf_noise_rmse);
    cJSON_AddBoolToObject(o, "within_noise", standing == EXACT_WITHIN_NOISE);
    cJSON_AddStringToObject(o, "standing", exact_standing_names[standing]);
    cJSON_AddItemToArray(list, o);
}

void gtao_exact_horizons_statement(report *doc, cJSON *list, const gtao_validation_scene *s)
{
    const ao_variant_row *exact = gtao_validation_find(s, AO_TECHNIQUE_GTAO, GTAO_PRESET_REFERENCE, 0);
    const ao_error_split *x = &s->split;
    if (!exact || !x->exact_valid)
        return;
    exact_standing standing = exact_standing_of(x);
    exact_json(list, s, exact->label, standing);
    char measured[512];
    if (standing == EXACT_UNEXPLAINED) {
        report_paragraph(doc,
                         "%s (one frame) is RMSE %.4f from the height-field reference, %.4f once "
                         "the reference's noise (RMSE %.4f) is taken out: more than one 8-bit code value, a "
                         "difference between GTAO and the reference the tests do not explain, so the converged "
                         "presets' gap is not only their horizon search's steps.",
                         exact->label, x->exact_rmse_hf, x->exact_sampling_rmse, x->hf_noise_rmse);
        return;
    }
    if (standing == EXACT_WITHIN_NOISE)
        snprintf(measured, sizeof measured,
                 "%s (brute force, one frame) is RMSE %.4f from the height-field reference, within the "
                 "reference's own noise (RMSE %.4f), as the tests prove it must be.",
                 exact->label, x->exact_rmse_hf, x->hf_noise_rmse);
    else
        snprintf(measured, sizeof measured,
                 "%s (brute force, one frame) is RMSE %.4f from the height-field reference, %.4f once the "
                 "reference's noise (RMSE %.4f) is taken out: less than one 8-bit code value, equal for a viewer.",
                 exact->label, x->exact_rmse_hf, x->exact_sampling_rmse, x->hf_noise_rmse);
    if (x->converged_sampling_rmse < CLAIM_ONE_CODE_VALUE_8BIT) {
        report_paragraph(doc, "%s The converged presets are as close (less than one 8-bit code value once the noise "
                              "is taken out): there is no gap here to explain.",
                         measured);
        return;
    }
    report_paragraph(doc,
                     "%s What separates the converged presets from the reference is therefore their horizon "
                     "search's steps, not a difference between GTAO and the reference: a horizon is the highest of "
                     "the samples taken along the slice, and a few samples per side over a radius of the image's "
                     "width miss the nearest occluders, so GTAO errs towards too little occlusion and the error "
                     "falls only as the steps per side grow (the convergence figure on boxes at the end of this "
                     "section).",
                     measured);
}

/* Where the error of the talk's configuration comes from, in words. */
static void render_statement(report *doc, const gtao_validation_scene *s)
{
    const ao_variant_row *medium = gtao_validation_find(s, AO_TECHNIQUE_GTAO, GTAO_PRESET_MEDIUM, 0);
    const ao_variant_row *ultra = gtao_validation_find(s, AO_TECHNIQUE_GTAO, GTAO_PRESET_ULTRA, 1);
    const ao_error_split *x = &s->split;
    if (!medium || !ultra || !x->valid)
        return;
    char model_text[64], sampling_text[64], converged_text[64];
    noise_corrected_text(x->model_rmse, model_text, sizeof model_text);
    noise_corrected_text(x->sampling_rmse, sampling_text, sizeof sampling_text);
    noise_corrected_text(x->converged_sampling_rmse, converged_text, sizeof converged_text);
    report_paragraph(doc,
                     "%s: the height-field assumption alone (height-field reference vs 3-D reference) costs RMSE "
                     "%.4f (%s once both references' Monte Carlo noise is taken out; DSSIM %.4f, the height-field "
                     "reference's own noise floor being DSSIM %.4f). GTAO in the talk's configuration (medium, one "
                     "frame) is RMSE %.4f from the height-field reference (%s without its noise: sampling and "
                     "denoising) and %.4f from the 3-D reference. In squared error, %.0f%% of the two parts is "
                     "sampling/denoising and %.0f%% the height-field assumption. Converged (%s), the sampling "
                     "part falls to RMSE %.4f (%s without the reference's noise).",
                     s->scene, s->hf_vs_3d_rmse, model_text, s->hf_vs_3d_dssim, s->hf_noise_floor_dssim,
                     medium->rmse_hf, sampling_text, medium->rmse_3d, x->sampling_percent, x->model_percent,
                     ultra->label, ultra->rmse_hf, converged_text);
}

/* The references, GTAO and the errors of one scene in a comparison view. */
static void render_heatmaps(report *doc, const char *scene)
{
    static const char *const stems[6] = {"ao", "gtao_hf", "gtao_medium", "gtao_err_hf_vs_3d", "gtao_err_medium_vs_hf",
                                         "gtao_err_medium_vs_3d"};
    static const char *const what[6] = {"3-D reference", "height-field reference", "GTAO medium (1 frame)",
                                        "|height field - 3-D|", "|GTAO medium - height field|", "|GTAO medium - 3-D|"};
    char paths[6][256], caption[256];
    const char *p[6];
    for (int k = 0; k < 6; ++k) {
        snprintf(paths[k], sizeof paths[k], "figures/%s_%s.png", stems[k], scene);
        p[k] = paths[k];
    }
    snprintf(caption, sizeof caption, "%s: the references, GTAO medium and their |errors| (0 to 0.25)", scene);
    report_comparison(doc, 6, p, what, 3, caption);
}

/* Whether x runs in real time: every variant but brute-force GTAO (exact
 * horizons through every pixel cell, seconds a frame), which is the bound
 * the real-time variants approach, not one of them. */
static int real_time_variant(const ao_variant_row *x)
{
    return !(x->technique == AO_TECHNIQUE_GTAO && x->preset == GTAO_PRESET_REFERENCE);
}

/* The lowest RMSE of a real-time variant on scene s, against the 3-D
 * reference (against_3d) or the height field. */
static double best_real_time_rmse(const gtao_validation_scene *s, int against_3d)
{
    double best = NAN;
    for (int v = 0; v < s->variant_count; ++v) {
        const ao_variant_row *x = &s->variants[v];
        double rmse = against_3d ? x->rmse_3d : x->rmse_hf;
        if (real_time_variant(x) && (isnan(best) || rmse < best))
            best = rmse;
    }
    return best;
}

/* Each reference's noise beside the figures it supports, against the
 * budget of the scene's best real-time figure (issue 46 item 1); into
 * summary.json's gtao_reference_noise too. */
static void render_reference_noise(report *doc, cJSON *list, const gtao_validation_scene *s)
{
    double noise_3d = sqrt(s->ref3d_mean_variance), noise_hf = sqrt(s->hf_mean_variance);
    double best_3d = best_real_time_rmse(s, 1), best_hf = best_real_time_rmse(s, 0);
    char text_3d[HEADLINE_TEXT], text_hf[HEADLINE_TEXT];
    noise_budget_phrase(noise_3d, best_3d, CLAIM_ONE_CODE_VALUE_8BIT, text_3d, sizeof text_3d);
    noise_budget_phrase(noise_hf, best_hf, CLAIM_ONE_CODE_VALUE_8BIT, text_hf, sizeof text_hf);
    report_paragraph(doc, "The references' noise on %s: the 3-D reference's %s (its best real-time RMSE %.4f); the "
                          "height field's %s (%.4f). A budget is the most noise under which a figure reads within a "
                          "quarter of one 8-bit code value.",
                     s->scene, text_3d, best_3d, text_hf, best_hf);
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "scene", s->scene);
    cJSON_AddNumberToObject(o, "noise_rmse_3d", noise_3d);
    cJSON_AddNumberToObject(o, "budget_3d", noise_budget_for_measured_rmse(best_3d, noise_3d, CLAIM_ONE_CODE_VALUE_8BIT));
    cJSON_AddNumberToObject(o, "noise_rmse_heightfield", noise_hf);
    cJSON_AddNumberToObject(o, "budget_heightfield",
                            noise_budget_for_measured_rmse(best_hf, noise_hf, CLAIM_ONE_CODE_VALUE_8BIT));
    cJSON_AddItemToArray(list, o);
}

static void render_scene(report *doc, cJSON *list, cJSON *exact, cJSON *noise, const gtao_validation_scene *s)
{
    report_heading(doc, 3, s->scene);
    report_rows(doc, list, variant_columns, COUNT(variant_columns), s->variants, sizeof s->variants[0],
                s->variant_count);
    render_reference_noise(doc, noise, s);
    render_statement(doc, s);
    gtao_exact_horizons_statement(doc, exact, s);
    render_heatmaps(doc, s->scene);
}

/* RMSE against slices x steps from the study's data file, solid against the
 * height field and dashed against the 3-D reference, one line per steps. */
static int render_convergence(report_context *ctx, const char *scene, gt_error *e)
{
    char data[4096], png[4096], script[16384];
    snprintf(data, sizeof data, "%s/%s/%s", ctx->study.output_dir, GTAO_VALIDATION_DIR, GTAO_CONVERGENCE_DATA);
    snprintf(png, sizeof png, "%s/figures/gtao_convergence.png", ctx->study.output_dir);
    snprintf(script, sizeof script,
             "set termoption font ',12'\n" /* the figure's font since it was first drawn */
             "set logscale xy\nset xlabel 'slices x samples per side'\nset ylabel 'RMSE'\n"
             "set title 'GTAO on %s: regular slices, no denoiser'\nset key outside\n"
             "plot for [i=0:3] '%s' index i using 3:4 with linespoints title sprintf('vs height field, %%d steps', 2**(i+1)), "
             "for [i=0:3] '%s' index i using 3:5 with lines dashtype 2 title sprintf('vs 3-D, %%d steps', 2**(i+1))\n",
             scene, data, data);
    if (gnuplot_render(script, png, 800, 500, e) != 0)
        return -1;
    char caption[128];
    snprintf(caption, sizeof caption, "GTAO error against slices x samples (%s)", scene);
    const char *p[1] = {"figures/gtao_convergence.png"}, *c[1] = {caption};
    report_paragraph(ctx->doc,
                     "Convergence of brute-force GTAO on %s: RMSE against the height-field reference (solid) "
                     "and the 3-D reference (dashed). Data: gtao/gtao_convergence.dat.",
                     scene);
    report_figures(ctx->doc, 1, p, c);
    return 0;
}

/* The fit as gtao/params_fit.json (the format of `gtlab fit gtao-params`)
 * and as the summary's gtao_parameter_fit.parameter_fit. */
static int write_fit(report_context *ctx, const gtao_validation_result *r, gt_error *e)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s/params_fit.json", ctx->study.output_dir, GTAO_VALIDATION_DIR);
    cJSON *fit = gtao_fit_json(&r->fit_request, &r->fit);
    char *text = cJSON_Print(fit);
    int rc = text ? atomic_write_text(path, text, e) : gt_error_set(e, path, "out of memory");
    free(text);
    cJSON_AddItemToObject(cJSON_AddObjectToObject(ctx->summary, "gtao_parameter_fit"), "parameter_fit", fit);
    return rc;
}

void gtao_fit_bound_explanation(const gtao_fit_result *r, char *text, size_t size)
{
    static const char *const names[GTAO_FIT_PARAMS] = {"the radius", "the falloff", "the thickness"};
    char which[128] = "";
    int count = 0;
    for (int k = 0; k < GTAO_FIT_PARAMS; ++k)
        if (gtao_fit_at_bound(r, k) != 0) {
            size_t used = strlen(which);
            snprintf(which + used, sizeof which - used, "%s%s", count ? " and " : "", names[k]);
            ++count;
        }
    static const char *const heuristics[4] = {
        "", " (a falloff of 0 is no fade: on these scenes the fit wants none)",
        " (a thickness of 0 is no thickness heuristic: on these scenes the fit wants none)",
        " (a falloff of 0 is no fade, a thickness of 0 no thickness heuristic: on these scenes the fit wants "
        "neither)"};
    const int off = (gtao_fit_at_bound(r, 1) < 0) | (gtao_fit_at_bound(r, 2) < 0) << 1;
    text[0] = '\0';
    if (count)
        snprintf(text, size,
                 " %c%s end%s on the edge of the fit's range: the objective still falls towards the edge, so the "
                 "data want %s past what the range allows%s, and the standard error there is only the local "
                 "curvature, not an interval.",
                 toupper((unsigned char)which[0]), which + 1, count == 1 ? "s" : "", count == 1 ? "it" : "them",
                 heuristics[off]);
}

static void render_fit(report *doc, const gtao_fit_request *rq, const gtao_fit_result *r)
{
    char bounds[512];
    gtao_fit_bound_explanation(r, bounds, sizeof bounds);
    report_heading(doc, 3, "Parameters tuned to the 3-D references");
    report_paragraph(doc,
                     "'gtlab fit gtao-params --refs ao' (Ceres, DSSIM objective, %s preset, %d iterations%s): radius "
                     "%.3f +- %.3f of the camera's distance to its target (start %.2f), falloff %.3f +- %.3f (start "
                     "%.2f), thickness %.3f +- %.3f (start %.2f); standard errors treat pixels as independent and "
                     "are optimistic.%s Fitted on %s; held out: %s.",
                     rq->preset, r->iterations, r->converged ? "" : ", not converged", r->value[0], r->se[0],
                     r->start[0], r->value[1], r->se[1], r->start[1], r->value[2], r->se[2], r->start[2], bounds,
                     rq->train, rq->test);
    report_rows(doc, NULL, fit_score_columns, COUNT(fit_score_columns), r->scores, sizeof r->scores[0],
                r->score_count);
    int better = 0, held_out = 0;
    for (int i = 0; i < r->score_count; ++i) {
        const gtao_fit_score *x = &r->scores[i];
        held_out += x->held_out;
        better += x->held_out && x->dssim_after < x->dssim_before;
    }
    report_finding(doc, "GTAO auto-tune",
                   "Tuning GTAO's radius, falloff and thickness by DSSIM on %d scene%s lowers DSSIM on %d of the %d "
                   "held-out scenes (radius %.2f of the camera distance, falloff %.2f, thickness %.2f%s).",
                   r->score_count - held_out, r->score_count - held_out == 1 ? "" : "s", better, held_out,
                   r->value[0], r->value[1], r->value[2], bounds[0] ? "; see the section on the range's edge" : "");
}


/* The summary table's row: the real-time variants (by label, as run on the
 * first scene) ranked by their mean RMSE against the 3-D reference over
 * the scenes, the gap's interval from the per-scene differences. */
void gtao_headline(report *doc, const gtao_validation_result *r)
{
    const gtao_validation_scene *first = &r->scenes[0];
    const char *labels[GTAO_VALIDATION_MAX_VARIANTS];
    double rmse[GTAO_VALIDATION_MAX_VARIANTS * GTAO_VALIDATION_MAX_SCENES];
    int scenes = r->scene_count, ranked = 0;
    for (int v = 0; v < first->variant_count; ++v) {
        const ao_variant_row *x = &first->variants[v];
        if (!real_time_variant(x))
            continue;
        labels[ranked] = x->label;
        for (int i = 0; i < scenes; ++i) {
            const ao_variant_row *y = gtao_validation_find(&r->scenes[i], x->technique, x->preset, x->converged);
            rmse[ranked * scenes + i] = y ? y->rmse_3d : NAN;
        }
        ++ranked;
    }
    report_headline h = {.topic = "GTAO, HBAO, VO", .significance = HEADLINE_NOT_COMPUTED,
                         .margin = CLAIM_ONE_CODE_VALUE_8BIT}; /* RMSE of an 8-bit AO target */
    char over[64];
    snprintf(h.measure, sizeof h.measure, "mean RMSE vs the 3-D reference (%d scenes; real-time variants, no radius limit, "
             "as the references)", scenes);
    snprintf(over, sizeof over, "paired over %d scenes", scenes);
    double variance = 0.0;
    for (int i = 0; i < scenes; ++i)
        variance += r->scenes[i].ref3d_mean_variance / scenes;
    if (scenes > 0 && headline_rank_paired(&h, ranked, labels, rmse, scenes, over) == 0) {
        headline_state_reference_noise(&h, sqrt(variance));
        report_add_headline(doc, &h);
    }
}

int gtao_section(report_context *ctx, const gtao_validation_result *r, gt_error *e)
{
    render_introduction(ctx->doc, r);
    cJSON *list = cJSON_AddArrayToObject(ctx->summary, "gtao");
    cJSON *exact = cJSON_AddArrayToObject(ctx->summary, "gtao_exact_horizons");
    cJSON *noise = cJSON_AddArrayToObject(ctx->summary, "gtao_reference_noise");
    for (int i = 0; i < r->scene_count; ++i)
        render_scene(ctx->doc, list, exact, noise, &r->scenes[i]);
    if (render_convergence(ctx, r->convergence_scene, e) != 0 || write_fit(ctx, r, e) != 0)
        return -1;
    render_fit(ctx->doc, &r->fit_request, &r->fit);
    gtao_headline(ctx->doc, r);
    gtao_shortcuts_section(ctx, &r->shortcuts);
    return 0;
}
