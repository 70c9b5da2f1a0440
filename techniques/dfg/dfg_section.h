/* The split-sum DFG LUT: its accuracy, and the bilinear lookup's error
 * against the table size beside Filament's 128^2 (figures/dfg_interpolation.png). */
#ifndef GTLAB_DFG_SECTION_H
#define GTLAB_DFG_SECTION_H

#include "dfg/dfg_study.h"
#include "report/report_context.h"

/* Adds the section to ctx's report and summary.json; -1 (e set) if a file it
 * writes could not be made. */
int dfg_section(report_context *ctx, const dfg_result *r, gt_error *e);

#endif
