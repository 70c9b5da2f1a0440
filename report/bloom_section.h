/* The bloom downsample's 13 -> 9 tap refit (INSIDE, GDC 2016; studies/bloom.h). */
#ifndef GTLAB_REPORT_BLOOM_SECTION_H
#define GTLAB_REPORT_BLOOM_SECTION_H

#include "report/report_context.h"
#include "studies/bloom.h"

/* Adds the section to ctx's report, summary.json and claims; -1 (e set) on failure. */
int bloom_section(report_context *ctx, const bloom_result *r, gt_error *e);

#endif
