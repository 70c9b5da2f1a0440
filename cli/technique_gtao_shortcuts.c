/* The GTAO talk's shortcuts and baselines measured against the references
 * (issue 25, items 9-13): a stage of `gtlab all` after `gtao`, whose
 * height-field references it reads. */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/technique.h"
#include "report/gtao_checks_section.h"
#include "studies/ao_references.h"
#include "studies/gtao_validation.h"

static const cli_subcommand approximations[] = {
    {"alchemy", approx_alchemy, "Alchemy ambient obscurance (McGuire et al. 2011), a baseline the GTAO talk cites"},
    {"crytek", approx_crytek, "CryENGINE 2's SSAO (Mittring 2007), a baseline the GTAO talk cites"},
    {NULL, NULL, NULL},
};

static int all_stage_gtao_shortcuts(report_context *ctx, gt_error *e)
{
    char refs[4096], gtao[4096];
    snprintf(refs, sizeof refs, "%s/%s", ctx->study.output_dir, AO_REFERENCES_DIR);
    snprintf(gtao, sizeof gtao, "%s/%s", ctx->study.output_dir, GTAO_VALIDATION_DIR);
    gtao_shortcuts_request rq = {refs, gtao};
    static gtao_fast_math_result fast_math;
    static gtao_baselines_result baselines;
    static gtao_bent_normals_result bent;
    static gtao_thickness_result thickness;
    static gtao_distance_fade_result fade;
    if (gtao_fast_math_study(&ctx->study, &rq, &fast_math, e) != 0 ||
        gtao_baselines_study(&ctx->study, &rq, &baselines, e) != 0 ||
        gtao_bent_normals_study(&ctx->study, &rq, &bent, e) != 0 ||
        gtao_thickness_study(&ctx->study, &rq, &thickness, e) != 0 ||
        gtao_distance_fade_study(&ctx->study, &rq, &fade, e) != 0)
        return -1;
    report_heading(ctx->doc, 2, "GTAO's shortcuts against the references");
    report_paragraph(ctx->doc,
                     "Each shortcut the GTAO talk publishes, measured on the scenes of the AO references against "
                     "the height-field reference (what GTAO can know) and the 3-D one. Paired differences of "
                     "squared errors carry standard errors over 8x8-pixel blocks (metrics/cluster_mean.h), so a "
                     "difference smaller than twice its standard error is not significant.");
    cJSON *summary = cJSON_AddObjectToObject(ctx->summary, "gtao_shortcuts");
    gtao_fast_math_section(ctx, &fast_math, summary);
    gtao_baselines_section(ctx, &baselines, summary);
    gtao_bent_normals_section(ctx, &bent, summary);
    gtao_thickness_section(ctx, &thickness, summary);
    gtao_distance_fade_section(ctx, &fade, summary);
    return 0;
}

static const all_stage stages[] = {
    {"gtao-shortcuts", "GTAO's shortcuts", all_stage_gtao_shortcuts, NULL, "gtao"},
    {NULL, NULL, NULL, NULL, NULL},
};

const technique technique_gtao_shortcuts = {
    .name = "gtao_shortcuts",
    .subcommands = {[VERB_APPROX] = approximations},
    .stages = stages,
};
