/* Report section: the GTAO multi-bounce refit (Jimenez et al. 2016,
 * "Multiple Bounces" to "Shader Code"; issue 3; multibounce/multibounce_study.h)
 * rendered into the report: the fit's coefficients against the talk's, the
 * per-albedo cubics, the leave-one-scene-out table, what the data show, the
 * gnuplot figures, the validation against the references and the
 * performance; the same figures in summary.json. */
#include <math.h>
#include <stdio.h>

#include "multibounce/multibounce_section.h"

#include "multibounce/multibounce_section_parts.h"
#include "multibounce/multibounce_study.h"
#include "report/claim_thresholds.h"
#include "report/gnuplot_plot.h"
#include "report/report_table.h"

#define COLUMNS(c) (int)(sizeof(c) / sizeof((c)[0]))

/* ---- Cells ---------------------------------------------------------------------------------- */

static void coefficient_name_cell(const void *row, char *text, size_t size)
{
    const multibounce_coefficient_row *r = row;
    snprintf(text, size, "%s%s", r->name, r->rho_power ? " (x rho)" : "");
}

static void a_cell(const void *row, char *text, size_t size)
{
    const multibounce_albedo_row *r = row;
    snprintf(text, size, "%.3f ± %.3f", r->a, r->se_a);
}

static void b_cell(const void *row, char *text, size_t size)
{
    const multibounce_albedo_row *r = row;
    snprintf(text, size, "%.3f ± %.3f", r->b, r->se_b);
}

static void c_cell(const void *row, char *text, size_t size)
{
    const multibounce_albedo_row *r = row;
    snprintf(text, size, "%.3f ± %.3f", r->c, r->se_c);
}

static void talk_cubic_cell(const void *row, char *text, size_t size)
{
    const multibounce_albedo_row *r = row;
    snprintf(text, size, "%.3f, %.3f, %.3f", r->talk_a, r->talk_b, r->talk_c);
}

static void talk_below_cell(const void *row, char *text, size_t size)
{
    snprintf(text, size, "%.1f%%", 100.0 * ((const multibounce_albedo_row *)row)->fraction_talk_below);
}

/* An RMSE, or "n/a" for a model the data could not determine (NAN). */
static void rmse_or_na(double rmse, char *text, size_t size)
{
    if (isnan(rmse))
        snprintf(text, size, "n/a");
    else
        snprintf(text, size, "%.4f", rmse);
}

static void heldout_linear_cell(const void *row, char *text, size_t size)
{
    rmse_or_na(((const multibounce_heldout_row *)row)->rmse_linear, text, size);
}

static void heldout_quadratic_cell(const void *row, char *text, size_t size)
{
    rmse_or_na(((const multibounce_heldout_row *)row)->rmse_quadratic, text, size);
}

static void heldout_anchored_cell(const void *row, char *text, size_t size)
{
    rmse_or_na(((const multibounce_heldout_row *)row)->rmse_anchored, text, size);
}

/* ---- Columns -------------------------------------------------------------------------------- */

static const report_column coefficient_columns[] = {
    REPORT_CELL("coefficient", coefficient_name_cell),
    REPORT_REAL("gtlab joint fit", NULL, "%.4f", multibounce_coefficient_row, ours),
    REPORT_REAL("standard error (pixels)", NULL, "%.4f", multibounce_coefficient_row, standard_error),
    REPORT_REAL("jackknife s.e. (scenes)", NULL, "%.4f", multibounce_coefficient_row, jackknife_se),
    REPORT_REAL("talk", NULL, "%.4f", multibounce_coefficient_row, talk),
    REPORT_REAL("talk - ours in jackknife s.e.", NULL, "%.1f", multibounce_coefficient_row,
                talk_minus_ours_jackknife),
};

static const report_column albedo_columns[] = {
    REPORT_REAL("albedo", NULL, "%.1f", multibounce_albedo_row, albedo),
    REPORT_CELL("a", a_cell),
    REPORT_CELL("b", b_cell),
    REPORT_CELL("c", c_cell),
    REPORT_CELL("talk a, b, c", talk_cubic_cell),
    REPORT_REAL("RMSE own cubic", NULL, "%.4f", multibounce_albedo_row, rmse_own),
    REPORT_REAL("RMSE joint", NULL, "%.4f", multibounce_albedo_row, rmse_joint),
    REPORT_REAL("RMSE talk", NULL, "%.4f", multibounce_albedo_row, rmse_talk),
    REPORT_CELL("talk cubic < V_d", talk_below_cell),
};

static const report_column heldout_columns[] = {
    REPORT_TEXT("held-out scene", NULL, multibounce_heldout_row, scene),
    REPORT_CELL("RMSE joint linear", heldout_linear_cell),
    REPORT_CELL("RMSE joint quadratic", heldout_quadratic_cell),
    REPORT_CELL("RMSE joint anchored", heldout_anchored_cell),
    REPORT_REAL("RMSE talk", NULL, "%.4f", multibounce_heldout_row, rmse_talk),
    REPORT_COUNT("samples", NULL, multibounce_heldout_row, samples),
};

static const report_column validation_columns[] = {
    REPORT_TEXT("scene", "scene", multibounce_validation_row, scene),
    REPORT_REAL("albedo", "albedo", "%.1f", multibounce_validation_row, albedo),
    REPORT_REAL("DSSIM floor", "noise_floor_dssim", "%.2e", multibounce_validation_row, noise_floor_dssim),
    REPORT_REAL("DSSIM V_d", "dssim_v_d", "%.2e", multibounce_validation_row, dssim_v_d),
    REPORT_REAL("DSSIM talk", "dssim_talk", "%.2e", multibounce_validation_row, dssim_talk),
    REPORT_REAL("DSSIM ours", "dssim_ours", "%.2e", multibounce_validation_row, dssim_ours),
    REPORT_REAL(NULL, "dssim_ours_held_out", NULL, multibounce_validation_row, dssim_ours_held_out),
    REPORT_REAL("RMSE floor", "noise_floor_rmse", "%.4f", multibounce_validation_row, noise_floor_rmse),
    REPORT_REAL("RMSE V_d", "rmse_v_d", "%.4f", multibounce_validation_row, rmse_v_d),
    REPORT_REAL("RMSE talk", "rmse_talk", "%.4f", multibounce_validation_row, rmse_talk),
    REPORT_REAL("RMSE ours", "rmse_ours", "%.4f", multibounce_validation_row, rmse_ours),
    REPORT_REAL("RMSE ours (held out)", "rmse_ours_held_out", "%.4f", multibounce_validation_row,
                rmse_ours_held_out),
};

static const report_column render_columns[] = {
    REPORT_TEXT(NULL, "scene", multibounce_render_row, scene),
    REPORT_REAL(NULL, "seconds", NULL, multibounce_render_row, seconds),
    REPORT_COUNT(NULL, "paths", multibounce_render_row, paths),
    REPORT_COUNT(NULL, "rays", multibounce_render_row, rays),
    REPORT_REAL(NULL, "mean_spp", NULL, multibounce_render_row, mean_spp),
    REPORT_REAL(NULL, "noise_rmse", NULL, multibounce_render_row, noise_rmse),
};

/* summary.json's "multibounce" object: figures of the whole study. */
static const report_column summary_columns[] = {
    REPORT_STRING(NULL, "fit", multibounce_study_result, fit.file),
    REPORT_COUNT(NULL, "samples", multibounce_study_result, fit.samples),
    REPORT_REAL(NULL, "rmse_ours", NULL, multibounce_study_result, fit.rmse_ours),
    REPORT_REAL(NULL, "rmse_talk", NULL, multibounce_study_result, fit.rmse_talk),
    REPORT_REAL(NULL, "rmse_talk_without_max", NULL, multibounce_study_result, fit.rmse_talk_without_max),
    REPORT_REAL(NULL, "fraction_talk_cubic_below_v_d", NULL, multibounce_study_result,
                fit.fraction_talk_cubic_below_v_d),
    REPORT_REAL(NULL, "heldout_mean_rmse_linear", NULL, multibounce_study_result, fit.heldout_mean_rmse_linear),
    REPORT_REAL(NULL, "heldout_mean_rmse_quadratic", NULL, multibounce_study_result,
                fit.heldout_mean_rmse_quadratic),
    REPORT_REAL(NULL, "heldout_mean_rmse_talk", NULL, multibounce_study_result, fit.heldout_mean_rmse_talk),
    REPORT_REAL(NULL, "heldout_mean_rmse_anchored", NULL, multibounce_study_result,
                fit.heldout_mean_rmse_anchored),
    REPORT_STRING(NULL, "chosen", multibounce_study_result, fit.chosen),
    REPORT_REAL(NULL, "paths_per_s_1_thread", NULL, multibounce_study_result, performance.paths_per_s_1_thread),
    REPORT_REAL(NULL, "rays_per_s_1_thread", NULL, multibounce_study_result, performance.rays_per_s_1_thread),
    REPORT_REAL(NULL, "raw_intersect1_rays_per_s_1_thread", NULL, multibounce_study_result,
                performance.raw_intersect1_rays_per_s_1_thread),
    REPORT_REAL(NULL, "one_pass_seconds", NULL, multibounce_study_result, performance.one_pass_seconds),
    REPORT_REAL(NULL, "separate_renders_seconds", NULL, multibounce_study_result,
                performance.separate_renders_seconds),
    REPORT_REAL(NULL, "joint_fit_solve_seconds", NULL, multibounce_study_result,
                performance.joint_fit_solve_seconds),
};

/* ---- summary.json --------------------------------------------------------------------------- */

/* The "multibounce" object: the study's figures, the joint linear
 * coefficients and their standard errors as arrays, and the renders. */
static cJSON *add_summary(report_context *ctx, const multibounce_study_result *r)
{
    cJSON *o = report_object(ctx->summary, "multibounce", summary_columns, COLUMNS(summary_columns), r);
    double p[MULTIBOUNCE_COEFFICIENTS], se[MULTIBOUNCE_COEFFICIENTS];
    for (int i = 0; i < MULTIBOUNCE_COEFFICIENTS; ++i) {
        p[i] = r->coefficients[i].ours;
        se[i] = r->coefficients[i].standard_error;
    }
    cJSON_AddItemToObject(o, "joint_linear", cJSON_CreateDoubleArray(p, MULTIBOUNCE_COEFFICIENTS));
    cJSON_AddItemToObject(o, "joint_linear_standard_errors", cJSON_CreateDoubleArray(se, MULTIBOUNCE_COEFFICIENTS));
    report_rows(NULL, cJSON_AddArrayToObject(o, "renders"), render_columns, COLUMNS(render_columns), r->renders,
                sizeof r->renders[0], MULTIBOUNCE_STUDY_SCENES);
    return o;
}

/* ---- Sections ------------------------------------------------------------------------------- */

/* "the 5 built-in scenes (sphere-on-plane, corner, ...)", and that they are
 * not a project's when there is one: the stage keeps gtlab's own scenes. */
static void scenes_text(const report_context *ctx, const multibounce_study_result *r, char *text, size_t size)
{
    int n = snprintf(text, size, "%d built-in scenes (", MULTIBOUNCE_STUDY_SCENES);
    for (int k = 0; k < MULTIBOUNCE_STUDY_SCENES && n > 0 && (size_t)n < size; ++k)
        n += snprintf(text + n, size - (size_t)n, "%s%s", k ? ", " : "", r->renders[k].scene);
    if (n > 0 && (size_t)n < size)
        snprintf(text + n, size - (size_t)n, ")%s",
                 ctx->study.project ? ", gtlab's own and not the project's: this stage does not take a project's scenes"
                                    : "");
}

/* "each pixel's paths stopping at its noise budget, a standard error of ...
 * (at most N paths; M on average)", or "N paths per pixel" without a budget:
 * how the references were sampled. */
static void sampling_text(const multibounce_study_result *r, char *text, size_t size)
{
    if (r->noise_budget > 0)
        snprintf(text, size,
                 "each pixel's paths stopping at its noise budget, a standard error of %g in V'_d at albedo %.1f "
                 "(at most %d paths; %.0f on average)",
                 r->noise_budget, (double)r->albedo_values[0], r->spp, r->mean_spp);
    else
        snprintf(text, size, "%d paths per pixel", r->spp);
}

static void intro(report_context *ctx, const multibounce_study_result *r)
{
    char scenes[512], sampling[256], noise[256];
    scenes_text(ctx, r, scenes, sizeof scenes);
    sampling_text(r, sampling, sizeof sampling);
    noise_budget_phrase(r->noise_rmse, fmin(r->fit.heldout_mean_rmse_linear, r->fit.heldout_mean_rmse_talk),
                        CLAIM_ONE_CODE_VALUE_8BIT, noise, sizeof noise);
    report_heading(ctx->doc, 2, "Multi-bounce AO: references and the GTAO refit");
    report_paragraph(ctx->doc,
                     "Jimenez et al. 2016 ('Multiple Bounces'): V'_d = L / rho of a Lambertian surface of albedo rho "
                     "under a white dome, every surface of albedo rho, %d bounces (inter-reflections after the first "
                     "hit, the talk's 4), against the single-bounce V_d of the same paths. One pass per scene serves "
                     "all %d albedos (0.1 to 0.9; the talk does not list its seven). The %s, at %dx%d, %s: "
                     "%.3g paths and %.3g rays in %.1f s. Fit (gtlab fit multibounce; "
                     "fits/multibounce.json, .h, .hlsl): per albedo V'_d = ((a V_d + b) V_d + c) V_d, and jointly "
                     "a, b, c linear in rho fitted to all samples at once through Ceres, each scene and albedo "
                     "weighted equally; standard errors from Ceres' covariance (pixels taken as independent) and, "
                     "more telling, the jackknife over scenes. V_d itself carries Monte Carlo noise (errors in the "
                     "variable the fit takes as exact), which flattens fitted curves slightly, and V'_d's noise "
                     "inflates every RMSE against it: for the held-out figures the references (V'_d, every albedo "
                     "weighted as the fit weighs them) have %s (V_d of the same paths shares part of that noise, "
                     "so the residual may carry less).",
                     r->bounces, MULTIBOUNCE_STUDY_ALBEDOS, scenes, r->width, r->height, sampling, r->total_paths,
                     r->total_rays, r->total_seconds, noise);
}

static void fit_tables(report_context *ctx, const multibounce_study_result *r)
{
    report_rows(ctx->doc, NULL, coefficient_columns, COLUMNS(coefficient_columns), r->coefficients,
                sizeof r->coefficients[0], MULTIBOUNCE_COEFFICIENTS);
    report_heading(ctx->doc, 3, "Per albedo");
    report_rows(ctx->doc, NULL, albedo_columns, COLUMNS(albedo_columns), r->albedos, sizeof r->albedos[0],
                r->albedo_count);
    report_heading(ctx->doc, 3, "Leave one scene out");
    report_rows(ctx->doc, NULL, heldout_columns, COLUMNS(heldout_columns), r->heldout, sizeof r->heldout[0],
                r->heldout_rows);
}

/* The summary table's row: the linear refit against the talk's
 * coefficients, each scored on scenes it was not fitted to; the jackknife
 * over scenes says whether the two coefficient sets differ. */
static void add_headline(report *doc, const multibounce_study_result *r)
{
    const multibounce_fit_summary *s = &r->fit;
    const char *labels[2] = {"refit (linear in rho)", "the talk's coefficients"};
    const double errors[2] = {s->heldout_mean_rmse_linear, s->heldout_mean_rmse_talk};
    report_headline h = {.topic = "GTAO multi-bounce", .margin = CLAIM_ONE_CODE_VALUE_8BIT};
    snprintf(h.measure, sizeof h.measure, "held-out weighted RMSE (mean of %d scenes)", s->heldout_scenes);
    if (headline_rank(&h, 2, labels, errors) != 0)
        return;
    double sigmas = r->findings.farthest_scenes_sigmas;
    h.significance = sigmas > CLAIM_Z ? HEADLINE_SIGNIFICANT : HEADLINE_NOT_SIGNIFICANT;
    snprintf(h.basis, sizeof h.basis, "the talk's coefficients at most %.1f jackknife s.e. from the refit's", sigmas);
    headline_apply_margin(&h, errors[1] - errors[0], 0.0);
    headline_state_reference_noise(&h, r->noise_rmse);
    report_add_headline(doc, &h);
}

static void findings(report_context *ctx, const multibounce_study_result *r)
{
    const multibounce_fit_summary *s = &r->fit;
    const multibounce_findings *f = &r->findings;
    const multibounce_albedo_row *low = &r->albedos[0], *high = &r->albedos[r->albedo_count - 1];
    report_paragraph(
        ctx->doc,
        "What the data show. On %llu samples (%d scenes x %d albedos, every scene and albedo weighted equally) "
        "the talk's coefficients give a weighted RMSE of %.4f (max error %.3f); our joint refit of the same "
        "form gives %.4f (max %.3f), and one cubic per albedo %.4f at albedo %.1f to %.4f at %.1f. Our "
        "coefficients differ from the talk's by up to %.0f of their per-pixel standard errors (%s): on these "
        "scenes the talk's numbers are not the least-squares optimum, though the curves they give are close "
        "(a, b and c are strongly correlated). The per-pixel standard errors treat pixels as independent; "
        "the jackknife over scenes (from the leave-one-scene-out fits) measures how much the coefficients move "
        "with the content, and by it the talk's coefficients are at most %.1f standard errors (%s) from ours: "
        "within the spread of content. Generalisation: "
        "fitted without a scene and scored on it, our linear model's RMSE averages %.4f over the %d scenes "
        "against %.4f for the talk's (the talk's is better on %d of them): one curve does not serve all "
        "content to better than a few hundredths, and the scene-to-scene spread is larger than the difference "
        "between the two coefficient sets. Alternatives, held out the same way: a, b, c quadratic in the albedo "
        "%.4f, the anchored form (exact at albedo 0 and V_d = 0, 1, 4 parameters) %.4f; chosen: %s. The max(V_d, "
        ".): the talk's cubic falls below V_d by up to %.4f at albedo %.1f and by up to %.3f at albedo 0; on "
        "the data it is lower than V_d by more than 0.001 for %.1f%% of the weighted samples, and the max "
        "changes its RMSE from %.5f to %.5f. So the max is a guard for albedos below about 0.1, where the "
        "talk's linear coefficients fall short of V'_d >= V_d; at the talk's albedos it changes little. Our "
        "refit's cubic falls below V_d by up to %.4f (albedo %.1f) and %.3f at albedo 0. The largest errors are "
        "not noise: the talk's worst pixel (%s, albedo %.1f) has V_d = %.3f but V'_d = %.3f. Where a point sees "
        "little sky but much lit surface (contacts, crevices facing bright walls), V'_d is not a function of "
        "V_d, and no curve in V_d alone can follow it. The talk's own procedure (lines through the per-albedo "
        "coefficients) gives the joint fit's coefficients to %.1e here: when every albedo is rendered on the "
        "same pixels with the same weights, as one multi-bounce pass does, least squares decomposes that way "
        "exactly; a joint fit differs only where the albedos' samples differ.",
        (unsigned long long)s->samples, s->scenes, s->albedos, s->rmse_talk, s->max_error_talk, s->rmse_ours,
        s->max_error_ours, low->rmse_own, low->albedo, high->rmse_own, high->albedo, f->farthest_pixels_sigmas,
        r->coefficients[f->farthest_pixels].name, f->farthest_scenes_sigmas, r->coefficients[f->farthest_scenes].name,
        s->heldout_mean_rmse_linear, s->heldout_scenes, s->heldout_mean_rmse_talk, f->talk_better_heldout,
        s->heldout_mean_rmse_quadratic, s->heldout_mean_rmse_anchored, s->chosen, f->talk_shortfall_lowest_albedo,
        low->albedo, f->talk_shortfall_zero, 100.0 * s->fraction_talk_cubic_below_v_d, s->rmse_talk_without_max,
        s->rmse_talk, f->ours_worst_shortfall, f->ours_worst_shortfall_albedo, f->ours_shortfall_zero,
        s->worst_scene, s->worst_albedo, s->worst_v_d, s->worst_v_prime_d, f->two_step_gap);
    const multibounce_coefficient_row *c = r->coefficients;
    report_finding(ctx->doc, "GTAO multi-bounce",
                   "refit a = %.3f %+.3f rho, b = %.3f %+.3f rho, c = %.3f %+.3f rho; weighted RMSE %.4f against "
                   "the talk's %.4f on the same data; fitted without the scene scored, %.4f against %.4f (the "
                   "talk's better on %d of %d scenes); the talk's coefficients lie within %.1f jackknife standard "
                   "errors of ours.",
                   c[0].ours, c[1].ours, c[2].ours, c[3].ours, c[4].ours, c[5].ours, s->rmse_ours, s->rmse_talk,
                   s->heldout_mean_rmse_linear, s->heldout_mean_rmse_talk, f->talk_better_heldout, s->heldout_scenes,
                   f->farthest_scenes_sigmas);
    add_headline(ctx->doc, r);
}

/* ---- Figures -------------------------------------------------------------------------------- */

static int plot_scatter(const report_context *ctx, const multibounce_study_result *r, gt_error *e)
{
    char points[4096], curves[4096], png[4096], script[16384];
    const char *out = ctx->study.output_dir;
    snprintf(points, sizeof points, "%s/figures/%s", out, MULTIBOUNCE_SCATTER_DATA);
    snprintf(curves, sizeof curves, "%s/figures/%s", out, MULTIBOUNCE_CURVES_DATA);
    snprintf(png, sizeof png, "%s/figures/multibounce_scatter.png", out);
    size_t used = (size_t)snprintf(script, sizeof script,
                                   "set multiplot layout 2,4 title \"V'_d against V_d, 4 bounces, %d scenes\"\n"
                                   "set xrange [0:1]\nset yrange [0:1]\nset key top left font ',8'\n"
                                   "set xlabel 'V_d'\nset ylabel \"V'_d\"\nset grid\n",
                                   r->fit.scenes);
    for (int k = 0; k < r->albedo_count; ++k)
        used += (size_t)snprintf(script + used, sizeof script - used,
                                 "set title 'albedo %.1f'\n"
                                 "plot '%s' index %d using 1:2 with points pt 7 ps 0.15 lc rgb '#a0a0a0' title "
                                 "'samples', '%s' index %d using 1:2 with lines lw 2 lc rgb '#d62728' title 'talk', "
                                 "'' index %d using 1:3 with lines lw 2 lc rgb '#1f77b4' title 'gtlab joint', "
                                 "'' index %d using 1:4 with lines lw 1 dt 2 lc rgb '#2ca02c' title 'own cubic', "
                                 "x with lines dt 3 lc rgb 'black' title 'V_d'\n",
                                 r->albedos[k].albedo, points, k, curves, k, k, k);
    snprintf(script + used, sizeof script - used, "unset multiplot\n");
    return gnuplot_render(script, png, 1600, 850, e);
}

static int plot_coefficients(const report_context *ctx, gt_error *e)
{
    char data[4096], png[4096], script[8192];
    snprintf(data, sizeof data, "%s/figures/%s", ctx->study.output_dir, MULTIBOUNCE_COEFFICIENTS_DATA);
    snprintf(png, sizeof png, "%s/figures/multibounce_coefficients.png", ctx->study.output_dir);
    size_t used = (size_t)snprintf(script, sizeof script,
                                   "set multiplot layout 1,3 title 'cubic coefficients against the albedo'\n"
                                   "set xrange [0:1]\nset xlabel 'albedo'\nset grid\nset key bottom left font ',8'\n");
    for (int c = 0; c < 3; ++c)
        used += (size_t)snprintf(script + used, sizeof script - used,
                                 "set title '%c'\n"
                                 "plot '%s' index 0 using 1:%d:%d with yerrorbars pt 7 lc rgb 'black' title "
                                 "'per-albedo fit (± s.e.)', '' index 1 using 1:%d with lines lw 2 lc rgb "
                                 "'#1f77b4' title 'gtlab joint linear', '' index 1 using 1:%d with lines lw 2 "
                                 "lc rgb '#d62728' title 'talk', '' index 1 using 1:%d with lines dt 2 lc rgb "
                                 "'#2ca02c' title 'gtlab joint quadratic', '' index 1 using 1:%d with lines dt 4 "
                                 "lc rgb '#9467bd' title 'gtlab joint anchored'\n",
                                 "abc"[c], data, 2 + 2 * c, 3 + 2 * c, 2 + c, 5 + c, 8 + c, 11 + c);
    snprintf(script + used, sizeof script - used, "unset multiplot\n");
    return gnuplot_render(script, png, 1500, 500, e);
}

static void figures_section(report_context *ctx, const multibounce_study_result *r)
{
    if (!gnuplot_available()) {
        gt_warn("gtlab all", "gnuplot not found: multi-bounce plots skipped (Debian package gnuplot-nox)");
        report_paragraph(ctx->doc, "(Plots skipped: gnuplot was not found.)");
        return;
    }
    gt_error e;
    const char *paths[2] = {"figures/multibounce_scatter.png", "figures/multibounce_coefficients.png"};
    const char *captions[2] = {"per albedo: samples (V_d, V'_d) of every scene, the talk's curve, our joint "
                               "fit and the albedo's own cubic",
                               "a, b, c of the per-albedo cubics (± standard error) and the joint models"};
    if (plot_scatter(ctx, r, &e) != 0 || plot_coefficients(ctx, &e) != 0) {
        gt_warn("gtlab all", "plot failed: %s", e.message);
        report_paragraph(ctx->doc, "(Plots failed: %s)", e.message);
        return;
    }
    report_figures(ctx->doc, 1, &paths[0], &captions[0]);
    report_figures(ctx->doc, 1, &paths[1], &captions[1]);
}

/* ---- Validation and performance ------------------------------------------------------------ */

static void validation_section(report_context *ctx, const multibounce_study_result *r, cJSON *summary)
{
    report_heading(ctx->doc, 3, "Validation against the references");
    report_paragraph(ctx->doc,
                     "For each scene and albedo, the multi-bounce reference V'_d against: V_d alone (no "
                     "multi-bounce term), the talk's polynomial and our joint refit, each applied to V_d with the "
                     "shader's max(V_d, .), and our refit made without the scene (the out-of-sample figure). V_d "
                     "and V'_d of one render come from the same paths and share their noise, so the "
                     "approximations take V_d from the even-index samples and are scored against V'_d of the "
                     "odd-index samples; the noise floors (DSSIM and RMSE) score the even half of V'_d against the "
                     "odd half: the score of an estimate exact but for noise like the reference's. An "
                     "approximation whose input V_d is less noisy than V'_d (at high albedos) can score below it; "
                     "the floor says how finely this comparison can separate approximations.");
    report_rows(ctx->doc, cJSON_AddArrayToObject(summary, "validation"), validation_columns,
                COLUMNS(validation_columns), r->validation, sizeof r->validation[0], r->validation_count);
    const multibounce_validation_row *m = &r->validation_mean;
    report_paragraph(ctx->doc,
                     "Means over the %d scene-albedo pairs: DSSIM %.2e (floor), %.2e (V_d), %.2e (talk), %.2e "
                     "(ours), %.2e (ours, scene held out); RMSE %.4f (floor), %.4f, %.4f, %.4f, %.4f.",
                     r->validation_count, m->noise_floor_dssim, m->dssim_v_d, m->dssim_talk, m->dssim_ours,
                     m->dssim_ours_held_out, m->noise_floor_rmse, m->rmse_v_d, m->rmse_talk, m->rmse_ours,
                     m->rmse_ours_held_out);
}

static void performance_section(report_context *ctx, const multibounce_performance *p)
{
    report_heading(ctx->doc, 3, "Performance");
    report_paragraph(ctx->doc,
                     "On %s (%dx%d, %d paths per pixel, %d albedos; 'gtlab bench multibounce' measures the same "
                     "at any size): the multi-bounce loop traces %.3g paths/s and %.3g rays/s on one core, raw "
                     "Embree closest-hit queries (rtcIntersect1) on the paths' first rays %.3g rays/s: a ratio of "
                     "%.2f (the loop also samples directions, interpolates hit normals and accumulates %d channels). "
                     "With %d threads: %.3g paths/s. All %d albedos in one pass took %.2f s against %.2f s for one "
                     "render per albedo: %.1fx cheaper. The joint fit of this stage (%llu samples, blocks of %d) "
                     "solved in %.2f s; 'gtlab bench fit' times a million samples.",
                     p->scene, p->width, p->height, p->spp, p->albedos, p->paths_per_s_1_thread,
                     p->rays_per_s_1_thread, p->raw_intersect1_rays_per_s_1_thread, p->loop_to_raw_ratio,
                     p->channels, p->threads, p->paths_per_s_threads, p->albedos, p->one_pass_seconds,
                     p->separate_renders_seconds, p->one_pass_speedup, (unsigned long long)p->fit_samples,
                     p->fit_block, p->joint_fit_solve_seconds);
}

int multibounce_section(report_context *ctx, const multibounce_study_result *r, gt_error *e)
{
    (void)e; /* a plot that fails is said in the report */
    cJSON *summary = add_summary(ctx, r);
    intro(ctx, r);
    fit_tables(ctx, r);
    findings(ctx, r);
    figures_section(ctx, r);
    validation_section(ctx, r, summary);
    multibounce_clamp_section(ctx, r, summary);
    multibounce_bounces_section(ctx, r, summary);
    multibounce_gtao_section(ctx, r, summary);
    multibounce_contrast_section(ctx, r, summary);
    multibounce_colour_section(ctx, r, summary);
    performance_section(ctx, &r->performance);
    return 0;
}
