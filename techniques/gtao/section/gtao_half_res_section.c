/* The GTAO section's subsection on half resolution and the MIN depth MIP
 * chain (issue 25, item 6; gtao_half_res_study.c): the error of each
 * shortcut against the full-resolution search by radius, against the
 * references with no radius limit, "4x samples per direction", and the
 * claims-table rows. */
#include <math.h>
#include <stdio.h>

#include "gtao/gtao_shortcuts_section.h"
#include "report/claim_thresholds.h"
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
        char cells[1 + GTAO_HALF_RES_VARIANTS][160];
        const char *row[1 + GTAO_HALF_RES_VARIANTS];
        radius_text(x->radius_fraction, cells[0], sizeof cells[0]);
        for (int v = 0; v < GTAO_HALF_RES_VARIANTS; ++v)
            snprintf(cells[1 + v], sizeof cells[1 + v], "%.4f ± %.4f (bias %+.4f ± %.4f; mean |change| %.2f code "
                     "values, %.0f%% of codes changed)", x->rmse[v], x->rmse_se[v], x->bias_mean[v], x->bias_se[v],
                     block_mean_value(&x->change[v]) / CLAIM_ONE_CODE_VALUE_8BIT,
                     100.0 * block_mean_value(&x->codes[v]));
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
            cJSON_AddNumberToObject(c, "mean_abs_change", block_mean_value(&x->change[v]));
            cJSON_AddNumberToObject(c, "mean_abs_change_se", block_mean_se(&x->change[v]));
            cJSON_AddNumberToObject(c, "codes_changed", block_mean_value(&x->codes[v]));
        }
        cJSON_AddItemToArray(radii, row);
    }
    report_rows(NULL, cJSON_AddArrayToObject(o, "scenes"), scene_columns, COLUMNS(scene_columns), r->scenes,
                sizeof r->scenes[0], r->scene_count);
    cJSON_AddNumberToObject(o, "four_x_mean", r->four_x_mean);
    cJSON_AddNumberToObject(o, "four_x_se", r->four_x_se);
    cJSON_AddNumberToObject(o, "four_x_min_rmse", r->four_x_min_rmse);
    cJSON_AddNumberToObject(o, "four_x_point_rmse", r->four_x_point_rmse);
    cJSON_AddNumberToObject(o, "min_vs_mip", r->min_vs_mip_mean);
    cJSON_AddNumberToObject(o, "min_vs_mip_se", r->min_vs_mip_se);
    cJSON_AddNumberToObject(o, "mip_rmse", r->mip_rmse);
}

/* "Improves samples per direction (4x) - Not ideally distributed (close
 * together), but still useful": the talk concedes the 4 texels a MIN fetch
 * sees are not 4 well-spread samples, so the row tests "still useful": the
 * MIN-filtered chain against the point-sampled chain at the same 4 samples
 * per side, both against a converged search. */
static const claim_record min_filter_claim = {
    .talk = "Jimenez et al. 2016 (GTAO)",
    .seed = "001",
    .section = "Achieving the Performance Target",
    .quote = "Gets closest to camera height on 2x2 bilinear block ... Improves samples per direction (4x) ... Not "
             "ideally distributed (close together), but still useful",
    .setting = "PS4, 1080p at half resolution (960x540), a depth MIP chain traversed by distance with "
               "D3D11_FILTER_MINIMUM fetches (or min(Gather4())), 8 samples per direction",
    .setting_match = CLAIM_SETTING_TALK,
    .setting_note = "the talk's resolution and pass: the 960x540 half of a 1920x1080 G-buffer from gtlab's ray "
                    "tracer, its MIN chain traversed by distance, 4 samples per side (the talk's 8 per direction), "
                    "radius 0.2 of the camera's distance, one frame without the denoiser; not the talk's content: "
                    "gtlab's boxes and Cornell box (production adds menger and corner), not its game levels",
    .reading = "a MIN fetch takes the closest of 4 depth texels, which the talk calls 4x the samples while "
               "conceding they lie close together; what it claims is that they still help: at the same samples "
               "per side the MIN-filtered chain is closer to a converged horizon search than the point-sampled "
               "chain",
    .form = CLAIM_BETTER,
    .margin = CLAIM_ONE_CODE_VALUE_8BIT_MSE,
    .tolerance_source = CLAIM_TOLERANCE_TALK_COMPARISON,
    .tolerance = "better by more than one 8-bit code value squared of MSE (CLAIM_ONE_CODE_VALUE_8BIT_MSE)"};

/* The talk's half resolution with the MIN-filtered MIP chain as its own
 * change from the full-resolution search, in code values of an 8-bit AO
 * target. */
static const claim_record half_res_claim = {
    .talk = "Jimenez et al. 2016 (GTAO)",
    .seed = "001",
    .section = "Achieving the Performance Target",
    .quote = "Half resolution - Traverse a depth mipmap chain during sampling - Near samples: use half-res depth - "
             "Further away samples: progressively use lower mips ... In this budget we could only afford half "
             "resolution",
    .setting = "PS4, 1080p rendered at half resolution (960x540) within a 0.5 ms budget, the MIN-filtered depth "
               "MIP chain, 1 direction per pixel before the spatio-temporal denoiser",
    .setting_match = CLAIM_SETTING_TALK,
    .setting_note = "the talk's resolution: a 1920x1080 G-buffer from gtlab's ray tracer and its 960x540 half (each "
                    "2x2 block's closest pixel) with the MIN chain, upsampled by block, against the 1920x1080 "
                    "search; 4 regular slices x 4 samples per side, no denoiser (the talk's 1 direction before its "
                    "denoiser is not what is measured), radius 0.2 of the camera's distance; not the talk's "
                    "content: gtlab's boxes and Cornell box (production adds menger and corner), not its levels",
    .reading = "the talk takes half resolution with the MIN-filtered chain as the price of its budget and uses it "
               "in place of the full-resolution search",
    .stronger_reading = "that it moves the AO from the full-resolution search by less than one 8-bit code value on "
                        "average: the talk gives no figure for what half resolution costs in accuracy",
    .form = CLAIM_RANGE,
    .low = 0.0,
    .high = CLAIM_ONE_CODE_VALUE_8BIT,
    .tolerance_source = CLAIM_TOLERANCE_VISIBILITY,
    .tolerance = "one code value of an 8-bit AO target (CLAIM_ONE_CODE_VALUE_8BIT), the mean change allowed"};

/* The radius the claims are measured at (GTAO_HALF_RES_4X_RADIUS), or NULL. */
static const gtao_half_res_radius *claims_radius(const gtao_half_res_result *r)
{
    for (int k = 0; k < r->radius_count; ++k)
        if (r->radii[k].radius_fraction == GTAO_HALF_RES_4X_RADIUS)
            return &r->radii[k];
    return NULL;
}

/* The rows, from the runs in the talk's setting: the MIN filter within the
 * 960x540 pass (t->half_pass), half resolution against the 1920x1080 search
 * (t->half_res). */
static void add_claims(report_context *ctx, const gtao_talk_result *t)
{
    char scenes[256];
    gtao_talk_scenes_text(t, scenes, sizeof scenes);
    const gtao_half_res_result *p = &t->half_pass;
    claims_table_add(ctx->claims, &min_filter_claim, p->min_vs_mip_mean, p->min_vs_mip_se,
                     "squared error against a %d-sample search of the %dx%d pass, MIN-filtered MIP chain minus "
                     "point-sampled MIP chain, both with %d samples per side, radius %.2f of the camera distance, "
                     "mean over %ld 8x8 blocks of %s (s.e. over blocks); RMSE %.4f and %.4f (16 point samples of "
                     "the pass's depth: %.4f)",
                     GTAO_HALF_RES_CONVERGED_STEPS, t->half_width, t->half_height, GTAO_HALF_RES_STEPS,
                     GTAO_HALF_RES_4X_RADIUS, p->min_vs_mip.blocks, scenes, p->four_x_min_rmse, p->mip_rmse,
                     p->four_x_point_rmse);
    const gtao_half_res_radius *k = claims_radius(&t->half_res);
    if (!k)
        return;
    const int v = GTAO_HALF_RES_HALF_MIP_MIN;
    claims_table_add(ctx->claims, &half_res_claim, block_mean_value(&k->change[v]), block_mean_se(&k->change[v]),
                     "mean |AO of the %dx%d pass with the MIN-filtered MIP chain (upsampled by block) - AO of the "
                     "%dx%d search|, radius %.2f of the camera distance, mean over %ld 8x8 blocks of %s (s.e. over "
                     "blocks); %.1f%% of pixels change 8-bit code, mean signed change %+.4f",
                     t->half_width, t->half_height, t->full_width, t->full_height, k->radius_fraction,
                     k->change[v].blocks, scenes, 100.0 * block_mean_value(&k->codes[v]), k->bias_mean[v]);
}

/* The talk-setting figures in words, beside gtlab's 256x256 tables. */
static void talk_paragraph(report *doc, const gtao_half_res_result *r, const gtao_talk_result *t)
{
    const gtao_half_res_radius *k = claims_radius(&t->half_res), *own = claims_radius(r);
    if (!k || t->scene_count == 0)
        return;
    char scenes[256];
    gtao_talk_scenes_text(t, scenes, sizeof scenes);
    const int v = GTAO_HALF_RES_HALF_MIP_MIN;
    const gtao_half_res_result *p = &t->half_pass;
    report_paragraph(
        doc,
        "In the talk's setting (the claims table's rows): on %dx%d G-buffers of %s and their %dx%d halves, at "
        "radius %.2f, the talk's half resolution with the MIN chain moves the AO of the %dx%d search by %.2f ± "
        "%.2f code values of an 8-bit target on average (%.1f%% of pixels change code; RMSE %.4f), against %.2f "
        "at gtlab's 256x256 above; within the %dx%d pass the MIN-filtered chain with %d samples per side has RMSE "
        "%.4f against a %d-sample search, the point-sampled chain %.4f (paired difference in squared error %+.2e "
        "± %.1e). The runs in the talk's setting (the G-buffers, this subsection's, the pattern's and the "
        "denoisers') took %.0f s of wall clock and %.0f s of CPU on this machine.",
        t->full_width, t->full_height, scenes, t->half_width, t->half_height, k->radius_fraction, t->full_width,
        t->full_height, block_mean_value(&k->change[v]) / CLAIM_ONE_CODE_VALUE_8BIT,
        block_mean_se(&k->change[v]) / CLAIM_ONE_CODE_VALUE_8BIT, 100.0 * block_mean_value(&k->codes[v]),
        k->rmse[v], own ? block_mean_value(&own->change[v]) / CLAIM_ONE_CODE_VALUE_8BIT : NAN, t->half_width, t->half_height, GTAO_HALF_RES_STEPS, p->four_x_min_rmse,
        GTAO_HALF_RES_CONVERGED_STEPS, p->mip_rmse, p->min_vs_mip_mean, p->min_vs_mip_se, t->seconds,
        t->cpu_seconds);
}

/* summary.half_resolution.talk_setting: the rows' figures. */
static void add_talk_summary(const gtao_talk_result *t, cJSON *o)
{
    cJSON *x = cJSON_AddObjectToObject(o, "talk_setting");
    cJSON_AddItemToObject(x, "size", cJSON_CreateIntArray((int[]){t->full_width, t->full_height}, 2));
    cJSON_AddItemToObject(x, "pass", cJSON_CreateIntArray((int[]){t->half_width, t->half_height}, 2));
    const gtao_half_res_radius *k = claims_radius(&t->half_res);
    if (k) {
        cJSON_AddNumberToObject(x, "mean_abs_change", block_mean_value(&k->change[GTAO_HALF_RES_HALF_MIP_MIN]));
        cJSON_AddNumberToObject(x, "mean_abs_change_se", block_mean_se(&k->change[GTAO_HALF_RES_HALF_MIP_MIN]));
    }
    cJSON_AddNumberToObject(x, "min_vs_mip", t->half_pass.min_vs_mip_mean);
    cJSON_AddNumberToObject(x, "min_vs_mip_se", t->half_pass.min_vs_mip_se);
}

void gtao_half_res_section(report_context *ctx, const gtao_half_res_result *r, const gtao_talk_result *t,
                           cJSON *summary)
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
        "never lies below the full-resolution one at the same samples (techniques/gtao/tests/test_gtao_depth_mip.c), "
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
        "with 4 samples per side has RMSE %.4f, the same chain point-sampled %.4f (paired difference in squared "
        "error %+.2e ± %.1e at gtlab's 256x256; the claims table's \"still useful\" is measured in the talk's "
        "setting below); point samples of the full-resolution depth "
        "with 16 per side have %.4f (MIN chain with 4 minus them: %+.2e ± %.1e, a stronger reading than the "
        "talk's, which concedes the 4 texels are \"not ideally distributed\").",
        GTAO_HALF_RES_4X_RADIUS, GTAO_HALF_RES_CONVERGED_STEPS, r->four_x_min_rmse, r->mip_rmse, r->min_vs_mip_mean,
        r->min_vs_mip_se, r->four_x_point_rmse, r->four_x_mean, r->four_x_se);
    talk_paragraph(ctx->doc, r, t);
    add_summary(r, summary);
    add_talk_summary(t, cJSON_GetObjectItem(summary, "half_resolution"));
    add_claims(ctx, t);
}
