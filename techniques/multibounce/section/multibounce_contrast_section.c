/* The multi-bounce section's subsection on the model's premise (issue 25,
 * item 1; multibounce/multibounce_study.h, multibounce_contrast_study): albedo
 * contrast against uniform albedo, the neighbourhood correction held out,
 * and the claims row. */
#include <math.h>
#include <stdio.h>

#include "multibounce/multibounce_section_parts.h"
#include "report/report_table.h"

#define COLUMNS(c) (int)(sizeof(c) / sizeof((c)[0]))

static const report_column contrast_columns[] = {
    REPORT_TEXT("scene", "scene", multibounce_contrast_row, scene),
    REPORT_REAL("floor albedo", "floor_albedo", "%.1f", multibounce_contrast_row, floor_albedo),
    REPORT_REAL("object albedo", "object_albedo", "%.1f", multibounce_contrast_row, object_albedo),
    REPORT_REAL("premise RMS, objects", "premise_rms_object", "%.4f", multibounce_contrast_row, premise_rms_object),
    REPORT_REAL("premise RMS, floor", "premise_rms_floor", "%.4f", multibounce_contrast_row, premise_rms_floor),
    REPORT_REAL("RMSE f, uniform", "rmse_uniform", "%.4f", multibounce_contrast_row, rmse_uniform),
    REPORT_REAL("RMSE f, contrast", "rmse_contrast", "%.4f", multibounce_contrast_row, rmse_contrast),
    REPORT_REAL("RMSE f corrected (held out)", "rmse_corrected_held_out", "%.4f", multibounce_contrast_row,
                rmse_corrected_held_out),
};

static const report_column summary_columns[] = {
    REPORT_INT(NULL, "radius_px", multibounce_contrast_study, radius_px),
    REPORT_REAL(NULL, "weight", NULL, multibounce_contrast_study, weight),
    REPORT_REAL(NULL, "mean_rmse_uniform", NULL, multibounce_contrast_study, mean_rmse_uniform),
    REPORT_REAL(NULL, "mean_rmse_contrast", NULL, multibounce_contrast_study, mean_rmse_contrast),
    REPORT_REAL(NULL, "mean_rmse_corrected", NULL, multibounce_contrast_study, mean_rmse_corrected),
    REPORT_REAL(NULL, "premise_cost", NULL, multibounce_contrast_study, premise_cost),
    REPORT_REAL(NULL, "premise_cost_se", NULL, multibounce_contrast_study, premise_cost_se),
    REPORT_REAL(NULL, "correction_gain", NULL, multibounce_contrast_study, correction_gain),
    REPORT_REAL(NULL, "correction_gain_se", NULL, multibounce_contrast_study, correction_gain_se),
};

/* The talk states the premise as the assumption that replaces "single
 * bounce": measured where it does not hold, no verdict. */
static const claim_record kPremise = {
    .talk = MB_TALK, .seed = "001", .section = "Relaxing the Assumptions",
    .quote = "and replace it with the assumption that the albedo for the point being shaded is similar to that in "
             "the close neighborhood.",
    .setting = MB_SETTING, .setting_match = CLAIM_SETTING_GTLAB, .setting_note = MB_SETTING_NOTE,
    .reading = "The fit assumes the neighbours share the shaded point's albedo; where they do not (dark objects on "
               "a white floor, white on dark) f(V_d, local albedo) errs by more than on uniform scenes, by the "
               "figure.",
    .form = CLAIM_ASSUMPTION, .tolerance_source = CLAIM_TOLERANCE_NONE};

static void add_claim(report_context *ctx, const multibounce_study_result *r)
{
    const multibounce_contrast_study *c = &r->contrast;
    claims_table_add(ctx->claims, &kPremise, c->premise_cost, c->premise_cost_se,
                     "RMSE of the talk's f on albedo-contrast scenes minus on the same pixels of uniform scenes at "
                     "each pixel's albedo, mean over %d scene-contrast pairs (jackknife s.e. over scenes)",
                     c->count);
}

void multibounce_contrast_section(report_context *ctx, const multibounce_study_result *r, cJSON *summary)
{
    const multibounce_contrast_study *c = &r->contrast;
    report_heading(ctx->doc, 3, "The premise: neighbouring albedos like the point's own");
    report_paragraph(
        ctx->doc,
        "Per-object-albedo references (the scene's albedos, %d bounces, the study's cameras and samples) of "
        "scenes whose floor and objects differ, against the study's uniform references at each pixel's own "
        "albedo: the same paths, so V_d is the same and any difference in V'_d is the neighbours' albedo. "
        "'premise RMS' is that difference on object and floor pixels; 'RMSE f' is the talk's f(V_d, local "
        "albedo) against V'_d of the contrast and of the uniform scene (V_d from the even samples, V'_d from the "
        "odd). The correction a shader can afford: rho_eff = rho + w (mean albedo over the %dx%d pixels around "
        "- rho), from the albedo G-buffer; w (closed-form least squares, f being linear in rho) is %.3f on all "
        "scenes, and each row is scored with w fitted without its scene.",
        r->bounces, 2 * c->radius_px + 1, 2 * c->radius_px + 1, c->weight);
    report_rows(ctx->doc, cJSON_AddArrayToObject(summary, "contrast"), contrast_columns, COLUMNS(contrast_columns),
                c->rows, sizeof c->rows[0], c->count);
    report_paragraph(ctx->doc,
                     "Means over the rows: RMSE %.4f (uniform), %.4f (contrast), %.4f (contrast, corrected, held "
                     "out). The premise, which the talk states as an assumption (a limitation measured, no verdict), costs "
                     "%+.4f ± %.4f in RMSE; the correction changes the contrast scenes' "
                     "RMSE by %+.4f ± %.4f (jackknife over the %d scenes).",
                     c->mean_rmse_uniform, c->mean_rmse_contrast, c->mean_rmse_corrected, c->premise_cost,
                     c->premise_cost_se, c->correction_gain, c->correction_gain_se, MULTIBOUNCE_CONTRAST_SCENES);
    report_object(summary, "contrast_summary", summary_columns, COLUMNS(summary_columns), c);
    add_claim(ctx, r);
}
