/* The project's shaders and plug-ins beside gtlab's multi-bounce variants
 * (report/multibounce_score_section.h). */
#include "report/multibounce_score_section.h"

#include "report/report_table.h"

#define COLUMNS(c) (int)(sizeof(c) / sizeof((c)[0]))

static const report_column variant_columns[] = {
    REPORT_TEXT("variant", "name", multibounce_score_variant, name),
    REPORT_STRING("from", "kind", multibounce_score_variant, kind),
    REPORT_REAL("mean DSSIM", "dssim", "%.3e", multibounce_score_variant, dssim),
    REPORT_REAL("DSSIM floor", "noise_floor_dssim", "%.3e", multibounce_score_variant, dssim_floor),
    REPORT_REAL("mean RMSE", "rmse", "%.5f", multibounce_score_variant, rmse),
    REPORT_REAL("RMSE floor", "noise_floor_rmse", "%.5f", multibounce_score_variant, rmse_floor),
};

int multibounce_score_section(report_context *ctx, const multibounce_score_result *r, gt_error *e)
{
    (void)e;
    if (r->variant_count == 0)
        return 0;
    report_heading(ctx->doc, 2, "Your shaders and plug-ins: multi-bounce AO");
    report_paragraph(ctx->doc,
                     "The project's function files (`shaders`, the per-sample contract of docs/shaders.md, run on "
                     "Vulkan%s%s) and C plug-ins (`plugins`, core/plugin_abi.h), scored on the multi-bounce "
                     "references as the multi-bounce validation scores gtlab's own: every variant takes V_d of the "
                     "even-sample half and is compared with V'_d of the odd-sample half, over %d reference and "
                     "albedo pairs; the means below, beside V_d alone and the talk's GTAOMultiBounce. A variant "
                     "within the noise floor is as good as these references can tell.",
                     r->device[0] ? ": " : "", r->device, r->row_count);
    cJSON *o = cJSON_AddObjectToObject(ctx->summary, "shader_scores");
    cJSON_AddNumberToObject(o, "pairs", r->row_count);
    report_rows(ctx->doc, cJSON_AddArrayToObject(o, "variants"), variant_columns, COLUMNS(variant_columns),
                r->variants, sizeof r->variants[0], r->variant_count);
    return 0;
}
