/* The project's screen-space shaders scored beside gtlab's GTAO (issue 15,
 * item 6): each file of a project's `screen_shaders` (docs/shaders.md's
 * screen-space contract, with the project's parameters) runs on Vulkan over
 * each AO reference's G-buffer (the ao stage's <output>/ao/<scene>.exr,
 * which carries depth.Z, N, P, albedo, mask.A, the bent normal and the
 * camera) and its ao.V is scored as the GTAO study scores gtlab's own
 * variants (techniques/gtao/study/ao_image_score.h): RMSE, DSSIM and FLIP against
 * the 3-D reference, and the paired difference of squared errors against
 * gtlab's C GTAO on the same pixels with its 8x8-block standard error,
 * pooled over the scenes. The first row is that C GTAO, in the
 * configuration of techniques/gtao/gtao.glsl at its gtlab.param defaults
 * (cosine weighting, 4 regular slices, 8 steps per side, radius 1, falloff
 * 0.25, at most 256 pixels, no thickness, no denoiser, one frame), so the
 * shader run with its defaults is a sanity line: its largest difference from
 * the C image is within the bound of tests/test_gpu_screen_pass.c (2e-3). */
#ifndef GTLAB_SHADER_SCREEN_SHADER_SCORE_H
#define GTLAB_SHADER_SCREEN_SHADER_SCORE_H

#include "gtao/ao_image_score.h"
#include "metrics/cluster_mean.h"
#include "project/study_context.h"
#include "project/project_file.h"
#include "project/scene_list.h"

enum { SCREEN_SCORE_MAX_VARIANTS = 1 + PROJECT_MAX_FILES, SCREEN_SCORE_MAX_SCENES = STUDY_SCENES_MAX, SCREEN_SCORE_NAME = 128 };

typedef struct {
    char name[SCREEN_SCORE_NAME]; /* "GTAO (C)" or the file's name */
    const char *kind;             /* "gtlab", "shader" */
    double dssim, flip;           /* means over the scenes */
    double rmse;                  /* pooled: sqrt of the pixel-weighted mean MSE */
    cluster_mean vs_gtao;         /* pooled (AO - 3-D)^2 - (GTAO (C) - 3-D)^2 */
    double max_diff_vs_c;         /* the largest |AO - GTAO (C)| over every scene's mask */
} screen_shader_variant;

typedef struct {
    int variant_count, scene_count;
    screen_shader_variant variants[SCREEN_SCORE_MAX_VARIANTS];
    ao_image_score scores[SCREEN_SCORE_MAX_SCENES][SCREEN_SCORE_MAX_VARIANTS];
    char device[SCREEN_SCORE_NAME];
} screen_shader_score_result;

/* The stage screen-shaders: every shader compiled first (a bad one stops the
 * stage before any reference is read), then run on the first
 * SCREEN_SCORE_MAX_SCENES scenes' AO references. Without a project or with
 * no screen_shaders it reads nothing and out->variant_count = 0. Returns 0,
 * or -1 with e naming the file at fault. */
int screen_shader_score_project(const study_context *ctx, screen_shader_score_result *out, gt_error *e);

#endif
