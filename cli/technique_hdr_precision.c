/* Kaplanyan 2010's colour-precision and HDR-range figures: a section of
 * `gtlab all` (studies/hdr_precision.h). */
#include "cli/technique.h"
#include "report/hdr_precision_section.h"
#include "studies/hdr_precision.h"

static int all_stage_hdr_precision(report_context *ctx, gt_error *e)
{
    hdr_precision_result r;
    return hdr_precision_study(&ctx->study, &r, e) != 0 ? -1 : hdr_precision_section(ctx, &r, e);
}

static const all_stage stages[] = {
    {"hdr-precision", "gamma vs linear and HDR lower bounds", all_stage_hdr_precision, HDR_PRECISION_DIR, NULL},
    {NULL, NULL, NULL, NULL, NULL},
};

const technique technique_hdr_precision = {.name = "hdr-precision", .stages = stages};
