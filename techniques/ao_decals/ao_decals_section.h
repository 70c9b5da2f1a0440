/* INSIDE's analytic AO decals against the AO reference (ao_decals_study.h). */
#ifndef GTLAB_AO_DECALS_AO_DECALS_SECTION_H
#define GTLAB_AO_DECALS_AO_DECALS_SECTION_H

#include "ao_decals/ao_decals_study.h"
#include "report/report_context.h"

/* Adds the section to ctx's report, summary.json and claims; -1 (e set) on failure. */
int ao_decals_section(report_context *ctx, const ao_decals_result *r, gt_error *e);

#endif
