/* The volumetric-light section of `gtlab all` (volumetric_light/volumetric_light_study.h). */
#ifndef GTLAB_VOLUMETRIC_LIGHT_SECTION_H
#define GTLAB_VOLUMETRIC_LIGHT_SECTION_H

#include "report/report_context.h"
#include "volumetric_light/volumetric_light_study.h"

int volumetric_light_section(report_context *ctx, const volumetric_light_result *r, gt_error *e);

#endif
