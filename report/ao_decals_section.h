/* INSIDE's analytic AO decals against the AO reference (studies/ao_decals.h). */
#ifndef GTLAB_REPORT_AO_DECALS_SECTION_H
#define GTLAB_REPORT_AO_DECALS_SECTION_H

#include "report/report_context.h"
#include "studies/ao_decals.h"

/* Adds the section to ctx's report, summary.json and claims; -1 (e set) on failure. */
int ao_decals_section(report_context *ctx, const ao_decals_result *r, gt_error *e);

#endif
