/* The GTAO section's part on visibility-bitmask AO (issue 27, item 1;
 * vbao_study.h): the ranking beside GTAO, VBAO's error split into
 * the estimator's and the screen space's, and the best thickness per scene,
 * with the members of the summary object `vbao`. */
#ifndef GTLAB_GTAO_VBAO_SECTION_H
#define GTLAB_GTAO_VBAO_SECTION_H

#include <cjson/cJSON.h>

#include "gtao/vbao_study.h"
#include "report/report_context.h"

void vbao_section(report_context *ctx, const vbao_study_result *r, cJSON *summary);

#endif
