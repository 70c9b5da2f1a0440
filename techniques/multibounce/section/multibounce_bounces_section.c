/* The multi-bounce section's subsection on the bounce count (issue 25,
 * item 3; multibounce/multibounce_study.h, multibounce_bounce_study): the joint refit
 * at 1, 2, 4 and unlimited bounces, the distance of the talk's curve to
 * each, and the claims-table row "fitted to 4-bounce references". */
#include <math.h>
#include <stdio.h>

#include "multibounce/multibounce_section_parts.h"
#include "report/report_table.h"

#define COLUMNS(c) (int)(sizeof(c) / sizeof((c)[0]))

static void coefficient_cell(const multibounce_bounce_row *r, int k, char *text, size_t size)
{
    snprintf(text, size, "%.3f ± %.3f", r->coefficients[k], r->jackknife_se[k]);
}
static void a0_cell(const void *row, char *text, size_t size) { coefficient_cell(row, 0, text, size); }
static void a1_cell(const void *row, char *text, size_t size) { coefficient_cell(row, 1, text, size); }
static void b0_cell(const void *row, char *text, size_t size) { coefficient_cell(row, 2, text, size); }
static void b1_cell(const void *row, char *text, size_t size) { coefficient_cell(row, 3, text, size); }
static void c0_cell(const void *row, char *text, size_t size) { coefficient_cell(row, 4, text, size); }
static void c1_cell(const void *row, char *text, size_t size) { coefficient_cell(row, 5, text, size); }

static void distance_cell(const void *row, char *text, size_t size)
{
    const multibounce_bounce_row *r = row;
    snprintf(text, size, "%.4f ± %.4f", r->talk_distance, r->talk_distance_se);
}

static const report_column bounce_columns[] = {
    REPORT_TEXT("bounces", "bounces", multibounce_bounce_row, bounces),
    REPORT_CELL("a0", a0_cell),
    REPORT_CELL("a1 (x rho)", a1_cell),
    REPORT_CELL("b0", b0_cell),
    REPORT_CELL("b1 (x rho)", b1_cell),
    REPORT_CELL("c0", c0_cell),
    REPORT_CELL("c1 (x rho)", c1_cell),
    REPORT_REAL("mean V'_d - V_d", "mean_gain", "%.4f", multibounce_bounce_row, mean_gain),
    REPORT_REAL("RMSE V_d", "rmse_v_d", "%.4f", multibounce_bounce_row, rmse_v_d),
    REPORT_REAL("RMSE talk", "rmse_talk", "%.4f", multibounce_bounce_row, rmse_talk),
    REPORT_REAL("RMSE refit", "rmse_refit", "%.4f", multibounce_bounce_row, rmse_refit),
    REPORT_CELL("talk - refit (RMS over the curves)", distance_cell),
    REPORT_REAL(NULL, "talk_distance", NULL, multibounce_bounce_row, talk_distance),
    REPORT_REAL(NULL, "talk_distance_se", NULL, multibounce_bounce_row, talk_distance_se),
    REPORT_REAL(NULL, "render_seconds", NULL, multibounce_bounce_row, render_seconds),
};

static void add_json(const multibounce_bounce_study *b, cJSON *summary)
{
    cJSON *o = cJSON_AddObjectToObject(summary, "bounce_counts");
    cJSON *rows = cJSON_AddArrayToObject(o, "rows");
    report_rows(NULL, rows, bounce_columns, COLUMNS(bounce_columns), b->rows, sizeof b->rows[0],
                MULTIBOUNCE_BOUNCE_COUNTS);
    for (int i = 0; i < MULTIBOUNCE_BOUNCE_COUNTS; ++i) {
        cJSON *r = cJSON_GetArrayItem(rows, i);
        cJSON_AddItemToObject(r, "joint_linear", cJSON_CreateDoubleArray(b->rows[i].coefficients, MULTIBOUNCE_COEFFICIENTS));
        cJSON_AddItemToObject(r, "jackknife_se", cJSON_CreateDoubleArray(b->rows[i].jackknife_se, MULTIBOUNCE_COEFFICIENTS));
    }
    cJSON_AddStringToObject(o, "closest", b->rows[b->closest].bounces);
    cJSON_AddNumberToObject(o, "four_minus_best_other", b->four_minus_best_other);
    cJSON_AddNumberToObject(o, "four_minus_best_other_se", b->four_minus_best_other_se);
}

/* The talk states its method; the row checks that the published curve is
 * closest to gtlab's refit at that bounce count, past a visible margin. */
static const claim_record kFourBounces = {
    .talk = MB_TALK, .seed = "001", .section = "Multiple Bounces",
    .quote = "Calculate multi-bounce using Monte Carlo ray tracing @ given albedo $\\rho$ (4 bounces)",
    .setting = MB_SETTING, .setting_match = CLAIM_SETTING_GTLAB, .setting_note = MB_SETTING_NOTE,
    .reading = "The published a, b, c were fitted to 4-bounce references, so of gtlab's refits at 1, 2, 4 and "
               "unlimited bounces the 4-bounce one lies closest to the talk's curve, by more than a code value.",
    .form = CLAIM_BETTER, .margin = CLAIM_ONE_CODE_VALUE_8BIT, .tolerance_source = CLAIM_TOLERANCE_VISIBILITY,
    .tolerance = "one code value of an 8-bit AO target (CLAIM_ONE_CODE_VALUE_8BIT) of RMS distance between curves"};

static void add_claim(report_context *ctx, const multibounce_bounce_study *b)
{
    claims_table_add(ctx->claims, &kFourBounces, b->four_minus_best_other, b->four_minus_best_other_se,
                     "RMS distance of the talk's curve to gtlab's 4-bounce refit minus that to the closest other "
                     "bounce count's refit (%s), over V_d in [0, 1] and rho in [0.1, 0.9] (jackknife s.e. over "
                     "scenes)",
                     b->rows[b->best_other].bounces);
}

void multibounce_bounces_section(report_context *ctx, const multibounce_study_result *r, cJSON *summary)
{
    const multibounce_bounce_study *b = &r->bounce_counts;
    report_heading(ctx->doc, 3, "The bounce count");
    report_paragraph(
        ctx->doc,
        "The talk fitted its a, b, c to 4-bounce references. The same scenes and cameras, %d samples per pixel, "
        "rendered at 1, 2 and unlimited bounces ('inf': Russian roulette with survival probability the albedo, "
        "unbiased but for paths cut after %d bounces), each refitted jointly (a, b, c linear in rho, every scene "
        "and albedo weighted equally; ± the jackknife standard error over scenes). 'talk - refit' is the RMS "
        "over V_d in [0, 1] and rho in [%.1f, %.1f] of the talk's curve minus the refit's, both with the max, "
        "± its jackknife standard error.",
        r->substudy_spp, b->path_limit, MULTIBOUNCE_DISTANCE_ALBEDO_MIN, MULTIBOUNCE_DISTANCE_ALBEDO_MAX);
    report_rows(ctx->doc, NULL, bounce_columns, COLUMNS(bounce_columns), b->rows, sizeof b->rows[0],
                MULTIBOUNCE_BOUNCE_COUNTS);
    report_paragraph(ctx->doc,
                     "The talk's curve is closest to the %s-bounce refit (%.4f). At 4 bounces it is %.4f from "
                     "the refit, against %.4f at %s bounces, the closest other count: a difference of %+.4f ± "
                     "%.4f. The bounces add %.4f (1) to %.4f (inf) to V_d on average; V_d alone misses V'_d by "
                     "an RMSE of %.4f to %.4f, the refit of each count by %.4f to %.4f.",
                     b->rows[b->closest].bounces, b->rows[b->closest].talk_distance, b->rows[2].talk_distance,
                     b->rows[b->best_other].talk_distance, b->rows[b->best_other].bounces,
                     b->four_minus_best_other, b->four_minus_best_other_se, b->rows[0].mean_gain,
                     b->rows[MULTIBOUNCE_BOUNCE_COUNTS - 1].mean_gain, b->rows[0].rmse_v_d,
                     b->rows[MULTIBOUNCE_BOUNCE_COUNTS - 1].rmse_v_d, b->rows[0].rmse_refit,
                     b->rows[MULTIBOUNCE_BOUNCE_COUNTS - 1].rmse_refit);
    add_json(b, summary);
    add_claim(ctx, b);
}
