/* The temporal part of the anti-aliasing section (anti_aliasing/aa_temporal_study.h):
 * tables, frame strips and error maps, and the claims rows of the talk's
 * TAA and checkerboard statements. Called by aa_section. */
#ifndef GTLAB_ANTI_ALIASING_AA_TEMPORAL_SECTION_H
#define GTLAB_ANTI_ALIASING_AA_TEMPORAL_SECTION_H

#include "anti_aliasing/aa_temporal_study.h"
#include "report/report_context.h"

void aa_temporal_section(report_context *ctx, cJSON *json, const aa_temporal_result *r);

#endif
