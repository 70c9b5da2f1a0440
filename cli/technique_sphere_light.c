/* GGX sphere lights: Karis's representative point and Decima's GetNoHSquared. */
#include "cli/cli.h"
#include "cli/technique.h"
#include "report/sphere_light_section.h"

static const cli_subcommand fits[] = {
    {"sphere-light", fit_sphere_light, "Decima's sphere-light radius reduction and normalisation vs MC references"},
    {NULL, NULL, NULL},
};
static const cli_subcommand checks[] = {
    {"sphere-noh", check_sphere_noh,
     "GetNoHSquared (Karis, 1 and 2 Newton steps) against the brute-force max of (N.H)^2"},
    {NULL, NULL, NULL},
};
static const cli_subcommand benches[] = {
    {"sphere-light", bench_sphere_light, "cost of the Newton step: instructions and ns"},
    {NULL, NULL, NULL},
};
static int all_stage_sphere_light(report_context *ctx, gt_error *e)
{
    static sphere_light_result r;
    return sphere_light_study(&ctx->study, &r, e) != 0 ? -1 : sphere_light_section(ctx, &r, e);
}

static const all_stage stages[] = {
    {"sphere-light", "GGX sphere lights", all_stage_sphere_light, NULL, NULL},
    {NULL, NULL, NULL, NULL, NULL},
};

const technique technique_sphere_light = {
    .name = "sphere-light",
    .subcommands = {[VERB_FIT] = fits, [VERB_CHECK] = checks, [VERB_BENCH] = benches},
    .stages = stages,
};
