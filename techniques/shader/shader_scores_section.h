/* The project's shaders and plug-ins (issue 15, item 6): the functions and
 * plug-ins a project file lists, scored on the multi-bounce references beside
 * gtlab's own variants (multibounce/multibounce_score.h), in one table, and on
 * the specular-occlusion references (specular_occlusion/specular_occlusion_score.h), in
 * another, each only when a listed file implements its quantity. A run
 * without such lists adds nothing to the report or summary.json. */
#ifndef GTLAB_SHADER_SHADER_SCORES_SECTION_H
#define GTLAB_SHADER_SHADER_SCORES_SECTION_H

#include "multibounce/multibounce_score.h"
#include "report/report_context.h"
#include "shader/shader_scores.h"

/* Adds the section (nothing when r->variant_count == 0); returns 0. */
int multibounce_score_section(report_context *ctx, const function_score_result *r, gt_error *e);

/* The same for specular occlusion ("Your shaders and plug-ins: specular
 * occlusion", summary.json's shader_scores_specular_occlusion). */
int specular_occlusion_score_section(report_context *ctx, const function_score_result *r, gt_error *e);

/* The stage's sections: multi-bounce, then specular occlusion. */
int shader_scores_section(report_context *ctx, const shader_scores_result *r, gt_error *e);

#endif
