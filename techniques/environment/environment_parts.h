/* Inside the environment study (environment/environment_study.c): one case (an
 * environment and a scene) scored, and the images written. */
#ifndef GTLAB_ENVIRONMENT_ENVIRONMENT_PARTS_H
#define GTLAB_ENVIRONMENT_ENVIRONMENT_PARTS_H

#include "core/image.h"
#include "environment/environment_screen.h"
#include "environment/environment_study.h"

/* What one case reads: the AO reference (G-buffer, ao.V, bent normal), the
 * two environment references, and the lighting of the environment. */
typedef struct {
    const image *ao, *diffuse, *specular;
    const environment_lighting *lighting;
    const so_variant *variants; /* ENVIRONMENT_STUDY_SO_VARIANTS */
    const char *what;           /* "<environment> / <scene>" for errors */
} environment_case;

/* The scores of one case. */
typedef struct {
    environment_score diffuse[ENVIRONMENT_IRRADIANCE_SOURCES][ENVIRONMENT_STUDY_OCCLUDED_KINDS][ENVIRONMENT_PARTS];
    environment_score specular[ENVIRONMENT_STUDY_SO_VARIANTS][ENVIRONMENT_PARTS];
    double reference_noise;
} environment_case_scores;

/* Scores every combination of the case. Returns 0, or -1 with e. */
int environment_case_score(const environment_case *c, environment_case_scores *out, gt_error *e);

/* Side by side for the case: <dir>/<stem>_ref.png (the direct diffuse
 * reference, RGB), _approx.png (AO x E(n) from the irradiance map), _dssim.png
 * (the DSSIM map of their luminances, 0 to 0.5). Returns 0, or -1 with e. */
int environment_case_images(const environment_case *c, const char *dir, const char *stem, gt_error *e);

#endif
