/* Anti-aliasing against supersampled truth: a section of `gtlab all`
 * (studies/anti_aliasing.h). */
#include "cli/technique.h"
#include "report/anti_aliasing_section.h"
#include "studies/anti_aliasing.h"

static int all_stage_aa(report_context *ctx, gt_error *e)
{
    static aa_result r;
    aa_request rq = aa_default_request(ctx->study.quality);
    return aa_study(&ctx->study, &rq, &r, e) != 0 ? -1 : aa_section(ctx, &r, e);
}

GTLAB_STAGE_TECHNIQUE(anti_aliasing, "aa", "anti-aliasing against supersampled truth", all_stage_aa, AA_DIR);
