/* GTAO, HBAO and VO against the height-field and 3-D AO references: scores,
 * heatmaps, the convergence plot, and GTAO's parameters tuned by DSSIM
 * (written as gtao/params_fit.json too). */
#ifndef GTLAB_GTAO_GTAO_SECTION_H
#define GTLAB_GTAO_GTAO_SECTION_H

#include "gtao/gtao_validation.h"
#include "report/report_context.h"

/* Adds the section to ctx's report and summary.json; -1 (e set) if a file it
 * writes could not be made. */
int gtao_section(report_context *ctx, const gtao_validation_result *r, gt_error *e);

#endif
