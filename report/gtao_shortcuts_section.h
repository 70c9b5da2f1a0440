/* The GTAO section's subsections on the talk's performance shortcuts and
 * denoisers (issue 25, items 6-8; studies/gtao_shortcuts.h): one
 * subsection and claims-table rows per item, one file each
 * (gtao_<item>_section.c). */
#ifndef GTLAB_REPORT_GTAO_SHORTCUTS_SECTION_H
#define GTLAB_REPORT_GTAO_SHORTCUTS_SECTION_H

#include "report/report_context.h"
#include "studies/gtao_shortcuts.h"

void gtao_shortcuts_section(report_context *ctx, const gtao_shortcuts_result *r);

void gtao_pattern_section(report_context *ctx, const gtao_pattern_result *r, cJSON *summary);
void gtao_half_res_section(report_context *ctx, const gtao_half_res_result *r, cJSON *summary);
void gtao_denoisers_section(report_context *ctx, const gtao_denoisers_result *r, cJSON *summary);

#endif
