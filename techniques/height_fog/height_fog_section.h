/* The height fog of the Decima talk: the published and corrected analytic
 * models against the references on the terrain, the regime table, and the
 * talk's claim of an exact single-scattering solution (height_fog/height_fog_study.h). */
#ifndef GTLAB_HEIGHT_FOG_SECTION_H
#define GTLAB_HEIGHT_FOG_SECTION_H

#include "report/report_context.h"
#include "height_fog/height_fog_study.h"

/* Adds the section to ctx's report, summary.json ("height_fog") and the
 * claims table; -1 (e set) on failure. */
int height_fog_section(report_context *ctx, const height_fog_result *r, gt_error *e);

#endif
