/* Inside the environment study (environment/env_approx_study.c): one case (an
 * environment and a scene) scored, and the images written. */
#ifndef GTLAB_ENVIRONMENT_ENV_APPROX_PARTS_H
#define GTLAB_ENVIRONMENT_ENV_APPROX_PARTS_H

#include "core/image.h"
#include "environment/env_approx_screen.h"
#include "environment/env_approx_study.h"

/* What one case reads: the AO reference (G-buffer, ao.V, bent normal), the
 * two environment references, and the lighting of the environment. */
typedef struct {
    const image *ao, *diffuse, *specular;
    const env_approx_lighting *lighting;
    const so_variant *variants; /* ENV_STUDY_SO_VARIANTS */
    const char *what;           /* "<environment> / <scene>" for errors */
} env_case;

/* The scores of one case. */
typedef struct {
    env_score diffuse[ENV_IRRADIANCE_SOURCES][ENV_STUDY_OCCLUDED_KINDS][ENV_PARTS];
    env_score specular[ENV_STUDY_SO_VARIANTS][ENV_PARTS];
    double reference_noise;
} env_case_scores;

/* Scores every combination of the case. Returns 0, or -1 with e. */
int env_case_score(const env_case *c, env_case_scores *out, gt_error *e);

/* Side by side for the case: <dir>/<stem>_ref.png (the direct diffuse
 * reference, RGB), _approx.png (AO x E(n) from the irradiance map), _dssim.png
 * (the DSSIM map of their luminances, 0 to 0.5). Returns 0, or -1 with e. */
int env_case_images(const env_case *c, const char *dir, const char *stem, gt_error *e);

#endif
