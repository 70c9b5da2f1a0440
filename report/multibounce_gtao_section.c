/* The multi-bounce section's subsection on "agnostic to the source of AO"
 * (issue 25, item 5; studies/multibounce.h, multibounce_gtao_study): the
 * talk's f on GTAO's V_d and on the reference's, both against the
 * multi-bounce reference, GTAO's share of the error, and the claims row. */
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

/* The talk's configuration is the medium preset. */
static void add_claim(report_context *ctx, const multibounce_study_result *r)
{
    const multibounce_gtao_row *medium = &r->gtao_input.rows[1];
    unreviewed_claim row = {.source = "Jimenez et al. 2016, Multi-Bounce",
                 .statement = "The multi-bounce fit is agnostic to the source of AO: applied to GTAO's V_d (the "
                              "talk's configuration) it matches the multi-bounce reference as well as applied to "
                              "the reference V_d",
                 .figure = medium->difference,
                 .standard_error = medium->difference_se,
                 .low = -INFINITY,
                 .high = r->validation_mean.noise_floor_rmse};
    snprintf(row.quantity, sizeof row.quantity,
             "RMSE of f(GTAO %s V_d) minus RMSE of f(reference V_d) against V'_d, all scenes and albedos "
             "(jackknife s.e. over scenes); the claim allows up to the references' noise-floor RMSE",
             medium->preset);
    claims_table_add_unreviewed(ctx->claims, &row);
}

void multibounce_gtao_section(report_context *ctx, const multibounce_study_result *r, cJSON *summary)
{
    const multibounce_gtao_study *g = &r->gtao_input;
    report_heading(ctx->doc, 3, "f on GTAO's V_d: how much of the error is GTAO's");
    report_paragraph(ctx->doc,
                     "The talk calls its multi-bounce function agnostic to the source of AO. Here the talk's f "
                     "is applied to GTAO's V_d (each preset, one frame, unbounded radius as the reference, run on "
                     "each reference's own G-buffer) and to the reference V_d (even-sample half), both scored "
                     "against the multi-bounce reference V'_d (odd half), every scene and albedo weighted "
                     "equally. GTAO's share of the squared error is 1 - MSE(f(reference V_d)) / MSE(f(GTAO "
                     "V_d)): the part the AO source adds to what f itself misses. ± are jackknife standard "
                     "errors over the %d scenes.",
                     MULTIBOUNCE_STUDY_SCENES);
    report_rows(ctx->doc, cJSON_AddArrayToObject(summary, "gtao_input"), gtao_columns, COLUMNS(gtao_columns),
                g->rows, sizeof g->rows[0], MULTIBOUNCE_GTAO_PRESETS);
    add_claim(ctx, r);
}
