/* Ray throughput of the AO reference against raw Embree, measured in this run. */
#ifndef GTLAB_THROUGHPUT_RAY_THROUGHPUT_SECTION_H
#define GTLAB_THROUGHPUT_RAY_THROUGHPUT_SECTION_H

#include "report/report_context.h"
#include "throughput/ray_throughput_study.h"

/* Adds the section to ctx's report and summary.json; -1 (e set) if a file it
 * writes could not be made. */
int ray_throughput_section(report_context *ctx, const ray_throughput_result *r, gt_error *e);

#endif
