/* GTAO's multi-bounce approximation (Jimenez et al. 2016) and its refit. */
#include "cli/cli.h"
#include "cli/technique.h"
#include "report/multibounce_section.h"

static const cli_subcommand fits[] = {
    {"multibounce", fit_multibounce, "GTAO multi-bounce cubic (per albedo and joint in rho) vs multibounce renders"},
    {NULL, NULL, NULL},
};
static const cli_subcommand benches[] = {
    {"multibounce", bench_multibounce, "multi-bounce paths/s against raw Embree; N albedos in one pass"},
    {"fit", bench_fit, "a million-sample fit, 1- vs 1024-sample blocks"},
    {NULL, NULL, NULL},
};
static int all_stage_multibounce(report_context *ctx, gt_error *e)
{
    static multibounce_study_result r;
    return multibounce_study(&ctx->study, &r, e) != 0 ? -1 : multibounce_section(ctx, &r, e);
}

static const all_stage stages[] = {
    {"multibounce", "multi-bounce refit", all_stage_multibounce, NULL, NULL},
    {NULL, NULL, NULL, NULL, NULL},
};

const technique technique_multibounce = {
    .name = "multibounce",
    .subcommands = {[VERB_FIT] = fits, [VERB_BENCH] = benches},
    .stages = stages,
};
