/* The GTAO section's subsections on the talk's performance shortcuts and
 * denoisers (issue 25, items 6-8; gtao_shortcuts.h): one
 * subsection and claims-table rows per item, one file each
 * (gtao_<item>_section.c). */
#ifndef GTLAB_GTAO_GTAO_SHORTCUTS_SECTION_H
#define GTLAB_GTAO_GTAO_SHORTCUTS_SECTION_H

#include "gtao/gtao_shortcuts.h"
#include "gtao/gtao_talk_text.h"
#include "report/report_context.h"

void gtao_shortcuts_section(report_context *ctx, const gtao_shortcuts_result *r);

/* Each subsection's tables are gtlab's 256x256 runs (r); its claims-table
 * rows come from the runs in the talk's setting (t: a 1920x1080 frame at
 * half resolution, issue 42 item 4), which a paragraph states beside them. */
void gtao_pattern_section(report_context *ctx, const gtao_pattern_result *r, const gtao_talk_result *t,
                          cJSON *summary);
void gtao_half_res_section(report_context *ctx, const gtao_half_res_result *r, const gtao_talk_result *t,
                           cJSON *summary);
void gtao_denoisers_section(report_context *ctx, const gtao_denoisers_result *r, const gtao_talk_result *t,
                            cJSON *summary);

#endif
