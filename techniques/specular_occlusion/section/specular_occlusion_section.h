/* Specular occlusion (GTSO): the LUTs' axes, every variant scored against
 * the references, the splits, the gloss-to-aperture fits and the conclusions. */
#ifndef GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_SECTION_H
#define GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_SECTION_H

#include "report/report_context.h"
#include "specular_occlusion/specular_occlusion_study.h"

/* Adds the section to ctx's report and summary.json; -1 (e set) if a file it
 * writes could not be made. */
int specular_occlusion_section(report_context *ctx, const so_study_result *r, gt_error *e);

#endif
