/* A user's specular-occlusion functions and plug-ins scored like gtlab's own
 * variants (issue 15, items 3 and 5): `gtlab shader score --quantity
 * specular-occlusion --function F.glsl|F.hlsl --plugin lib.so --ao AO.exr
 * ... REF.exr ...` (the function contract gpu_function_specular_occlusion,
 * the plug-in entry point gtlab_specular_occlusion_v1).
 *
 * The data are the specular-occlusion study's (specular_occlusion/specular_occlusion_study.h):
 * a reference made by `gtlab render specular-occlusion` (specocc.V, GGX,
 * its roughness) and the `gtlab render ao` of the same view (ao.V, the bent
 * normal), read into the per-pixel inputs as the study reads them
 * (aperture_case_from_images). Every variant takes the AO reference's
 * inputs and is scored against specocc.V with the study's own scoring
 * (so_study_add_scores: DSSIM, RMSE over the mask), beside the study's noise
 * floor (the even and odd samples' ratios against each other). The
 * variants: gtlab's AO alone, Lagarde's, GTSO's cone/cone (exact caps and
 * Oat and Sander's, cos a_s = 2^(-3.32193 alpha^2)) and the spherical
 * Gaussians, then each function file and each plug-in, in the order given.
 * One row per reference (its scene and roughness) and the mean row. The
 * quantity-agnostic part is scoring/function_score.h's. */
#ifndef GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_SCORE_H
#define GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_SCORE_H

#include "core/error.h"
#include "scoring/function_score.h"
#include "project/study_context.h"

#define SO_SCORE_QUANTITY "specular-occlusion"

/* The quantity: gtlab_specular_occlusion(ao, beta, roughness, n_dot_v), gtlab_specular_occlusion_v1. */
extern const function_score_quantity specular_occlusion_scored_quantity;

typedef struct {
    const char *const *references; /* EXRs of `gtlab render specular-occlusion` */
    int reference_count;
    const char *const *aos;        /* the AO reference of each reference's view */
    int ao_count;
    function_score_files files;
} specular_occlusion_score_request;

/* Scores rq (rq->aos[i] the AO reference of rq->references[i]). Returns 0,
 * or -1 with e naming the file at fault: a reference or AO file without its
 * channels, a function or plug-in that cannot be loaded or compiled or that
 * has no specular occlusion, NaN, no Vulkan device. */
int specular_occlusion_score(const specular_occlusion_score_request *rq, function_score_result *out, gt_error *e);

/* For the stage of `gtlab all` (techniques/shader/shader_scores.h): a project's
 * specular-occlusion function files and plug-ins scored on the study's
 * references of every scene and roughness, rendered again as the study
 * renders them (so_study_render; the study keeps its own in memory only)
 * into <output>/SO_SCORE_DIR as <scene>_ao.exr and <scene>_r<roughness>.exr
 * (so `gtlab shader score` can score more files on them later). With both
 * lists empty it renders nothing and out->variant_count = 0. */
#define SO_SCORE_DIR "shader_scores"
int specular_occlusion_score_project(const study_context *ctx, const char *const *functions, int function_count,
                                     const char *const *plugins, int plugin_count, function_score_result *out,
                                     gt_error *e);

#endif
