/* A user's multi-bounce function scored like gtlab's own (issue 15, items
 * 3, 5 and 6): `gtlab shader score --function F.glsl|F.hlsl` (the function
 * contract, gpu/function_shader.h), `--plugin lib.so` (core/plugin_abi.h)
 * and the project's `shaders`/`plugins` in `gtlab all --project`.
 *
 * The data are the multi-bounce study's (studies/multibounce.h): references
 * made by `gtlab render multibounce --albedo ...`, grey albedos. As in its
 * validation, per reference and albedo every variant takes V_d of the
 * even-sample half and is scored against V'_d of the odd-sample half (DSSIM,
 * RMSE over the surface pixels), beside the noise floor (the even half of
 * V'_d against the odd half); the mean row is the mean over the rows. The
 * variants: V_d alone and the talk's GTAOMultiBounce (gtlab's own, always),
 * then each function file and each plug-in, in the order given. */
#ifndef GTLAB_STUDIES_MULTIBOUNCE_SCORE_H
#define GTLAB_STUDIES_MULTIBOUNCE_SCORE_H

#include <stdio.h>

#include "core/error.h"
#include "studies/study.h"

enum {
    MB_SCORE_MAX_FILES = 16,    /* references, function files, plug-ins: each at most */
    MB_SCORE_MAX_ALBEDOS = 8,   /* per reference (the study renders 7) */
    MB_SCORE_MAX_VARIANTS = 2 + 2 * MB_SCORE_MAX_FILES,
    MB_SCORE_MAX_ROWS = MB_SCORE_MAX_FILES * MB_SCORE_MAX_ALBEDOS,
    MB_SCORE_NAME = 128
};

typedef struct {
    const char *quantity;          /* "multibounce" (NULL: the same) or "specular-occlusion"
                                      (studies/specular_occlusion_score.h); named "--quantity" in errors */
    const char *const *references; /* EXRs of `gtlab render multibounce` */
    int reference_count;
    const char *const *functions;  /* GLSL/HLSL function files */
    int function_count;
    const char *const *plugins;    /* shared libraries */
    int plugin_count;
    const char *device;            /* a Vulkan device name substring, or NULL */
    double timeout;                /* seconds per dispatch */
    const char *const *aos;        /* specular-occlusion: the AO reference of each reference's view */
    int ao_count;
} multibounce_score_request;

/* One reference and albedo. */
typedef struct {
    char scene[MB_SCORE_NAME]; /* the file's gtlab.scene, or "mean" */
    double albedo;
    double noise_floor_dssim, noise_floor_rmse;
    double dssim[MB_SCORE_MAX_VARIANTS], rmse[MB_SCORE_MAX_VARIANTS];
} multibounce_score_row;

/* One variant's means over the rows (the report's table). */
typedef struct {
    char name[MB_SCORE_NAME]; /* "V_d", "talk", or the file's name */
    const char *kind;         /* "gtlab", "function", "plug-in" */
    double dssim, rmse;
    double dssim_floor, rmse_floor; /* the mean noise floors, alike for every variant */
} multibounce_score_variant;

typedef struct {
    int variant_count, row_count;
    multibounce_score_variant variants[MB_SCORE_MAX_VARIANTS];
    multibounce_score_row rows[MB_SCORE_MAX_ROWS];
    multibounce_score_row mean;
    char device[MB_SCORE_NAME]; /* the Vulkan device of the function files; "" without any */
    const char *parameter;      /* the rows' parameter: "albedo", or "roughness" for specular occlusion */
    const char *caption;        /* the table's first line */
} multibounce_score_result;

/* Scores the request's variants (a specular-occlusion request:
 * specular_occlusion_score). Returns 0, or -1 with e naming the file at
 * fault: a reference that is not a grey multi-bounce render, a plug-in or a
 * function that cannot be loaded or compiled, NaN, no Vulkan device. */
int multibounce_score(const multibounce_score_request *rq, multibounce_score_result *out, gt_error *e);

/* The mean row and each variant's means from the rows. */
void multibounce_score_take_means(multibounce_score_result *out);
/* A request has something to score and at most MB_SCORE_MAX_FILES files of
 * each kind: 0, or -1 with e. */
int multibounce_score_check_files(const multibounce_score_request *rq, gt_error *e);

/* The table: one row per reference and albedo and the mean; DSSIM and RMSE
 * columns per variant, after the floor. */
void multibounce_score_print(FILE *f, const multibounce_score_result *r);

/* For the stage of `gtlab all` (studies/shader_scores.h): a project's
 * multi-bounce function files and plug-ins scored on the multi-bounce
 * study's references in <output>/MULTIBOUNCE_STUDY_DIR (*.exr, in name
 * order). With both lists empty it reads nothing and out->variant_count = 0. */
int multibounce_score_project(const study_context *ctx, const char *const *functions, int function_count,
                              const char *const *plugins, int plugin_count, multibounce_score_result *out,
                              gt_error *e);

#endif
