/* The GTAO section's subsection on half resolution and the MIN depth MIP
 * chain (issue 25, item 6; studies/gtao_half_res.c): the error of each
 * shortcut against the full-resolution search by radius, against the
 * references with no radius limit, "4x samples per direction", and the
 * claims-table rows. */
#include <math.h>
#include <stdio.h>

#include "report/gtao_shortcuts_section.h"
#include "report/report_table.h"

#define COLUMNS(c) (int)(sizeof(c) / sizeof((c)[0]))

static const report_column scene_columns[] = {
    REPORT_TEXT("scene", "scene", gtao_half_res_scene, scene),
    REPORT_REAL("full res vs height field", "full_rmse_heightfield", "%.4f", gtao_half_res_scene, full_rmse_hf),
    REPORT_REAL("talk's vs height field", "talk_rmse_heightfield", "%.4f", gtao_half_res_scene, talk_rmse_hf),
    REPORT_REAL("full res vs 3-D", "full_rmse_3d", "%.4f", gtao_half_res_scene, full_rmse_3d),
    REPORT_REAL("talk's vs 3-D", "talk_rmse_3d", "%.4f", gtao_half_res_scene, talk_rmse_3d),
};

static void radius_text(double fraction, char *text, size_t size)
{
    if (fraction > 0.0)
        snprintf(text, size, "%.2f", fraction);
    else
        snprintf(text, size, "no limit");
}

/* One row per radius: RMSE ± s.e. and mean signed difference per variant. */
static void radius_table(report *doc, const gtao_half_res_result *r)
{
    const char *headers[1 + GTAO_HALF_RES_VARIANTS];
    headers[0] = "radius / camera distance";
    for (int v = 0; v < GTAO_HALF_RES_VARIANTS; ++v)
        headers[1 + v] = gtao_half_res_variant_names[v];
    report_table_begin(doc, 1 + GTAO_HALF_RES_VARIANTS, headers);
    for (int k = 0; k < r->radius_count; ++k) {
        const gtao_half_res_radius *x = &r->radii[k];
        char cells[1 + GTAO_HALF_RES_VARIANTS][96];
        const char *row[1 + GTAO_HALF_RES_VARIANTS];
        radius_text(x->radius_fraction, cells[0], sizeof cells[0]);
        for (int v = 0; v < GTAO_HALF_RES_VARIANTS; ++v)
            snprintf(cells[1 + v], sizeof cells[1 + v], "%.4f ± %.4f (bias %+.4f ± %.4f)", x->rmse[v],
                     x->rmse_se[v], x->bias_mean[v], x->bias_se[v]);
        for (int c = 0; c <= GTAO_HALF_RES_VARIANTS; ++c)
            row[c] = cells[c];
        report_table_row(doc, row);
    }
    report_table_end(doc);
}

static void add_summary(const gtao_half_res_result *r, cJSON *summary)
{
    cJSON *o = cJSON_AddObjectToObject(summary, "half_resolution");
    cJSON *radii = cJSON_AddArrayToObject(o, "radii");
    for (int k = 0; k < r->radius_count; ++k) {
        const gtao_half_res_radius *x = &r->radii[k];
        cJSON *row = cJSON_CreateObject();
        cJSON_AddNumberToObject(row, "radius_fraction", x->radius_fraction);
        for (int v = 0; v < GTAO_HALF_RES_VARIANTS; ++v) {
            cJSON *c = cJSON_AddObjectToObject(row, gtao_half_res_variant_names[v]);
            cJSON_AddNumberToObject(c, "rmse", x->rmse[v]);
            cJSON_AddNumberToObject(c, "rmse_se", x->rmse_se[v]);
            cJSON_AddNumberToObject(c, "bias", x->bias_mean[v]);
            cJSON_AddNumberToObject(c, "bias_se", x->bias_se[v]);
        }
        cJSON_AddItemToArray(radii, row);
    }
    report_rows(NULL, cJSON_AddArrayToObject(o, "scenes"), scene_columns, COLUMNS(scene_columns), r->scenes,
                sizeof r->scenes[0], r->scene_count);
    cJSON_AddNumberToObject(o, "four_x_mean", r->four_x_mean);
    cJSON_AddNumberToObject(o, "four_x_se", r->four_x_se);
    cJSON_AddNumberToObject(o, "four_x_min_rmse", r->four_x_min_rmse);
    cJSON_AddNumberToObject(o, "four_x_point_rmse", r->four_x_point_rmse);
}

static void add_claims(report_context *ctx, const gtao_half_res_result *r)
{
    unreviewed_claim samples = {.source = "Jimenez et al. 2016, Achieving the Performance Target",
                     .statement = "D3D11_FILTER_MINIMUM on the depth MIP chain \"improves samples per direction "
                                  "(4x)\": 4 MIN-filtered samples do as well as 16 point samples",
                     .figure = r->four_x_mean,
                     .standard_error = r->four_x_se,
                     .low = -INFINITY,
                     .high = 0.0};
    snprintf(samples.quantity, sizeof samples.quantity,
             "squared error against a %d-sample full-resolution search, MIN MIP with 4 samples per side minus "
             "point samples with 16, radius %.2f of the camera distance, mean over %ld 8x8 blocks of %d scenes "
             "(s.e. over blocks); at most 0: the MIN chain as good",
             GTAO_HALF_RES_CONVERGED_STEPS, GTAO_HALF_RES_4X_RADIUS, r->four_x.blocks, r->scene_count);
    claims_table_add_unreviewed(ctx->claims, &samples);
    unreviewed_claim half = {.source = "Jimenez et al. 2016, Achieving the Performance Target",
                  .statement = "half resolution with a MIN-filtered depth MIP chain (closest height ~= max "
                               "horizon) stands in for the full-resolution horizon search",
                  .figure = r->talk_rmse_unbounded,
                  .standard_error = r->talk_rmse_unbounded_se,
                  .low = 0.0,
                  .high = r->hf_noise_rmse};
    snprintf(half.quantity, sizeof half.quantity,
             "RMSE of half resolution + MIN MIP (upsampled by block) against the full-resolution search, no "
             "radius limit, %d scenes (s.e. over 8x8 blocks); the claim allows up to the height-field "
             "reference's noise RMSE",
             r->scene_count);
    claims_table_add_unreviewed(ctx->claims, &half);
}

void gtao_half_res_section(report_context *ctx, const gtao_half_res_result *r, cJSON *summary)
{
    report_heading(ctx->doc, 3, "Half resolution and the MIN depth MIP chain");
    report_paragraph(
        ctx->doc,
        "GTAO with %d regular slices and %d samples per side, no denoiser, exact maths; the baseline point-samples "
        "the full-resolution depth at each sample (the eye ray through the sample at the texel's depth). The "
        "chain's level l+1 is the minimum (closest to the camera) of 2x2 texels of level l; a sample t pixels "
        "away reads level floor(log2 t - 3.3) (XeGTAO's offset), point-sampled or MIN-filtered (the minimum of "
        "its 2x2 bilinear footprint, which is what both D3D11_FILTER_MINIMUM and min(Gather4()) return). Half "
        "resolution keeps each 2x2 block's closest pixel and is upsampled by block. The MIN-filtered horizon "
        "never lies below the full-resolution one at the same samples (tests/realtime/test_gtao_depth_mip.c), "
        "so the shortcuts only darken. RMSE against the full-resolution search ± s.e. over 8x8 blocks, and the "
        "mean signed difference (bias), pooled over %d scenes, by radius (a fraction of the camera's distance "
        "to its target):",
        GTAO_HALF_RES_SLICES, GTAO_HALF_RES_STEPS, r->scene_count);
    radius_table(ctx->doc, r);
    report_paragraph(ctx->doc, "With no radius limit, RMSE against the two references less their noise:");
    report_rows(ctx->doc, NULL, scene_columns, COLUMNS(scene_columns), r->scenes, sizeof r->scenes[0],
                r->scene_count);
    report_paragraph(
        ctx->doc,
        "\"4x samples per direction\", at radius %.2f against a %d-sample full-resolution search: the MIN chain "
        "with 4 samples per side has RMSE %.4f, point samples with 16 have %.4f; paired difference in squared "
        "error %+.2e ± %.1e.",
        GTAO_HALF_RES_4X_RADIUS, GTAO_HALF_RES_CONVERGED_STEPS, r->four_x_min_rmse, r->four_x_point_rmse,
        r->four_x_mean, r->four_x_se);
    add_summary(r, summary);
    add_claims(ctx, r);
}
