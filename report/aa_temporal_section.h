/* The temporal part of the anti-aliasing section (studies/aa_temporal.h):
 * tables, frame strips and error maps, and the claims rows of the talk's
 * TAA and checkerboard statements. Called by aa_section. */
#ifndef GTLAB_REPORT_AA_TEMPORAL_SECTION_H
#define GTLAB_REPORT_AA_TEMPORAL_SECTION_H

#include "report/report_context.h"
#include "studies/aa_temporal.h"

void aa_temporal_section(report_context *ctx, cJSON *json, const aa_temporal_result *r);

#endif
