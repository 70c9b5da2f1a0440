/* The bloom downsample's 13 -> 9 tap refit (INSIDE, GDC 2016; bloom_study.h). */
#ifndef GTLAB_BLOOM_BLOOM_SECTION_H
#define GTLAB_BLOOM_BLOOM_SECTION_H

#include "bloom/bloom_study.h"
#include "report/report_context.h"

/* Adds the section to ctx's report, summary.json and claims; -1 (e set) on failure. */
int bloom_section(report_context *ctx, const bloom_result *r, gt_error *e);

#endif
