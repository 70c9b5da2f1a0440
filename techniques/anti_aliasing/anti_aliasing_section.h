/* Anti-aliasing against supersampled truth (anti_aliasing/anti_aliasing_study.h): the
 * truth's convergence, each technique's error, previews. */
#ifndef GTLAB_ANTI_ALIASING_ANTI_ALIASING_SECTION_H
#define GTLAB_ANTI_ALIASING_ANTI_ALIASING_SECTION_H

#include "anti_aliasing/anti_aliasing_study.h"
#include "report/report_context.h"

int aa_section(report_context *ctx, const aa_result *r, gt_error *e);

#endif
