/* The specular-occlusion section's parts kept in their own files: the
 * talk's statements it measures (issue 26), each a subsection, an object of
 * the section's summary.json object and rows of the claims table. Internal
 * to report/. */
#ifndef GTLAB_REPORT_SPECULAR_OCCLUSION_SECTION_PARTS_H
#define GTLAB_REPORT_SPECULAR_OCCLUSION_SECTION_PARTS_H

#include <cjson/cJSON.h>

#include "report/report_context.h"
#include "studies/specular_occlusion.h"

/* The talk's rankings and the gloss bands (items 2 and 3;
 * specular_occlusion_rankings_section.c). */
void so_rankings_section(report_context *ctx, const so_study_result *r, cJSON *summary);

/* The visibility cone and the dropped view angle (items 1 and 5;
 * specular_occlusion_cone_view_section.c). */
void so_cone_view_section(report_context *ctx, const so_study_result *r, cJSON *summary);

#endif
