/* GGX sphere lights: GetNoHSquared's accuracy, the Decima refit (written as
 * fits/sphere_light.json), error maps, scenes and cost. */
#ifndef GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_SECTION_H
#define GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_SECTION_H

#include "report/report_context.h"
#include "sphere_light/sphere_light_study.h"

/* Adds the section to ctx's report and summary.json; -1 (e set) if a file it
 * writes could not be made. */
int sphere_light_section(report_context *ctx, const sphere_light_result *r, gt_error *e);

#endif
