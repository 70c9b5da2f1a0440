/* The project's shaders and plug-ins beside gtlab's multi-bounce variants
 * (shader_scores_section.h). */
#include "shader/shader_scores_section.h"

#include "report/report_table.h"
#include "specular_occlusion/specular_occlusion_score.h"

#define COLUMNS(c) (int)(sizeof(c) / sizeof((c)[0]))

static const report_column variant_columns[] = {
    REPORT_TEXT("variant", "name", function_score_variant, name),
    REPORT_STRING("from", "kind", function_score_variant, kind),
    REPORT_RANKED("mean DSSIM", "dssim", "%.3e", function_score_variant, dssim, REPORT_LOWEST_BEST),
    REPORT_REAL("DSSIM floor", "noise_floor_dssim", "%.3e", function_score_variant, dssim_floor),
    REPORT_REAL("mean RMSE", "rmse", "%.5f", function_score_variant, rmse),
    REPORT_REAL("RMSE floor", "noise_floor_rmse", "%.5f", function_score_variant, rmse_floor),
};

/* The table of the variants' means, and summary.json's `key`: {count_name: rows, variants: [...]}. */
static void variant_table(report_context *ctx, const function_score_result *r, const char *key,
                          const char *count_name)
{
    cJSON *o = cJSON_AddObjectToObject(ctx->summary, key);
    cJSON_AddNumberToObject(o, count_name, r->row_count);
    report_rows(ctx->doc, cJSON_AddArrayToObject(o, "variants"), variant_columns, COLUMNS(variant_columns),
                r->variants, sizeof r->variants[0], r->variant_count);
}

int multibounce_score_section(report_context *ctx, const function_score_result *r, gt_error *e)
{
    (void)e;
    if (r->variant_count == 0)
        return 0;
    report_heading(ctx->doc, 2, "Your shaders and plug-ins: multi-bounce AO");
    report_paragraph(ctx->doc,
                     "The project's function files (`shaders`, the per-sample contract of docs/shaders.md, run on "
                     "Vulkan%s%s) and C plug-ins (`plugins`, core/plugin_abi.h), scored on the multi-bounce "
                     "references (the multi-bounce stage's, on gtlab's built-in scenes, not the project's) as the "
                     "multi-bounce validation scores gtlab's own: every variant takes V_d of the "
                     "even-sample half and is compared with V'_d of the odd-sample half, over %d reference and "
                     "albedo pairs; the means below, beside V_d alone and the talk's GTAOMultiBounce. A variant "
                     "within the noise floor is as good as these references can tell.",
                     r->device[0] ? ": " : "", r->device, r->row_count);
    variant_table(ctx, r, "shader_scores", "pairs");
    return 0;
}

int specular_occlusion_score_section(report_context *ctx, const function_score_result *r, gt_error *e)
{
    (void)e;
    if (r->variant_count == 0)
        return 0;
    report_heading(ctx->doc, 2, "Your shaders and plug-ins: specular occlusion");
    report_paragraph(ctx->doc,
                     "The project's function files defining `gtlab_specular_occlusion` (run on Vulkan%s%s) and C "
                     "plug-ins exporting `gtlab_specular_occlusion_v1`, scored as the specular-occlusion study "
                     "scores gtlab's own variants: each takes the AO reference's cosine AO and bent normal and is "
                     "compared with the Monte Carlo V_s (specocc.V, GGX) over %d references (the study's scenes "
                     "and roughnesses, rendered again into `%s/`); the means below, beside gtlab's AO alone, "
                     "Lagarde's, GTSO's cone/cone (exact caps and Oat and Sander's, cos a_s = 2^(-3.32193 "
                     "alpha^2)) and the spherical Gaussians. The floors are the references' own (their even against "
                     "their odd samples).",
                     r->device[0] ? ": " : "", r->device, r->row_count, SO_SCORE_DIR);
    variant_table(ctx, r, "shader_scores_specular_occlusion", "references");
    return 0;
}

int shader_scores_section(report_context *ctx, const shader_scores_result *r, gt_error *e)
{
    return multibounce_score_section(ctx, &r->multibounce, e) != 0
               ? -1
               : specular_occlusion_score_section(ctx, &r->specular_occlusion, e);
}
