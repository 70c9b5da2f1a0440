/* GTAO (Jimenez et al. 2016), its screen-space baselines (HBAO, VO, Alchemy,
 * Crytek) and the talk's shortcuts measured (issue 25, items 9-13). */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/technique.h"
#include "report/gtao_checks_section.h"
#include "report/gtao_section.h"
#include "studies/ao_references.h"

static const cli_subcommand approximations[] = {
    {"gtao", approx_gtao, "ground-truth AO (Jimenez et al. 2016): cosine-weighted horizons, bent normals"},
    {"hbao", approx_hbao, "horizon-based AO (Bavoil et al. 2008): uniform weighting"},
    {"vo", approx_vo, "volumetric obscurance with 4 samples (Loos and Sloan 2010; CryENGINE 3)"},
    {"alchemy", approx_alchemy, "Alchemy ambient obscurance (McGuire et al. 2011), a baseline the GTAO talk cites"},
    {"crytek", approx_crytek, "CryENGINE 2's SSAO (Mittring 2007), a baseline the GTAO talk cites"},
    {NULL, NULL, NULL},
};
static const cli_subcommand fits[] = {
    {"gtao-params", fit_gtao_params, "GTAO radius, falloff and thickness against 3-D AO references"},
    {NULL, NULL, NULL},
};
static const cli_subcommand benches[] = {
    {"gtao", bench_gtao, "GTAO at 1920x1080 in the talk's configuration, every preset's cost per pixel"},
    {NULL, NULL, NULL},
};
/* GTAO is scored against the AO stage's references (its `needs`). */
static int all_stage_gtao(report_context *ctx, gt_error *e)
{
    char refs[4096];
    snprintf(refs, sizeof refs, "%s/%s", ctx->study.output_dir, AO_REFERENCES_DIR);
    gtao_validation_request rq = {refs};
    static gtao_validation_result r;
    return gtao_validation_study(&ctx->study, &rq, &r, e) != 0 ? -1 : gtao_section(ctx, &r, e);
}

/* The talk's shortcuts read the AO references and the `gtao` stage's height-field references. */
static int all_stage_gtao_shortcuts(report_context *ctx, gt_error *e)
{
    char refs[4096], gtao[4096];
    snprintf(refs, sizeof refs, "%s/%s", ctx->study.output_dir, AO_REFERENCES_DIR);
    snprintf(gtao, sizeof gtao, "%s/%s", ctx->study.output_dir, GTAO_VALIDATION_DIR);
    gtao_shortcuts_request rq = {refs, gtao};
    static gtao_checks_result r;
    return gtao_checks_study(&ctx->study, &rq, &r, e) != 0 ? -1 : (gtao_checks_section(ctx, &r), 0);
}

static const all_stage stages[] = {
    {"gtao", "GTAO validation", all_stage_gtao, GTAO_VALIDATION_DIR, "ao"},
    {"gtao-shortcuts", "GTAO's shortcuts", all_stage_gtao_shortcuts, NULL, "gtao"},
    {NULL, NULL, NULL, NULL, NULL},
};

const technique technique_gtao = {
    .name = "gtao",
    .subcommands = {[VERB_APPROX] = approximations, [VERB_FIT] = fits, [VERB_BENCH] = benches},
    .stages = stages,
};
