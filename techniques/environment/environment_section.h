/* The environment section of `gtlab all` (environment/environment_study.h): the error
 * of engines' ambient combinations under real environments, split into the
 * lighting's and the occlusion's parts; the specular-occlusion ranking
 * against the white dome's; side-by-side images with DSSIM maps; the GTAO
 * talk's claim about AO x a pre-convolved probe. Renders the results struct
 * alone (a test may hand it one it made up). */
#ifndef GTLAB_ENVIRONMENT_ENVIRONMENT_SECTION_H
#define GTLAB_ENVIRONMENT_ENVIRONMENT_SECTION_H

#include "report/report_context.h"
#include "environment/environment_study.h"

/* Adds the section to ctx's report, summary.json and claims table. */
int environment_section(report_context *ctx, const environment_study_result *r, gt_error *e);

#endif
