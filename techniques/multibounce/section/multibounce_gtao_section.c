/* The multi-bounce section's subsection on "agnostic to the source of the
 * AO as long as it is ground truth" (issue 25, item 5; issue 42;
 * multibounce/multibounce_study.h, multibounce_gtao_study): the talk's f on two
 * ground-truth sources, the 3-D and the height-field references, each scored
 * on the light it adds against the multi-bounce truth of its own world, and
 * the claims row; then, outside the claim (GTAO's V_d is not ground truth),
 * f on GTAO's V_d and GTAO's share of the error. */
#include <math.h>
#include <stdio.h>

#include "multibounce/multibounce_section_parts.h"
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

/* "Agnostic" read as the words say: the fit does not care which ground truth
 * feeds it, so the two sources' errors, each against its own world's truth,
 * differ by less than a code value either way. (Not "both errors within a
 * code value": that is f's own accuracy, which the fit's rows test, and f
 * misses either truth by several code values.) The scenes are gtlab's, not
 * the talk's: judged under gtlab's setting. */
static const claim_record kAgnostic = {
    .talk = MB_TALK, .seed = "001", .section = "Final Remarks",
    .quote = "Multibounce fit is agnostic to the source of the AO as long as it is ground truth",
    .setting = "ground-truth AO from another method, such as line-sweep AO [Timonen2013] whose horizon-based "
               "integration is the same, fed to the multi-bounce fit of the talk's references",
    .setting_match = CLAIM_SETTING_GTLAB,
    .setting_note = MB_SETTING_NOTE "; the two ground truths are the 3-D references and the height-field ones (the "
                    "depth buffer as a height field of infinite thickness, the world screen-space and line-sweep AO "
                    "see, path-traced with the same albedos and bounces, at the sub-studies' fixed samples), each V_d scored against the "
                    "multi-bounce truth of its own world",
    .reading = "Fed either ground truth, the 3-D reference's V_d or the height-field reference's (the ground truth of "
               "screen-space and line-sweep AO), the talk's f adds the light of the bounces, f(V_d) - V_d, as "
               "accurately against its own world's V'_d - V_d, to within one code value of RMSE either way.",
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
        "Two ground truths of the same pixels, each with its own multi-bounce truth: the 3-D references, and the "
        "height-field ones (`gtlab render heightfield-multibounce`: the depth buffer as a height field of "
        "infinite thickness, the world screen-space and line-sweep AO see, where a blocked ray goes on from the "
        "pixel surface or the side of the pixel column it enters; rendered at the reference's camera with the "
        "same albedos and 4 bounces, %d samples per pixel). Each source's even-sample half feeds f and its odd "
        "half is its truth. What f claims is the light the bounces add, so each source is scored on its own "
        "change: f(V_d) - V_d against its world's V'_d - V_d, RMS over every scene and albedo, each weighted "
        "equally. RMSE of that change: %.4f in the 3-D world, %.4f in the height field's, a difference of "
        "%+.4f ± %.4f (jackknife over the %d scenes), against one 8-bit code value (%.4f) either way: "
        "'agnostic' is read as that difference, not as f's own accuracy (its figures follow; the fit's rows "
        "test it). For scale: the height field's V_d is %.4f RMS from the 3-D one (the "
        "two worlds differ), and f(V_d) misses its own world's V'_d by %.4f (3-D) and %.4f (height field).",
        g->spp, g->gain_rmse_3d, g->gain_rmse_hf, g->difference, g->difference_se, MULTIBOUNCE_STUDY_SCENES,
        CLAIM_ONE_CODE_VALUE_8BIT, g->rmse_hf_v_d, g->rmse_total_3d, g->rmse_total_hf);
    report_object(summary, "agnostic", agnostic_columns, (int)(sizeof agnostic_columns / sizeof agnostic_columns[0]),
                  g);
    claims_table_add(ctx->claims, &kAgnostic, g->difference, g->difference_se,
                     "RMSE of the change f makes, f(V_d) - V_d, against its own world's V'_d - V_d, with the "
                     "height-field reference's V_d (height-field truth) minus with the 3-D reference's (3-D truth), "
                     "over %d scenes x %d albedos (jackknife s.e. over scenes)",
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
