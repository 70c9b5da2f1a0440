/* The GTAO talk's shortcuts measured against the references (issue 25,
 * items 9-13): one subsection of the report and one claims-table row per
 * item, each rendered from its study's results struct, with the members of
 * the summary object `gtao_shortcuts`. */
#ifndef GTLAB_GTAO_GTAO_CHECKS_SECTION_H
#define GTLAB_GTAO_GTAO_CHECKS_SECTION_H

#include <cjson/cJSON.h>

#include "report/report_context.h"
#include "gtao/gtao_checks.h"
#include "gtao/gtao_baselines.h"
#include "gtao/gtao_bent_normals.h"
#include "gtao/gtao_distance_fade.h"
#include "gtao/gtao_fast_math.h"
#include "gtao/gtao_thickness.h"

/* The claims' tolerance for "no visible change": one step of an 8-bit AO
 * buffer, 1/255, as a mean squared error. */
#define GTAO_SHORTCUT_VISIBLE_MSE ((1.0 / 255.0) * (1.0 / 255.0))

void gtao_fast_math_section(report_context *ctx, const gtao_fast_math_result *r, cJSON *summary);
void gtao_baselines_section(report_context *ctx, const gtao_baselines_result *r, cJSON *summary);
void gtao_bent_normals_section(report_context *ctx, const gtao_bent_normals_result *r, cJSON *summary);
void gtao_thickness_section(report_context *ctx, const gtao_thickness_result *r, cJSON *summary);
void gtao_distance_fade_section(report_context *ctx, const gtao_distance_fade_result *r, cJSON *summary);

/* The section: a heading, its introduction, the five subsections and the
 * summary object `gtao_shortcuts`. */
void gtao_checks_section(report_context *ctx, const gtao_checks_result *r);

#endif
