/* Colour-grading LUTs (color_grading_study.h): their error against the
 * exact grades by size, input space, interpolation and storage, and when
 * 16^3 suffices. */
#ifndef GTLAB_COLOR_GRADING_SECTION_H
#define GTLAB_COLOR_GRADING_SECTION_H

#include "report/report_context.h"
#include "color_grading/color_grading_study.h"

/* The claims row "16^3 is enough for the majority of colour transformations"
 * from the rows of the GPU path (sRGB-indexed, RGBA8, trilinear); a NULL
 * table ignores it. */
void color_grading_add_claim(claims_table *t, const grading_row *rows, int n);
int color_grading_section(report_context *ctx, const grading_result *r, gt_error *e);

#endif
