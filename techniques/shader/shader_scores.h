/* The stage `shader-scores` of `gtlab all --project` (issue 15, item 6): the
 * project's `shaders` (function files) and `plugins`, each scored for every
 * quantity it implements — a function file defining gtlab_multibounce
 * and/or gtlab_specular_occlusion (gpu/function_shader.h), a plug-in
 * exporting gtlab_multibounce_v1 and/or gtlab_specular_occlusion_v1
 * (core/plugin_abi.h) — on that quantity's references beside gtlab's own
 * variants: multibounce/multibounce_score.h (the multibounce stage's references)
 * and specular_occlusion/specular_occlusion_score.h (the specular-occlusion study's,
 * rendered again), the two users of scoring/function_score.h. A function
 * file that implements neither is an error.
 * Without a project, or with both lists empty, it reads and renders nothing
 * and both results have variant_count = 0. */
#ifndef GTLAB_SHADER_SHADER_SCORES_H
#define GTLAB_SHADER_SHADER_SCORES_H

#include "scoring/function_score.h"
#include "project/study_context.h"

typedef struct {
    function_score_result multibounce, specular_occlusion;
} shader_scores_result;

int shader_scores_project(const study_context *ctx, shader_scores_result *out, gt_error *e);

/* `gtlab shader score`: the user's files scored for the quantity named. */
typedef struct {
    const char *quantity;          /* "multibounce" (NULL: the same) or "specular-occlusion"; "--quantity" in errors */
    const char *const *references; /* EXRs of `gtlab render <quantity>` */
    int reference_count;
    const char *const *aos;        /* specular occlusion: the AO reference of each reference's view */
    int ao_count;
    function_score_files files;
} shader_score_request;

/* multibounce_score or specular_occlusion_score by rq->quantity. Returns 0,
 * or -1 with e (an unknown quantity, the scorer's errors). */
int shader_score(const shader_score_request *rq, function_score_result *out, gt_error *e);

#endif
