/* Colour-grading LUTs (Kaplanyan 2010): a section of `gtlab all`
 * (studies/color_grading.h). */
#include "cli/technique.h"
#include "report/color_grading_section.h"
#include "studies/color_grading.h"

static int all_stage_color_grading(report_context *ctx, gt_error *e)
{
    static grading_result r;
    return color_grading_study(&ctx->study, &r, e) != 0 ? -1 : color_grading_section(ctx, &r, e);
}

static const all_stage stages[] = {
    {"color-grading", "colour-grading LUTs", all_stage_color_grading, GRADING_DIR, NULL},
    {NULL, NULL, NULL, NULL, NULL},
};

const technique technique_color_grading = {.name = "color-grading", .stages = stages};
