/* Ambient occlusion and bent-normal references: the AO stage of `gtlab all`
 * (its references are the inputs of the screen-space techniques' stages). */
#include "cli/cli.h"
#include "cli/technique.h"
#include "report/ao_section.h"
#include "studies/ao_references.h"

static int all_stage_ao_references(report_context *ctx, gt_error *e)
{
    static ao_references_result r;
    ao_references_request rq = ao_references_default_request(ctx->study.quality);
    return ao_references_study(&ctx->study, &rq, &r, e) != 0 ? -1 : ao_references_section(ctx, &r, e);
}

static const cli_subcommand benches[] = {
    {"convergence", bench_convergence, "AO time to RMSE 0.01, plain against the height-field control variate"},
    {NULL, NULL, NULL},
};

static const all_stage stages[] = {
    {"ao", "AO references", all_stage_ao_references, AO_REFERENCES_DIR, NULL},
    {NULL, NULL, NULL, NULL, NULL},
};

const technique technique_ao = {.name = "ao", .subcommands = {[VERB_BENCH] = benches}, .stages = stages};
