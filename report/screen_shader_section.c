/* The project's screen-space shaders beside gtlab's GTAO
 * (report/screen_shader_section.h). */
#include "report/screen_shader_section.h"

#include "report/report_table.h"

#define COLUMNS(c) (int)(sizeof(c) / sizeof((c)[0]))

static const report_column variant_columns[] = {
    REPORT_TEXT("variant", "name", screen_shader_variant, name),
    REPORT_STRING("from", "kind", screen_shader_variant, kind),
    REPORT_REAL("RMSE vs 3-D", "rmse_3d", "%.5f", screen_shader_variant, rmse),
    REPORT_REAL("mean DSSIM", "dssim_3d", "%.4e", screen_shader_variant, dssim),
    REPORT_REAL("mean FLIP", "flip_3d", "%.4e", screen_shader_variant, flip),
    REPORT_REAL("MSE - MSE(GTAO (C))", "paired_mse_vs_gtao", "%+.2e", screen_shader_variant, vs_gtao.mean),
    REPORT_REAL("s.e. (8x8 blocks)", "paired_mse_vs_gtao_se", "%.1e", screen_shader_variant, vs_gtao.se),
    REPORT_STRING("vs GTAO (C), 95%", "verdict", screen_shader_variant, verdict),
    REPORT_REAL("max |AO - GTAO (C)|", "max_diff_vs_gtao", "%.2e", screen_shader_variant, max_diff_vs_c),
};

int screen_shader_section(report_context *ctx, const screen_shader_score_result *r, gt_error *e)
{
    (void)e;
    if (r->variant_count == 0)
        return 0;
    report_heading(ctx->doc, 2, "Your screen-space shaders: ambient occlusion");
    report_paragraph(ctx->doc,
                     "The project's screen-space shaders (`screen_shaders`, the contract of docs/shaders.md, run on "
                     "Vulkan: %s) over the G-buffers of the AO references of %d scene views, their ao.V scored as the GTAO study "
                     "scores gtlab's own variants: RMSE (pooled), DSSIM and FLIP (means over the scenes) against the "
                     "3-D reference, and the paired difference of squared errors against gtlab's C GTAO on the same "
                     "pixels, pooled with its 8x8-block standard error (better or worse where it exceeds Student's "
                     "t_0.975 standard errors). GTAO (C) is realtime/gtao.c in the configuration of shaders/gtao.glsl "
                     "at its defaults: that shader, listed without parameters, differs from it by at most 2e-3 "
                     "(float rounding of cos, sin and acos on the device).",
                     r->device, r->scene_count);
    cJSON *o = cJSON_AddObjectToObject(ctx->summary, "screen_shader_scores");
    cJSON_AddNumberToObject(o, "scenes", r->scene_count);
    cJSON_AddStringToObject(o, "device", r->device);
    report_rows(ctx->doc, cJSON_AddArrayToObject(o, "variants"), variant_columns, COLUMNS(variant_columns),
                r->variants, sizeof r->variants[0], r->variant_count);
    return 0;
}
