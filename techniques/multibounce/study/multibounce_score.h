/* A user's multi-bounce function scored like gtlab's own (issue 15, items
 * 3, 5 and 6): `gtlab shader score --function F.glsl|F.hlsl` (the function
 * contract, gpu/function_shader.h), `--plugin lib.so` (core/plugin_abi.h)
 * and the project's `shaders`/`plugins` in `gtlab all --project`.
 *
 * The data are the multi-bounce study's (multibounce/multibounce_study.h): references
 * made by `gtlab render multibounce --albedo ...`, grey albedos. As in its
 * validation, per reference and albedo every variant takes V_d of the
 * even-sample half and is scored against V'_d of the odd-sample half (DSSIM,
 * RMSE over the surface pixels), beside the noise floor (the even half of
 * V'_d against the odd half); the mean row is the mean over the rows. The
 * variants: V_d alone and the talk's GTAOMultiBounce (gtlab's own, always),
 * then each function file and each plug-in, in the order given. The
 * quantity-agnostic part (loading and applying the user's files, the table,
 * the means) is scoring/function_score.h's; this file supplies the
 * multi-bounce references, rows and built-ins. */
#ifndef GTLAB_MULTIBOUNCE_MULTIBOUNCE_SCORE_H
#define GTLAB_MULTIBOUNCE_MULTIBOUNCE_SCORE_H

#include "core/error.h"
#include "scoring/function_score.h"
#include "project/study_context.h"

enum { MB_SCORE_MAX_ALBEDOS = 8 }; /* per reference (the study renders 7) */

/* The quantity: gtlab_multibounce(visibility, albedo), gtlab_multibounce_v1. */
extern const function_score_quantity multibounce_scored_quantity;

typedef struct {
    const char *const *references; /* EXRs of `gtlab render multibounce` */
    int reference_count;
    function_score_files files;
} multibounce_score_request;

/* Scores the request's variants. Returns 0, or -1 with e naming the file at
 * fault: a reference that is not a grey multi-bounce render, a plug-in or a
 * function that cannot be loaded or compiled, NaN, no Vulkan device. */
int multibounce_score(const multibounce_score_request *rq, function_score_result *out, gt_error *e);

/* For the stage of `gtlab all` (techniques/shader/shader_scores.h): a project's
 * multi-bounce function files and plug-ins scored on the multi-bounce
 * study's references in <output>/MULTIBOUNCE_STUDY_DIR (*.exr, in name
 * order). With both lists empty it reads nothing and out->variant_count = 0. */
int multibounce_score_project(const study_context *ctx, const char *const *functions, int function_count,
                              const char *const *plugins, int plugin_count, function_score_result *out,
                              gt_error *e);

#endif
