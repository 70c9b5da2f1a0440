/* The record of the sphere-light refit (fit_sphere_light.h; the study that
 * draws the configurations and renders their references is
 * sphere_light/sphere_light_study.h, sphere_fit_study) and the files an engine and a
 * person take from it: JSON (values, standard errors, covariance, the
 * radius-reduction profile, held-out errors of Karis, Decima published and
 * Decima refit, the data used), a C header for sphere_light/sphere_light.h and
 * HLSL/GLSL generated from the C's own source
 * (sphere_light/sphere_light_shader.h). Written by `gtlab fit sphere-light` and
 * the sphere-light stage of `gtlab all`. */
#ifndef GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_FIT_OUTPUTS_H
#define GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_FIT_OUTPUTS_H

#include <stdint.h>

#include "core/error.h"
#include "sphere_light/sphere_light_fit.h"

typedef struct {
    int train, test;     /* configurations fitted and held out */
    uint32_t mc_samples; /* MIS samples per reference */
    uint32_t seed;
    int threads;
} sphere_fit_settings;

/* A fitted constant beside the talk's value. */
typedef struct {
    const char *name;
    double value, stderr_, published;
} sphere_fit_constant;

/* A model's errors on the held-out configurations. */
typedef struct {
    const char *method, *key;
    sphere_light_errors errors;
} sphere_fit_errors_row;

enum { SPHERE_FIT_KARIS, SPHERE_FIT_PUBLISHED, SPHERE_FIT_REFIT, SPHERE_FIT_MODELS };

typedef struct {
    sphere_light_fit_result fit;
    sphere_fit_constant constants[SPHERE_FIT_PARAMS];
    sphere_fit_errors_row held_out[SPHERE_FIT_MODELS];
    /* |residual_a| - |residual_b| paired over the held-out configurations
     * (sphere_light_paired_abs): its mean and standard error */
    double paired_abs[SPHERE_FIT_MODELS][SPHERE_FIT_MODELS], paired_abs_se[SPHERE_FIT_MODELS][SPHERE_FIT_MODELS];
    double mean_reference_rel_stderr; /* mean stderr / (reference + floor) of the held-out set */
    double seconds;
} sphere_fit_outcome;

/* Whether json_path and the C header beside it can be written (before the
 * fit runs). */
int sphere_fit_check_writable(const char *json_path, gt_error *e);

/* Writes json_path plus the C header, HLSL and GLSL beside it (the same
 * name with the extension replaced by .h, .hlsl, .glsl). */
int sphere_fit_write(const sphere_fit_settings *s, const sphere_fit_outcome *o, const char *json_path, gt_error *e);

#endif
