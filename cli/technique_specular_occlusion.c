/* Specular occlusion (GTSO, Jimenez et al. 2016) and its baselines. */
#include "cli/cli.h"
#include "cli/technique.h"
#include "report/specular_occlusion_section.h"

static const cli_subcommand approximations[] = {
    {"specular-occlusion", approx_specular_occlusion,
     "GTSO and the other specular-occlusion variants from AO + bent normal"},
    {NULL, NULL, NULL},
};
static const cli_subcommand fits[] = {
    {"aperture", fit_aperture, "GTSO gloss-to-aperture u by DSSIM against specular-occlusion references"},
    {NULL, NULL, NULL},
};
static const cli_subcommand luts[] = {
    {"specular-occlusion", lut_specular_occlusion, "GTSO cone/lobe V_s(a_v, beta, r): EXR, 8-bit PNG, C header"},
    {NULL, NULL, NULL},
};
static int all_stage_specular_occlusion(report_context *ctx, gt_error *e)
{
    static so_study_result r;
    return specular_occlusion_study(&ctx->study, &r, e) != 0 ? -1 : specular_occlusion_section(ctx, &r, e);
}

static const all_stage stages[] = {
    {"specular-occlusion", "specular occlusion", all_stage_specular_occlusion, NULL, NULL},
    {NULL, NULL, NULL, NULL, NULL},
};

const technique technique_specular_occlusion = {
    .name = "specular-occlusion",
    .subcommands = {[VERB_APPROX] = approximations, [VERB_FIT] = fits, [VERB_LUT] = luts},
    .stages = stages,
};
