/* The combination images of the Decima height fog (studies/aerial_perspective.h):
 * the tables of the terrain views and the ground fisheyes, their images,
 * and the talk's "realistic aerial perspective" in the claims table. Part
 * of the height fog's section. */
#ifndef GTLAB_REPORT_AERIAL_PERSPECTIVE_SECTION_H
#define GTLAB_REPORT_AERIAL_PERSPECTIVE_SECTION_H

#include <cjson/cJSON.h>

#include "report/report_context.h"
#include "studies/aerial_perspective.h"

/* The claim's figure: the largest over the cases of the median pixel's
 * relative error of the published combination on the terrain view; the
 * claim holds within Weber's fraction (studies/atmosphere_luts.h,
 * ATMOSPHERE_TOLERANCE): the median pixel no more different than the eye
 * can tell. */
double aerial_perspective_claim_figure(const aerial_perspective_result *r);

/* Adds the subsection to ctx's report, to json (the height fog's object:
 * key "aerial_perspective") and its row to the claims table. */
void aerial_perspective_section(report_context *ctx, cJSON *json, const char *dir, const aerial_perspective_result *r);

#endif
