/* Ambient occlusion and bent-normal references: the AO stage of `gtlab all`
 * (its references are the inputs of the screen-space techniques' stages). */
#include "cli/technique.h"
#include "report/ao_section.h"
#include "studies/ao_references.h"

static int all_stage_ao_references(report_context *ctx, gt_error *e)
{
    static ao_references_result r;
    ao_references_request rq = ao_references_default_request(ctx->study.quality);
    return ao_references_study(&ctx->study, &rq, &r, e) != 0 ? -1 : ao_references_section(ctx, &r, e);
}

static const all_stage stages[] = {
    {"ao", "AO references", all_stage_ao_references, AO_REFERENCES_DIR, NULL},
    {NULL, NULL, NULL, NULL, NULL},
};

const technique technique_ao = {.name = "ao", .stages = stages};
