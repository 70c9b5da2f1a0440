/* Colour-grading LUTs (studies/color_grading.h): their error against the
 * exact grades by size, input space, interpolation and storage, and when
 * 16^3 suffices. */
#ifndef GTLAB_REPORT_COLOR_GRADING_SECTION_H
#define GTLAB_REPORT_COLOR_GRADING_SECTION_H

#include "report/report_context.h"
#include "studies/color_grading.h"

int color_grading_section(report_context *ctx, const grading_result *r, gt_error *e);

#endif
