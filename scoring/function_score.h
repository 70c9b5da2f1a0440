/* A user's functions and plug-ins scored beside gtlab's own, for any
 * quantity (issue 15, items 3, 5 and 6): `gtlab shader score` and the stage
 * shader-scores of `gtlab all --project`.
 *
 * A quantity's user (multibounce/multibounce_score.h, specular_occlusion/specular_occlusion_score.h)
 * supplies what is its own: its function contract and plug-in entry point
 * (function_score_quantity), its references, its built-in variants, how a
 * variant is scored against a reference and the noise floor. This scorer
 * holds the rest: it loads the function files (checked against the
 * contract, gpu/function_shader.h, compiled on one Vulkan device) and the
 * plug-ins (plugins/plugin_loader.h), applies any of them to the quantity's
 * inputs at the masked pixels, and keeps the table — one row per reference
 * (and parameter value), the mean row, each variant's means — and prints it.
 * The variants are the user's built-ins first, then each function file and
 * each plug-in, in the order given. */
#ifndef GTLAB_SCORING_FUNCTION_SCORE_H
#define GTLAB_SCORING_FUNCTION_SCORE_H

#include <stddef.h>
#include <stdio.h>

#include "core/error.h"
#include "gpu/function_shader.h"

enum {
    FUNCTION_SCORE_MAX_FILES = 16,   /* function files, plug-ins: each at most */
    FUNCTION_SCORE_MAX_BUILTINS = 8, /* a quantity's own variants */
    FUNCTION_SCORE_MAX_VARIANTS = FUNCTION_SCORE_MAX_BUILTINS + 2 * FUNCTION_SCORE_MAX_FILES,
    FUNCTION_SCORE_MAX_ROWS = 128,
    FUNCTION_SCORE_NAME = 128
};

/* What a quantity's user names: its function files' contract and its
 * plug-ins' entry point, whose arguments are the contract's inputs in order. */
typedef struct {
    const char *name;                       /* in errors: "specular occlusion" */
    const gpu_function_contract *function;  /* gpu/function_shader.h */
    const char *plugin_symbol;              /* core/plugin_abi.h */
} function_score_quantity;

/* The user's files and how to run them. */
typedef struct {
    const char *const *functions; /* GLSL/HLSL function files */
    int function_count;
    const char *const *plugins;   /* shared libraries */
    int plugin_count;
    const char *device;           /* a Vulkan device name substring, or NULL */
    double timeout;               /* seconds per dispatch; <= 0: 10 */
} function_score_files;

/* One reference (and parameter value). */
typedef struct {
    char scene[FUNCTION_SCORE_NAME]; /* the file's gtlab.scene, or "mean" */
    double value;                    /* the row's parameter (an albedo, a roughness); NaN: none */
    double noise_floor_dssim, noise_floor_rmse;
    double dssim[FUNCTION_SCORE_MAX_VARIANTS], rmse[FUNCTION_SCORE_MAX_VARIANTS];
} function_score_row;

/* One variant's means over the rows (the report's table). */
typedef struct {
    char name[FUNCTION_SCORE_NAME]; /* a built-in's name, or the file's */
    const char *kind;               /* "gtlab", "function", "plug-in" */
    double dssim, rmse;
    double dssim_floor, rmse_floor; /* the mean noise floors, alike for every variant */
} function_score_variant;

typedef struct {
    int variant_count, row_count;
    function_score_variant variants[FUNCTION_SCORE_MAX_VARIANTS];
    function_score_row rows[FUNCTION_SCORE_MAX_ROWS];
    function_score_row mean;
    char device[FUNCTION_SCORE_NAME]; /* the Vulkan device of the function files; "" without any */
    const char *parameter;            /* the rows' parameter: "albedo", "roughness" */
    const char *caption;              /* the table's first line */
} function_score_result;

/* The user's files loaded: their texts, the device, the plug-ins. */
typedef struct function_scorer function_scorer;

/* A built-in variant named (before function_scorer_open): its rows are the user's to fill. */
void function_score_add_builtin(function_score_result *out, const char *name);

/* The request has something to score and at most FUNCTION_SCORE_MAX_FILES
 * files of each kind: 0, or -1 with e. */
int function_score_check_files(const function_score_files *f, gt_error *e);

/* Names each function file and plug-in as a variant after the built-ins and
 * loads it: a function file checked against q's contract (the Vulkan
 * device opened at the first), a plug-in that must export q's entry point.
 * Returns 0 with *s (function_scorer_close frees it, also after a
 * failure), or -1 with e naming the file at fault. */
int function_scorer_open(const function_score_quantity *q, const function_score_files *f, function_score_result *out,
                         function_scorer **s, gt_error *e);
void function_scorer_close(function_scorer *s);

/* Variant k (a function file or a plug-in: k at or after the built-ins) at
 * the n pixels with mask != 0, 0 elsewhere: its input j is planes[j][p], or
 * constants[j] where planes[j] is NULL. Returns 0, or -1 with e (a compile
 * error, a device timeout, NaN). */
int function_scorer_apply(const function_scorer *s, int k, const float *const planes[], const float constants[],
                          const float *mask, size_t n, float *out, gt_error *e);

/* The mean row and each variant's means from the rows. */
void function_score_take_means(function_score_result *out);

/* The table: one row per reference and the mean; DSSIM and RMSE columns per
 * variant, after the floor. */
void function_score_print(FILE *f, const function_score_result *r);

#endif
