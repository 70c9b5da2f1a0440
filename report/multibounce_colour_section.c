/* The multi-bounce section's subsection on colour (issue 25, item 2;
 * studies/multibounce.h, multibounce_colour_study): the talk's f per
 * channel against coloured references, DSSIM per channel and in luminance,
 * and the claims row "a close match". */
#include <math.h>
#include <stdio.h>

#include "report/multibounce_section_parts.h"
#include "report/report_table.h"

#define COLUMNS(c) (int)(sizeof(c) / sizeof((c)[0]))

static void channel_cell(const multibounce_colour_row *r, int c, char *text, size_t size)
{
    snprintf(text, size, "%.2e (floor %.2e)", r->dssim_channel[c], r->noise_floor_dssim_channel[c]);
}
static void red_cell(const void *row, char *text, size_t size) { channel_cell(row, 0, text, size); }
static void green_cell(const void *row, char *text, size_t size) { channel_cell(row, 1, text, size); }
static void blue_cell(const void *row, char *text, size_t size) { channel_cell(row, 2, text, size); }

static const report_column colour_columns[] = {
    REPORT_TEXT("scene", "scene", multibounce_colour_row, scene),
    REPORT_CELL("DSSIM R", red_cell),
    REPORT_CELL("DSSIM G", green_cell),
    REPORT_CELL("DSSIM B", blue_cell),
    REPORT_REAL("DSSIM luminance", "dssim_luminance", "%.2e", multibounce_colour_row, dssim_luminance),
    REPORT_REAL("floor", "noise_floor_dssim_luminance", "%.2e", multibounce_colour_row, noise_floor_dssim_luminance),
    REPORT_REAL("DSSIM luminance, grey f", "dssim_luminance_grey", "%.2e", multibounce_colour_row,
                dssim_luminance_grey),
    REPORT_REAL("RMSE luminance", "rmse_luminance", "%.4f", multibounce_colour_row, rmse_luminance),
    REPORT_REAL("RMSE luminance, grey f", "rmse_luminance_grey", "%.4f", multibounce_colour_row,
                rmse_luminance_grey),
};

static void add_json(const multibounce_colour_study *c, cJSON *summary)
{
    cJSON *rows = cJSON_AddArrayToObject(summary, "colour");
    report_rows(NULL, rows, colour_columns, COLUMNS(colour_columns), c->rows, sizeof c->rows[0],
                MULTIBOUNCE_COLOUR_SCENES);
    for (int k = 0; k < MULTIBOUNCE_COLOUR_SCENES; ++k) {
        cJSON *o = cJSON_GetArrayItem(rows, k);
        cJSON_AddItemToObject(o, "dssim_rgb", cJSON_CreateDoubleArray(c->rows[k].dssim_channel, 3));
        cJSON_AddItemToObject(o, "noise_floor_dssim_rgb", cJSON_CreateDoubleArray(c->rows[k].noise_floor_dssim_channel, 3));
    }
}

/* "A close match" read as: as close in colour (luminance DSSIM) as the
 * talk's f is on the grey references (their mean DSSIM). */
static void add_claim(report_context *ctx, const multibounce_study_result *r)
{
    const multibounce_colour_study *c = &r->colour;
    unreviewed_claim row = {.source = "Jimenez et al. 2016, Multi-Bounce",
                 .statement = "Per-channel multi-bounce with coloured albedo is a close match to the coloured "
                              "Monte Carlo reference",
                 .figure = c->mean_dssim_luminance,
                 .standard_error = c->mean_dssim_luminance_se,
                 .low = -INFINITY,
                 .high = r->validation_mean.dssim_talk};
    snprintf(row.quantity, sizeof row.quantity,
             "DSSIM in luminance of f per channel against the coloured reference, mean over %d scenes (s.e. over "
             "scenes); the claim allows up to the talk's mean DSSIM on the grey references",
             MULTIBOUNCE_COLOUR_SCENES);
    claims_table_add_unreviewed(ctx->claims, &row);
}

void multibounce_colour_section(report_context *ctx, const multibounce_study_result *r, cJSON *summary)
{
    const multibounce_colour_study *c = &r->colour;
    report_heading(ctx->doc, 3, "Colour: f per channel");
    report_paragraph(ctx->doc,
                     "Coloured references (the scene's base colours, %d bounces, the study's cameras and samples): "
                     "the Cornell box as built, menger coloured (0.8, 0.5, 0.2), boxes with a blue floor (0.2, "
                     "0.4, 0.8) and orange boxes (0.8, 0.3, 0.1). The talk's f per channel, f(V_d, rho_c) with the "
                     "pixel's own albedo, against the reference V'_c (V_d from the even samples, V'_c from the "
                     "odd); DSSIM per channel and of the luminance (Rec. 709) of rho_c V'_c, the shaded result, "
                     "with the noise floors (even half against odd); 'grey f' applies f with the luminance of rho "
                     "to every channel.",
                     r->bounces);
    report_rows(ctx->doc, NULL, colour_columns, COLUMNS(colour_columns), c->rows, sizeof c->rows[0],
                MULTIBOUNCE_COLOUR_SCENES);
    report_paragraph(ctx->doc,
                     "Mean DSSIM in luminance %.2e ± %.2e (floor %.2e; grey f %.2e), against %.2e for the talk's f "
                     "on the grey references.",
                     c->mean_dssim_luminance, c->mean_dssim_luminance_se, c->mean_noise_floor_dssim_luminance,
                     c->mean_dssim_luminance_grey, r->validation_mean.dssim_talk);
    add_json(c, summary);
    add_claim(ctx, r);
}
