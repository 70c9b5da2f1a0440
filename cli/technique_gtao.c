/* GTAO (Jimenez et al. 2016) and its screen-space baselines HBAO and VO. */
#include "cli/cli.h"
#include "cli/technique.h"
#include "studies/ao_references.h"

static const cli_subcommand approximations[] = {
    {"gtao", approx_gtao, "ground-truth AO (Jimenez et al. 2016): cosine-weighted horizons, bent normals"},
    {"hbao", approx_hbao, "horizon-based AO (Bavoil et al. 2008): uniform weighting"},
    {"vo", approx_vo, "volumetric obscurance with 4 samples (Loos and Sloan 2010; CryENGINE 3)"},
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
static const all_stage stages[] = {
    {"gtao", "GTAO validation", all_stage_gtao, NULL, "ao"},
    {NULL, NULL, NULL, NULL, NULL},
};

const technique technique_gtao = {
    .name = "gtao",
    .subcommands = {[VERB_APPROX] = approximations, [VERB_FIT] = fits, [VERB_BENCH] = benches},
    .stages = stages,
};
