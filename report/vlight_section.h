/* The volumetric-light section of `gtlab all` (studies/vlight.h). */
#ifndef GTLAB_REPORT_VLIGHT_SECTION_H
#define GTLAB_REPORT_VLIGHT_SECTION_H

#include "report/report_context.h"
#include "studies/vlight.h"

int vlight_section(report_context *ctx, const vlight_result *r, gt_error *e);

#endif
