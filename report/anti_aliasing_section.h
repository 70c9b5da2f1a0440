/* Anti-aliasing against supersampled truth (studies/anti_aliasing.h): the
 * truth's convergence, each technique's error, previews. */
#ifndef GTLAB_REPORT_ANTI_ALIASING_SECTION_H
#define GTLAB_REPORT_ANTI_ALIASING_SECTION_H

#include "report/report_context.h"
#include "studies/anti_aliasing.h"

int aa_section(report_context *ctx, const aa_result *r, gt_error *e);

#endif
