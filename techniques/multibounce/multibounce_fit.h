/* The GTAO multi-bounce refit (Jimenez et al. 2016, "Fitting for a Fixed
 * Albedo" to "Finding a Symbolic Expression"; issue 3): samples (V_d, V'_d,
 * rho) from multi-bounce references, fitted through the Ceres bridge with
 * the model of multibounce/multibounce.h (the formula lives there only):
 *   - per albedo, the cubic V'_d = ((a V_d + b) V_d + c) V_d (degree 0);
 *   - jointly over all albedos, a, b, c linear in rho (degree 1, the talk's);
 *   - two alternatives: a, b, c quadratic in rho (degree 2), and the
 *     anchored form (multibounce_model_anchored: 4 parameters, exact at
 *     rho = 0 and V_d = 0, 1), reported beside the linear model; the model
 *     with the lowest leave-one-scene-out error is the one chosen.
 * Weighting: each (scene, albedo) group of samples carries the same total
 * weight, so every scene and every albedo counts equally whatever its pixel
 * count; weights are scaled to mean 1. A sample's residual is
 * sqrt(w) (cubic(V_d) - V'_d). Fits use the cubic without the max(x, .) of
 * the shader (it is not differentiable and the fit should not depend on
 * it); the errors are reported with and without it. */
#ifndef GTLAB_MULTIBOUNCE_MULTIBOUNCE_FIT_H
#define GTLAB_MULTIBOUNCE_MULTIBOUNCE_FIT_H

#include <stddef.h>
#include <stdio.h>

#include "core/error.h"
#include "core/image.h"
#include "fitters/ceres_bridge.h"
#include "multibounce/multibounce.h"

/* "The cubic lies below V_d" counts only shortfalls beyond this: the
 * talk's coefficients, rounded to 4 decimals, give V'_d(1) = 0.9996 to
 * 1.0001, a rounding shortfall at every unoccluded pixel. */
#define MBFIT_BELOW_MARGIN 1e-3

enum { MBFIT_MAX_SCENES = 64, MBFIT_MAX_ALBEDOS = 32, MBFIT_NAME_MAX = 256, MBFIT_DEFAULT_BLOCK = 1024 };

typedef struct {
    float visibility;   /* V_d (ao.V) */
    float multibounce;  /* V'_d */
    float albedo;
    float weight;       /* from multibounce_data_weigh */
    short scene, albedo_index;
} multibounce_sample;

typedef struct {
    multibounce_sample *samples;
    size_t count, capacity;
    int scene_count, albedo_count, file_count;
    char scenes[MBFIT_MAX_SCENES][MBFIT_NAME_MAX];
    float albedos[MBFIT_MAX_ALBEDOS];
    char **files;
    char bounces[16];   /* the references' --bounces, "" before the first file */
    size_t group_count[MBFIT_MAX_SCENES][MBFIT_MAX_ALBEDOS];
} multibounce_data;

void multibounce_data_init(multibounce_data *d);
void multibounce_data_free(multibounce_data *d);

/* Index of a scene / albedo, added if new; -1 with e when the lists are full. */
int multibounce_data_scene(multibounce_data *d, const char *name, gt_error *e);
int multibounce_data_albedo(multibounce_data *d, float albedo, gt_error *e);
/* Appends one sample (weights are set by multibounce_data_weigh). */
int multibounce_data_push(multibounce_data *d, int scene, int albedo_index, float visibility, float multibounce,
                          gt_error *e);

/* The samples of a reference made by `gtlab render multibounce --albedo ...`
 * (grey albedos): every pixel with mask.A != 0 gives one sample per albedo
 * (ao.V, multibounce[_<rho>].V). The scene is the file's gtlab.scene. Errors
 * name `path`: not a multibounce render, coloured (--albedo scene), missing
 * channels, values outside [0, 1], no surface pixel, a --bounces setting
 * different from earlier files; after an error the data may hold part of
 * the file's samples and should be discarded. Then call
 * multibounce_data_weigh. */
int multibounce_data_add_image(multibounce_data *d, const image *img, const char *path, gt_error *e);

/* The grey albedos of a `gtlab render multibounce --albedo ...` reference
 * and the channel of each (multibounce[_<rho>].V), in the file's order:
 * the header checks of multibounce_data_add_image (a multibounce render,
 * grey albedos, a valid list). Returns 0, or -1 with e naming `path`. */
int multibounce_image_albedos(const image *img, const char *path, float albedos[MBFIT_MAX_ALBEDOS],
                              char channels[MBFIT_MAX_ALBEDOS][64], int *count, gt_error *e);

/* Sets every weight: each non-empty (scene, albedo) group gets equal total
 * weight, scaled so that the mean weight is 1. */
void multibounce_data_weigh(multibounce_data *d);

/* A copy of the samples of scene `scene` (or of all scenes but it, when
 * exclude; every scene when scene < 0) and of albedo `albedo_index` (every
 * albedo when < 0), reweighed. Scene and albedo indices are kept. */
int multibounce_data_select(const multibounce_data *d, int scene, int exclude, int albedo_index,
                            multibounce_data *out, gt_error *e);

typedef struct {
    int anchored;       /* 1: parameters p1, q1, p2, q2 of multibounce_model_anchored;
                           0: the model's own coefficients a[0..d], b[..], c[..] */
    multibounce_model model;
    int parameter_count;
    double params[MULTIBOUNCE_MAX_PARAMETERS];
    double standard_errors[MULTIBOUNCE_MAX_PARAMETERS];
    double covariance[MULTIBOUNCE_MAX_PARAMETERS * MULTIBOUNCE_MAX_PARAMETERS];
    double residual_variance;
    gt_fit_result solver;
} multibounce_fit;

typedef struct {
    int block_size;        /* residuals per Ceres block; 0: MBFIT_DEFAULT_BLOCK */
    int skip_covariance;   /* 1: the model only (held-out fits); standard errors stay 0 */
} multibounce_fit_options;

/* Least-squares fit of the model of `degree` (0: one cubic, whatever the
 * albedos) to the weighted samples; options may be NULL (blocks of 1024,
 * with covariance). The normal equations (DENSE_NORMAL_CHOLESKY) solve it:
 * with 3 to 9 parameters and hundreds of thousands of residuals they are
 * several times faster than QR, and the basis (x^3, x^2, x) x rho^k is
 * conditioned well enough for them. Returns 0 or -1 with e (too few samples
 * or albedos to determine the model, solver failure). */
int multibounce_fit_model(const multibounce_data *d, int degree, const multibounce_fit_options *options,
                          multibounce_fit *out, gt_error *e);
/* The same for the anchored form (multibounce/multibounce.h; 2+ albedos). */
int multibounce_fit_anchored(const multibounce_data *d, const multibounce_fit_options *options,
                             multibounce_fit *out, gt_error *e);

/* "a0", "b1", ... ("a", "b", "c" at degree 0; "p1", "q1", "p2", "q2" anchored). */
void multibounce_fit_parameter_name(const multibounce_fit *f, int index, char *name, size_t size);

typedef struct {
    size_t samples;
    double rmse;          /* sqrt(sum w r^2 / sum w): scenes and albedos equal */
    double max_abs;       /* max |r| over the samples */
    multibounce_sample worst; /* the sample where it occurs */
    double below;         /* weighted fraction of samples where the cubic < V_d - MBFIT_BELOW_MARGIN */
} multibounce_errors;

/* Errors of the model on the samples, r = model(V_d, rho) - V'_d, with the
 * shader's max(V_d, .) (with_max) or the bare cubic. */
void multibounce_measure(const multibounce_data *d, const multibounce_model *m, int with_max, multibounce_errors *out);

/* max over V_d in [0, 1] of V_d - cubic(V_d) at this albedo (on a grid of
 * 1001 points; <= 0 when the cubic never falls below V_d): how much the
 * shader's max(V_d, .) can change. */
double multibounce_max_shortfall(const multibounce_model *m, double albedo);

/* ---- The whole analysis of `gtlab fit multibounce` ---------------------------------- */

/* The joint models over all albedos, the candidates of issue 3 (c). */
typedef enum { MB_JOINT_LINEAR, MB_JOINT_QUADRATIC, MB_JOINT_ANCHORED, MB_JOINT_COUNT } multibounce_joint;
/* "joint_linear", "joint_quadratic", "joint_anchored" (JSON keys). */
extern const char *const multibounce_joint_names[MB_JOINT_COUNT];

typedef struct {
    float albedo;
    multibounce_fit fit;                    /* degree 0 */
    multibounce_errors own, linear, talk;   /* with max, on this albedo's samples */
} multibounce_albedo_result;

typedef struct {
    int scene;
    multibounce_model model[MB_JOINT_COUNT];      /* fitted without the scene */
    double params[MB_JOINT_COUNT][MULTIBOUNCE_MAX_PARAMETERS];
    multibounce_errors err[MB_JOINT_COUNT], talk; /* on the held-out scene, with max */
} multibounce_heldout;

typedef struct {
    multibounce_albedo_result per_albedo[MBFIT_MAX_ALBEDOS];
    int has[MB_JOINT_COUNT];                /* quadratic needs 3+ albedos */
    multibounce_fit joint[MB_JOINT_COUNT];
    multibounce_errors joint_err[MB_JOINT_COUNT][2], talk_err[2]; /* [0] bare cubic, [1] with max */
    /* The talk's own procedure, for comparison: lines a0 + a1 rho (etc.)
     * fitted through the per-albedo coefficients, unweighted. */
    multibounce_model two_step;
    multibounce_errors two_step_err;        /* with max, on all the data */
    int heldout_count;                      /* scenes when 2+, else 0 */
    multibounce_heldout heldout[MBFIT_MAX_SCENES];
    double heldout_mean[MB_JOINT_COUNT], heldout_mean_talk;
    /* Jackknife standard errors over scenes (2+ scenes): sqrt((S-1)/S sum
     * (p_without_s - mean)^2) from the leave-one-scene-out fits. They say how
     * much the coefficients move with the content, which the per-pixel
     * standard errors (pixels taken as independent) do not. */
    double jackknife_se[MB_JOINT_COUNT][MULTIBOUNCE_MAX_PARAMETERS];
    multibounce_joint chosen;               /* lowest held-out mean RMSE; linear without 2+ scenes */
} multibounce_analysis;

/* Every fit: per albedo, the joint models, the talk's errors, and
 * leave-one-scene-out. Needs samples at 2+ albedos. */
int multibounce_analyse(const multibounce_data *d, multibounce_analysis *out, gt_error *e);

/* The analysis as `gtlab fit multibounce` prints it: the data's size, each
 * joint model's coefficients with standard errors, the talk's error on the
 * same data, the held-out errors and the model chosen. */
void multibounce_analysis_print(FILE *out, const multibounce_data *d, const multibounce_analysis *a);

/* Writes the JSON (coefficients, standard errors, covariance, errors, the
 * talk's errors, data used), a C header and HLSL and GLSL functions, each
 * atomically; header_path / hlsl_path / glsl_path may be NULL. `command` is
 * recorded. */
int multibounce_write_outputs(const multibounce_data *d, const multibounce_analysis *a, const char *command,
                              const char *json_path, const char *header_path, const char *hlsl_path,
                              const char *glsl_path, gt_error *e);

/* The fit's output files: the JSON and its C header, HLSL and GLSL. */
typedef struct {
    const char *json, *header, *hlsl, *glsl;
    char sibling[3][4096]; /* storage for the derived paths */
} multibounce_output_files;

/* Points a NULL header / hlsl / glsl at the JSON's path with ".json"
 * replaced by .h / .hlsl / .glsl, then checks every path can be written
 * (before any work). 0, or -1 with e naming the file. */
int multibounce_output_files_resolve(multibounce_output_files *f, gt_error *e);

#endif
