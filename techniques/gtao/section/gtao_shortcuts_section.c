/* The shortcut subsections in the order of the issue; see
 * gtao_shortcuts_section.h. */
#include "gtao/gtao_shortcuts_section.h"

#include <stdio.h>

void gtao_shortcuts_section(report_context *ctx, const gtao_shortcuts_result *r)
{
    cJSON *summary = cJSON_AddObjectToObject(ctx->summary, "gtao_shortcuts");
    gtao_half_res_section(ctx, &r->half_res, &r->talk, summary);
    gtao_pattern_section(ctx, &r->pattern, &r->talk, summary);
    gtao_denoisers_section(ctx, &r->denoisers, &r->talk, summary);
}
