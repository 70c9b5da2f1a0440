/* The GTAO talk's shortcuts and baselines (issue 25, items 9-13): the
 * section that holds their subsections. */
#include "gtao/gtao_checks_section.h"
#include "gtao/vbao_section.h"

void gtao_checks_section(report_context *ctx, const gtao_checks_result *r)
{
    report_heading(ctx->doc, 2, "GTAO's shortcuts against the references");
    report_paragraph(ctx->doc,
                     "Each shortcut the GTAO talk publishes, measured on the scenes of the AO references against "
                     "the height-field reference (what GTAO can know) and the 3-D one. Paired differences of "
                     "squared errors carry standard errors over 8x8-pixel blocks (metrics/cluster_mean.h), so a "
                     "difference smaller than twice its standard error is not significant.");
    cJSON *summary = cJSON_AddObjectToObject(ctx->summary, "gtao_shortcuts");
    gtao_fast_math_section(ctx, &r->fast_math, summary);
    gtao_baselines_section(ctx, &r->baselines, summary);
    gtao_bent_normals_section(ctx, &r->bent, summary);
    gtao_thickness_section(ctx, &r->thickness, summary);
    gtao_distance_fade_section(ctx, &r->fade, summary);
    vbao_section(ctx, &r->vbao, summary);
}
