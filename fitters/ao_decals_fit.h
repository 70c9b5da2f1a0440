/* A refit of INSIDE's point AO decal (realtime/ao_decals.h) to AO
 * references by Ceres: the decal at a given centre with radius R (its unit
 * sphere scaled by R), falloff exponent k, wrap w and intensity s, so that
 * 1 - s ao_point_decal((c - p) / R, n, k, w) matches the reference's V_d
 * at each sample, least squares. Bounds: R in [0.5, 20], k in [0.1, 8],
 * w in [0, 4], s in [0, 2]; a parameter ending on a bound is reported. */
#ifndef GTLAB_FITTERS_AO_DECALS_FIT_H
#define GTLAB_FITTERS_AO_DECALS_FIT_H

#include <stddef.h>

#include "core/error.h"
#include "core/vec3.h"

enum { AO_DECAL_PARAMS = 4 }; /* R, k, w, s */

typedef struct {
    const vec3 *p, *n;    /* world position and unit normal per sample */
    const float *visibility; /* the reference's V_d */
    size_t count;
    vec3 centre;
} ao_decal_samples;

typedef struct {
    double params[AO_DECAL_PARAMS];
    double rmse;
    int converged, at_bound;
    int near_bound; /* parameters within 1 % of their range from a bound */
} ao_decal_fit_result;

/* The decal's visibility 1 - s a at sample i for params. */
double ao_decal_fit_visibility(const ao_decal_samples *s, size_t i, const double *params);

/* Starts from the published decal (k = 2, w = 1, s = 1) at radius start_radius. */
int ao_decal_fit(const ao_decal_samples *s, double start_radius, ao_decal_fit_result *out, gt_error *e);

#endif
