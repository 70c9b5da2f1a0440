/* The stage `shader-scores` of `gtlab all --project` (issue 15, item 6): the
 * project's `shaders` (function files) and `plugins`, each scored for every
 * quantity it implements — a function file defining gtlab_multibounce
 * and/or gtlab_specular_occlusion (gpu/function_shader.h), a plug-in
 * exporting gtlab_multibounce_v1 and/or gtlab_specular_occlusion_v1
 * (core/plugin_abi.h) — on that quantity's references beside gtlab's own
 * variants: studies/multibounce_score.h (the multibounce stage's references)
 * and studies/specular_occlusion_score.h (the specular-occlusion study's,
 * rendered again). A function file that implements neither is an error.
 * Without a project, or with both lists empty, it reads and renders nothing
 * and both results have variant_count = 0. */
#ifndef GTLAB_STUDIES_SHADER_SCORES_H
#define GTLAB_STUDIES_SHADER_SCORES_H

#include "studies/multibounce_score.h"

typedef struct {
    multibounce_score_result multibounce, specular_occlusion;
} shader_scores_result;

int shader_scores_project(const study_context *ctx, shader_scores_result *out, gt_error *e);

#endif
