/* Beyond the white dome (the `environment` stage of `gtlab all`; issue 28,
 * items 2 and 4): how wrong the ambient terms engines compute are under real
 * HDR environments, against the environment-lit references
 * (raytracer/environment_*), and which part of the error is the lighting's
 * and which the occlusion's.
 *
 * Environments: the white dome (the control, constant 1), the analytic sky
 * (core/optics/sky_environment.h), a synthetic small bright sun over a dim sky
 * (environment_sun_default: the hardest case for AO x probe) and Blender's
 * studio-light HDRs (a few at preview, all eight in production). Scenes: the
 * built-in study scenes. Inputs: the AO reference's exact AO and bent
 * normal (so the occlusion part is the combination's own error, not an AO
 * estimator's), the G-buffer's normal, albedo and roughness, F0 = 0.04.
 *
 * Combinations (environment/environment_approx.h): diffuse per unit albedo, AO x E(n),
 * AO x E(bent), G(AO, rho) x E(n) and x E(bent) (G the GTAO multi-bounce
 * function, the talk's coefficients), E from 9 SH coefficients and from the
 * exact irradiance map; specular, the split sum times each specular-
 * occlusion variant (AO as V_s, Lagarde, cone/cone with the talk's exp2
 * aperture, the GTSO cone/lobe LUT 32^3, cone/cone normalised above the
 * horizon, the spherical-Gaussian cone/lobe product of Unity HDRP,
 * specular_occlusion/specular_occlusion_sg.h). The one-bounce combinations are scored against the direct
 * diffuse reference, the multi-bounce ones against the reference with
 * inter-reflections.
 *
 * The error of each, split three ways, on luminance:
 *   lighting   the unoccluded approximation vs the unoccluded reference;
 *   occlusion  the approximation's occlusion factor (occluded / unoccluded
 *              approximation: AO, AO E(b)/E(n), G, V_s) times the unoccluded
 *              REFERENCE vs the occluded reference: the occlusion's error
 *              under exact lighting;
 *   total      the approximation vs the occluded reference.
 * Each as relative RMSE (RMSE over the mask / the reference's mean) and
 * DSSIM of both images divided by twice the reference's mean (so the
 * reference's mean is 1/2 whatever the environment's brightness), means over
 * the scenes, with the per-scene values kept for paired statistics. */
#ifndef GTLAB_ENVIRONMENT_ENVIRONMENT_STUDY_H
#define GTLAB_ENVIRONMENT_ENVIRONMENT_STUDY_H

#include "environment/environment_approx.h"
#include "project/study_context.h"

enum {
    ENVIRONMENT_STUDY_MAX_ENVIRONMENTS = 12,
    ENVIRONMENT_STUDY_MAX_SCENES = 8,
    ENVIRONMENT_STUDY_OCCLUDED_KINDS = ENVIRONMENT_DIFFUSE_KINDS - 1, /* ao-n .. multibounce-bent */
    ENVIRONMENT_STUDY_SO_VARIANTS = 6
};
typedef enum { ENVIRONMENT_PART_LIGHTING, ENVIRONMENT_PART_OCCLUSION, ENVIRONMENT_PART_TOTAL, ENVIRONMENT_PARTS } environment_error_part;
const char *environment_error_part_name(environment_error_part p); /* "lighting", "occlusion", "total" */

/* The specular-occlusion variants, in this order. */
const char *environment_study_so_label(int variant); /* "ao", "lagarde", "cone-exact:exp2-alpha", "lut", "cone-horizon:exp2-alpha", "sg" */

typedef struct {
    double rmse, dssim; /* relative RMSE, DSSIM (header) */
} environment_score;

/* One environment, every scene. */
typedef struct {
    char name[64];
    double sh_seconds, map_seconds, prefiltered_seconds; /* its precomputations */
    /* means over the scenes; [source][kind - 1][part] for the occluded kinds */
    environment_score diffuse[ENVIRONMENT_IRRADIANCE_SOURCES][ENVIRONMENT_STUDY_OCCLUDED_KINDS][ENVIRONMENT_PARTS];
    environment_score specular[ENVIRONMENT_STUDY_SO_VARIANTS][ENVIRONMENT_PARTS];
    /* per scene: the total relative RMSE of the specular variants, of ao-n (map) by part */
    double specular_case[ENVIRONMENT_STUDY_SO_VARIANTS][ENVIRONMENT_STUDY_MAX_SCENES];
    double ao_n_case[ENVIRONMENT_PARTS][ENVIRONMENT_STUDY_MAX_SCENES];
    /* the direct diffuse reference's RMS standard error / its mean (green), per scene and its mean */
    double noise_case[ENVIRONMENT_STUDY_MAX_SCENES], reference_noise;
} environment_study_environment;

/* A paired difference over the scenes: mean and standard error of the mean. */
typedef struct {
    double mean, standard_error;
    int cases;
} environment_paired;

/* The specular-occlusion ranking under one environment against the white
 * dome's: Kendall's tau between the two orders (by mean total relative
 * RMSE), the pairs whose order flips, and of those the ones whose paired
 * difference is significant (|mean| > 2 standard errors) under both. */
typedef struct {
    int order[ENVIRONMENT_STUDY_SO_VARIANTS]; /* variants, best first */
    double kendall_tau;
    int flipped_pairs, significant_flips;
} environment_so_ranking;

typedef struct {
    int size, spp, bounces; /* of every reference */
    int scene_count, environment_count;
    char scenes[ENVIRONMENT_STUDY_MAX_SCENES][64];
    char image_scene[64]; /* the scene whose images are written: cornell, or a project's first */
    environment_study_environment environments[ENVIRONMENT_STUDY_MAX_ENVIRONMENTS]; /* [0] is the white dome */
    environment_so_ranking rankings[ENVIRONMENT_STUDY_MAX_ENVIRONMENTS];             /* [0]: the white dome's own order */
    /* the talk's claim: AO x probe (map, exact AO) occlusion part, relative
     * RMSE with the reference's noise taken out per scene,
     * sqrt(max(0, rmse^2 - noise^2)) (metrics/noise_corrected.h) */
    int claim_environment;       /* the non-white environment with the smallest occlusion-part error */
    environment_paired white_occlusion;  /* under the white dome, over the scenes */
    environment_paired other_occlusion;  /* under claim_environment */
    double seconds;              /* the whole study */
} environment_study_result;

/* From the per-scene figures of out (scene_count, environments[]): the
 * ranking of environment env against environments[0], the white dome, and
 * the claim's figures. The study calls them; tests hand them made-up rows. */
void environment_study_rank(environment_study_result *out, int env);
void environment_study_claim(environment_study_result *out);

/* Runs the study; writes <output>/environment/ images (reference, approximation,
 * DSSIM map per environment for the first scene). */
int environment_study(const study_context *ctx, environment_study_result *out, gt_error *e);

#endif
