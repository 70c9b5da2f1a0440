/* The sphere-light refit end to end: configurations drawn from a realistic
 * distribution, their Monte Carlo references, the Ceres fit of Decima's
 * constants (fitters/fit_sphere_light.h), errors before and after on
 * held-out configurations, and the outputs (JSON, C header, HLSL, GLSL).
 * Used by `gtlab fit sphere-light` and the sphere-light stage of `gtlab all`. */
#ifndef GTLAB_CLI_FIT_SPHERE_LIGHT_H
#define GTLAB_CLI_FIT_SPHERE_LIGHT_H

#include <stdint.h>

#include "core/error.h"
#include "fitters/fit_sphere_light.h"

typedef struct {
    int train, test;       /* configurations fitted and held out */
    uint32_t mc_samples;   /* MIS samples per reference */
    uint32_t seed;
    int threads;
} sphere_fit_settings;

typedef struct {
    sphere_light_fit_result fit;
    sphere_light_errors karis, published, refit; /* on the held-out configurations */
    double mean_reference_rel_stderr;            /* mean stderr / (reference + floor) of the held-out set */
    double seconds;
} sphere_fit_outcome;

/* Runs everything and writes json_path plus the C header, HLSL and GLSL
 * beside it (same name, extensions .h, .hlsl, .glsl). */
int sphere_fit_run(const sphere_fit_settings *s, const char *json_path, sphere_fit_outcome *out, gt_error *e);

#endif
