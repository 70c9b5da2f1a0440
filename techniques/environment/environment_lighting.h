/* The engines' lighting precomputations for one environment
 * (core/optics/environment_map.h), as the environment study uses them: the 9 SH
 * coefficients, the exact irradiance map, the pre-filtered radiance levels
 * (the DFG LUT is the caller's, built once), with the time each took. A constant environment (no
 * texels) is first written as a small map of its constant; the rotation is
 * left to the caller (the study renders with none) and the intensity is
 * applied to the texels. */
#ifndef GTLAB_ENVIRONMENT_ENVIRONMENT_LIGHTING_H
#define GTLAB_ENVIRONMENT_ENVIRONMENT_LIGHTING_H

#include "core/optics/environment_map.h"
#include "core/error.h"
#include "environment/environment_approx.h"
#include "project/study_context.h"

typedef struct {
    int map_width, map_reduction;          /* irradiance map: width x width/2, blocks of 2^reduction texels */
    int prefiltered_width, prefiltered_levels, prefiltered_samples;
} environment_settings;

/* 64, 3; 256, 6, and the quality's prefiltered_samples (the quality table). */
environment_settings environment_default_settings(study_quality quality);

typedef struct {
    sh9_rgb sh;
    irradiance_map map;
    prefiltered_radiance prefiltered;
    multibounce_model multibounce; /* the talk's published coefficients */
    environment_lighting lighting;  /* pointers into the above */
    double sh_seconds, map_seconds, prefiltered_seconds;
} environment_precomputed;

/* Builds everything for env; dfg is kept as a pointer. Returns 0, or -1
 * with e (out of memory). */
int environment_precompute(const environment_map *env, const environment_settings *s, const dfg_lut *dfg, int threads,
                          environment_precomputed *out, gt_error *e);
void environment_precomputed_free(environment_precomputed *p);

#endif
