/* The height fog of the Decima talk: the published and corrected analytic
 * models against the references on the terrain, the regime table, and the
 * talk's claim of an exact single-scattering solution (studies/height_fog.h). */
#ifndef GTLAB_REPORT_HEIGHT_FOG_SECTION_H
#define GTLAB_REPORT_HEIGHT_FOG_SECTION_H

#include "report/report_context.h"
#include "studies/height_fog.h"

/* Adds the section to ctx's report, summary.json ("height_fog") and the
 * claims table; -1 (e set) on failure. */
int height_fog_section(report_context *ctx, const height_fog_result *r, gt_error *e);

#endif
