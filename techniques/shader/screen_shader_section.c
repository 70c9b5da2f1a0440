/* The project's screen-space shaders beside gtlab's GTAO
 * (screen_shader_section.h). */
#include "shader/screen_shader_section.h"

#include <math.h>
#include <stdio.h>

#include "core/statistics/sample_mean.h"
#include "report/claim_thresholds.h"
#include "report/report_table.h"

#define COLUMNS(c) (int)(sizeof(c) / sizeof((c)[0]))

/* A variant against GTAO (C) (row 0) on the same pixels: "better" or
 * "worse" only when the paired difference of squared errors is significant
 * (|mean| > t_975(blocks - 1) s.e.) AND the two RMSEs differ by more than
 * one 8-bit code value, the smallest change an AO target can show
 * (docs/claims-protocol.md); a smaller difference, however significant, is
 * "no visible difference". */
const char *screen_shader_verdict(const screen_shader_variant *x, const screen_shader_variant *gtao)
{
    if (x == gtao)
        return "-";
    if (fabs(x->rmse - gtao->rmse) <= CLAIM_ONE_CODE_VALUE_8BIT)
        return "no visible difference";
    if (fabs(x->vs_gtao.mean) <= student_t_975(x->vs_gtao.blocks - 1) * x->vs_gtao.se)
        return "not significant";
    return x->vs_gtao.mean < 0.0 ? "better" : "worse";
}

typedef struct {
    screen_shader_variant scores;
    const char *verdict;
} variant_row;

static const report_column variant_columns[] = {
    REPORT_TEXT("variant", "name", variant_row, scores.name),
    REPORT_STRING("from", "kind", variant_row, scores.kind),
    REPORT_REAL("RMSE vs 3-D", "rmse_3d", "%.5f", variant_row, scores.rmse),
    REPORT_REAL("mean DSSIM", "dssim_3d", "%.4e", variant_row, scores.dssim),
    REPORT_REAL("mean FLIP", "flip_3d", "%.4e", variant_row, scores.flip),
    REPORT_REAL("MSE - MSE(GTAO (C))", "paired_mse_vs_gtao", "%+.2e", variant_row, scores.vs_gtao.mean),
    REPORT_REAL("s.e. (8x8 blocks)", "paired_mse_vs_gtao_se", "%.1e", variant_row, scores.vs_gtao.se),
    REPORT_STRING("vs GTAO (C)", "verdict", variant_row, verdict),
    REPORT_REAL("max |AO - GTAO (C)|", "max_diff_vs_gtao", "%.2e", variant_row, scores.max_diff_vs_c),
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
                     "t_0.975 standard errors and the two RMSEs differ by more than one 8-bit code value, %.4f, the "
                     "smallest change an AO target shows; below that, no visible difference). GTAO (C) is techniques/gtao/gtao.c in the configuration of techniques/gtao/gtao.glsl "
                     "at its defaults: that shader, listed without parameters, differs from it by at most 2e-3 "
                     "(float rounding of cos, sin and acos on the device).",
                     r->device, r->scene_count, CLAIM_ONE_CODE_VALUE_8BIT);
    cJSON *o = cJSON_AddObjectToObject(ctx->summary, "screen_shader_scores");
    cJSON_AddNumberToObject(o, "scenes", r->scene_count);
    cJSON_AddStringToObject(o, "device", r->device);
    static variant_row rows[SCREEN_SCORE_MAX_VARIANTS];
    for (int v = 0; v < r->variant_count; ++v)
        rows[v] = (variant_row){r->variants[v], screen_shader_verdict(&r->variants[v], &r->variants[0])};
    report_rows(ctx->doc, cJSON_AddArrayToObject(o, "variants"), variant_columns, COLUMNS(variant_columns), rows,
                sizeof rows[0], r->variant_count);
    return 0;
}
