/* The Kulla-Conty energy compensation's section of `gtlab all`
 * (kulla_conty_study.h): the energy single scattering loses, and what the
 * average-albedo table's size costs the white furnace. */
#ifndef GTLAB_KULLA_CONTY_SECTION_H
#define GTLAB_KULLA_CONTY_SECTION_H

#include "kulla_conty/kulla_conty_study.h"
#include "report/report_context.h"

/* The smallest scored size whose furnace error is below the Weber fraction
 * (report/claim_thresholds.h), or 0 when none is. */
int kulla_conty_smallest_invisible_size(const kulla_conty_result *r);

/* Adds the section to ctx's report and summary.json; 0 (it writes no file). */
int kulla_conty_section(report_context *ctx, const kulla_conty_result *r, gt_error *e);

#endif
