/* The multi-bounce section's subsection on colour (issue 25, item 2;
 * multibounce/multibounce_study.h, multibounce_colour_study): the talk's f per
 * channel against coloured references, DSSIM per channel and in luminance,
 * and the claims row "a close match". */
#include <math.h>
#include <stdio.h>

#include "multibounce/multibounce_section_parts.h"
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

/* The talk's f takes a colour albedo and gives "colored multi bounce
 * visibility"; read as: per channel it is as close to coloured references
 * as it is to the grey ones it was fitted to, past a just-noticeable DSSIM. */
static const claim_record kColour = {
    .talk = MB_TALK, .seed = "001", .section = "Shader Code",
    .quote = "Two inputs, visibility and albedo, and single output, colored multi bounce visibility.",
    .setting = MB_SETTING, .setting_match = CLAIM_SETTING_GTLAB,
    .setting_note = MB_SETTING_NOTE "; coloured references: the Cornell box as built, menger (0.8, 0.5, 0.2), "
                    "boxes on a blue floor, orange boxes",
    .reading = "Applied per channel to a coloured albedo, f matches coloured multi-bounce references (DSSIM of the "
               "shaded luminance) as well as it matches the grey references, to within a just-noticeable "
               "difference.",
    .form = CLAIM_AS_GOOD, .margin = CLAIM_DSSIM_JUST_NOTICEABLE, .tolerance_source = CLAIM_TOLERANCE_VISIBILITY,
    .tolerance = "the DSSIM of a just noticeable difference (CLAIM_DSSIM_JUST_NOTICEABLE, SSIM 0.95)"};

static void add_claim(report_context *ctx, const multibounce_study_result *r)
{
    const multibounce_colour_study *c = &r->colour;
    claims_table_add(ctx->claims, &kColour, c->mean_dssim_luminance - r->validation_mean.dssim_talk,
                     c->mean_dssim_luminance_se,
                     "mean DSSIM in luminance of f per channel against the coloured references (%d scenes) minus "
                     "the mean DSSIM of f against the grey references (%.4f; s.e. of the coloured mean over scenes)",
                     MULTIBOUNCE_COLOUR_SCENES, r->validation_mean.dssim_talk);
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
