/* The combination images of the Decima height fog (height_fog/aerial_perspective_study.h):
 * the tables of the terrain views and the ground fisheyes, their images,
 * and a finding on the talk's "realistic aerial perspective" (no claims row:
 * the talk's claim is not numeric). Part of the height fog's section. */
#ifndef GTLAB_HEIGHT_FOG_AERIAL_PERSPECTIVE_SECTION_H
#define GTLAB_HEIGHT_FOG_AERIAL_PERSPECTIVE_SECTION_H

#include <cjson/cJSON.h>

#include "report/report_context.h"
#include "height_fog/aerial_perspective_study.h"

/* The finding's figure: the largest over the cases of the median pixel's
 * relative error of the published combination on the terrain view, set
 * beside Weber's fraction (atmosphere/atmosphere_luts_study.h, ATMOSPHERE_TOLERANCE):
 * the contrast the eye can tell. */
double aerial_perspective_worst_median(const aerial_perspective_result *r);

/* Adds the subsection to ctx's report, to json (the height fog's object:
 * key "aerial_perspective") and its finding. */
void aerial_perspective_section(report_context *ctx, cJSON *json, const char *dir, const aerial_perspective_result *r);

#endif
