/* The multi-bounce section's subsection on "agnostic to the source of the
 * AO as long as it is ground truth" (issue 25, item 5; issue 42;
 * studies/multibounce.h, multibounce_gtao_study): the talk's f on two
 * ground-truth sources, the 3-D and the height-field references, each scored
 * on the light it adds, and the claims row; then, outside the claim (GTAO's
 * V_d is not ground truth), f on GTAO's V_d and GTAO's share of the error. */
#include <math.h>
#include <stdio.h>

#include "report/multibounce_section_parts.h"
#include "report/report_table.h"

#define COLUMNS(c) (int)(sizeof(c) / sizeof((c)[0]))

static void share_cell(const void *row, char *text, size_t size)
{
    const multibounce_gtao_row *r = row;
    snprintf(text, size, "%.1f%% ± %.1f%%", 100.0 * r->gtao_share, 100.0 * r->gtao_share_se);
}

static void difference_cell(const void *row, char *text, size_t size)
{
    const multibounce_gtao_row *r = row;
    snprintf(text, size, "%+.4f ± %.4f", r->difference, r->difference_se);
}

static const report_column gtao_columns[] = {
    REPORT_TEXT("GTAO preset", "preset", multibounce_gtao_row, preset),
    REPORT_REAL("RMSE GTAO V_d vs reference V_d", "rmse_gtao_v_d", "%.4f", multibounce_gtao_row, rmse_gtao_v_d),
    REPORT_REAL("RMSE f(GTAO V_d)", "rmse_gtao_input", "%.4f", multibounce_gtao_row, rmse_gtao_input),
    REPORT_REAL("RMSE f(reference V_d)", "rmse_reference_input", "%.4f", multibounce_gtao_row,
                rmse_reference_input),
    REPORT_CELL("difference", difference_cell),
    REPORT_CELL("GTAO's share of the squared error", share_cell),
    REPORT_REAL(NULL, "difference", NULL, multibounce_gtao_row, difference),
    REPORT_REAL(NULL, "difference_se", NULL, multibounce_gtao_row, difference_se),
    REPORT_REAL(NULL, "gtao_share", NULL, multibounce_gtao_row, gtao_share),
    REPORT_REAL(NULL, "gtao_share_se", NULL, multibounce_gtao_row, gtao_share_se),
};

static const report_column agnostic_columns[] = {
    REPORT_INT(NULL, "heightfield_spp", multibounce_agnostic, spp),
    REPORT_REAL(NULL, "gain_rmse_3d", NULL, multibounce_agnostic, gain_rmse_3d),
    REPORT_REAL(NULL, "gain_rmse_heightfield", NULL, multibounce_agnostic, gain_rmse_hf),
    REPORT_REAL(NULL, "difference", NULL, multibounce_agnostic, difference),
    REPORT_REAL(NULL, "difference_se", NULL, multibounce_agnostic, difference_se),
    REPORT_REAL(NULL, "rmse_heightfield_v_d", NULL, multibounce_agnostic, rmse_hf_v_d),
    REPORT_REAL(NULL, "rmse_total_3d", NULL, multibounce_agnostic, rmse_total_3d),
    REPORT_REAL(NULL, "rmse_total_heightfield", NULL, multibounce_agnostic, rmse_total_hf),
};

/* "Agnostic" read literally: the same change, whichever ground truth feeds
 * f, to within a code value either way. Both changes are scored against the
 * 3-D truth's (there is no height-field multi-bounce reference), so the
 * verdict is at most "fails under gtlab's setting". */
static const claim_record kAgnostic = {
    .talk = MB_TALK, .seed = "001", .section = "Final Remarks",
    .quote = "Multibounce fit is agnostic to the source of the AO as long as it is ground truth",
    .setting = "ground-truth AO from another method, such as line-sweep AO [Timonen2013] whose horizon-based "
               "integration is the same, fed to the multi-bounce fit of the talk's references",
    .setting_match = CLAIM_SETTING_GTLAB,
    .setting_note = MB_SETTING_NOTE "; gtlab has no multi-bounce reference of the height-field world, so the height "
                    "field's change is scored against the 3-D truth's and its own error in V_d enters through the "
                    "slope of f(V_d) - V_d (a path tracer of the depth buffer as a height field would give that "
                    "source its own truth)",
    .reading = "Fed the height-field reference's V_d (the ground truth of screen-space and line-sweep AO) instead "
               "of the 3-D reference's, the talk's f adds the light of the bounces, f(V_d) - V_d, as accurately "
               "against the truth's V'_d - V_d, to within one code value either way.",
    .form = CLAIM_RANGE, .low = -CLAIM_ONE_CODE_VALUE_8BIT, .high = CLAIM_ONE_CODE_VALUE_8BIT,
    .tolerance_source = CLAIM_TOLERANCE_VISIBILITY,
    .tolerance = "one code value of an 8-bit AO target (CLAIM_ONE_CODE_VALUE_8BIT) of RMSE, either way"};

static void agnostic_section(report_context *ctx, const multibounce_study_result *r, cJSON *summary)
{
    const multibounce_agnostic *g = &r->gtao_input.agnostic;
    report_heading(ctx->doc, 3, "Agnostic to the source of the AO, as long as it is ground truth");
    report_paragraph(
        ctx->doc,
        "The talk's words stand under 'Final Remarks', beside line-sweep AO: any ground-truth AO may feed the fit. "
        "Two ground-truth sources on the same pixels: the 3-D reference's V_d (even-sample half) and the "
        "height-field reference's (the depth buffer as a height field of infinite thickness, the limit of "
        "screen-space and line-sweep AO; rendered at the reference's camera with %d samples per pixel, as many as "
        "that half). What f claims is the light the bounces add, so each source is scored on its own change: "
        "f(V_d) - V_d against the truth's V'_d - V_d (odd half), RMS over every scene and albedo, each weighted "
        "equally, so V_d's own error enters only through the slope of that change (below). RMSE of that change: %.4f with the 3-D V_d, %.4f with the "
        "height field's, a difference of %+.4f ± %.4f (jackknife over the %d scenes), against one 8-bit code "
        "value (%.4f). For scale: the height field's V_d is %.4f RMS from the 3-D one, and f(V_d) misses the 3-D "
        "V'_d by %.4f (3-D V_d) and %.4f (height field's), most of the latter the height field's own error. "
        "Each source should be scored against the multi-bounce truth of its own world; gtlab has none for the "
        "height field, so its change is scored against the 3-D world's and the height field's error in V_d still "
        "reaches the figure through the slope of f(V_d) - V_d: the claims row is judged under gtlab's setting.",
        g->spp, g->gain_rmse_3d, g->gain_rmse_hf, g->difference, g->difference_se, MULTIBOUNCE_STUDY_SCENES,
        CLAIM_ONE_CODE_VALUE_8BIT, g->rmse_hf_v_d, g->rmse_total_3d, g->rmse_total_hf);
    report_object(summary, "agnostic", agnostic_columns, (int)(sizeof agnostic_columns / sizeof agnostic_columns[0]),
                  g);
    claims_table_add(ctx->claims, &kAgnostic, g->difference, g->difference_se,
                     "RMSE of the change f makes, f(V_d) - V_d, against the 3-D truth's V'_d - V_d, with the "
                     "height-field reference's V_d minus with the 3-D reference's, over %d scenes x %d albedos "
                     "(jackknife s.e. over scenes)",
                     MULTIBOUNCE_STUDY_SCENES, MULTIBOUNCE_STUDY_ALBEDOS);
}

void multibounce_gtao_section(report_context *ctx, const multibounce_study_result *r, cJSON *summary)
{
    const multibounce_gtao_study *g = &r->gtao_input;
    agnostic_section(ctx, r, summary);
    report_heading(ctx->doc, 3, "f on GTAO's V_d: how much of the error is GTAO's");
    report_paragraph(ctx->doc,
                     "GTAO's V_d is not ground truth, so this lies outside the talk's claim above and has no claims "
                     "row: it shows what the AO source adds in practice. The talk's f "
                     "is applied to GTAO's V_d (each preset, one frame, unbounded radius as the reference, run on "
                     "each reference's own G-buffer) and to the reference V_d (even-sample half), both scored "
                     "against the multi-bounce reference V'_d (odd half), every scene and albedo weighted "
                     "equally. GTAO's share of the squared error is 1 - MSE(f(reference V_d)) / MSE(f(GTAO "
                     "V_d)): the part the AO source adds to what f itself misses. ± are jackknife standard "
                     "errors over the %d scenes.",
                     MULTIBOUNCE_STUDY_SCENES);
    report_rows(ctx->doc, cJSON_AddArrayToObject(summary, "gtao_input"), gtao_columns, COLUMNS(gtao_columns),
                g->rows, sizeof g->rows[0], MULTIBOUNCE_GTAO_PRESETS);
}
