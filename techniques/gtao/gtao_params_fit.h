/* GTAO's world radius (a fraction of each camera's distance to its target),
 * falloff and thickness fitted so GTAO matches AO references (issue 4, item
 * 6), through the Ceres bridge, and scored before and after on the training
 * and on held-out scenes. In-memory: each scene is a G-buffer, the AO to
 * match at its pixels and its camera distance; loading them is the caller's
 * (gtao_params.h reads a folder of AO references).
 *
 * Objectives: DSSIM (the default; issue 4 asks for the parameters that
 * minimise it and the talk tuned by image comparison too) has one residual
 * per SSIM window inside the mask, sqrt((1 - SSIM_w) / 2), whose squares sum
 * to the number of windows times the scene's DSSIM (Wang et al. 2004's mean
 * over windows); RMSE has one residual per covered pixel, GTAO minus the
 * reference. Each scene's residuals are scaled by 1/sqrt(their count), so
 * every training scene weighs the same and 2 * cost / scenes is the mean per
 * scene of DSSIM or of the mean squared error. */
#ifndef GTLAB_GTAO_GTAO_PARAMS_FIT_H
#define GTLAB_GTAO_GTAO_PARAMS_FIT_H

#include "core/error.h"
#include "realtime/screen_space.h"

typedef enum { GTAO_FIT_DSSIM, GTAO_FIT_RMSE } gtao_fit_objective;
enum { GTAO_FIT_PARAMS = 3, GTAO_FIT_MAX_SCENES = 32 }; /* as many as a study runs over (STUDY_SCENES_MAX) */
/* radius_over_camera_distance, falloff, thickness: the order of the values */
extern const char *const gtao_fit_param_names[GTAO_FIT_PARAMS];
extern const char *const gtao_fit_objective_names[2]; /* "dssim", "rmse" */

/* One scene of the fit: GTAO runs on g; its mask selects the pixels scored. */
typedef struct {
    const char *name;
    const ss_gbuffer *g;
    const float *reference; /* the AO to match, g->width x g->height */
    float camera_distance;  /* the fitted radius is a fraction of it */
} gtao_fit_scene;

typedef struct {
    const gtao_fit_scene *train; /* fitted on */
    int train_count;
    const gtao_fit_scene *test;  /* held out: scored only */
    int test_count;
    const char *preset;          /* GTAO preset the parameters override */
    gtao_fit_objective objective;
} gtao_fit_problem;

typedef struct {
    char scene[64];
    int held_out;
    double rmse_before, rmse_after, dssim_before, dssim_after;
} gtao_fit_score;

typedef struct {
    double start[GTAO_FIT_PARAMS], value[GTAO_FIT_PARAMS], se[GTAO_FIT_PARAMS];
    int have_se, converged, iterations;
    double objective_per_scene; /* mean over training scenes of DSSIM or mean squared error */
    int score_count;
    gtao_fit_score scores[2 * GTAO_FIT_MAX_SCENES]; /* training scenes first */
} gtao_fit_result;

/* Fits from radius 0.25, the preset's falloff and thickness 0.1 within the
 * bounds [0.01, 2] x [0, 1] x [0, 0.95], then scores every scene at the start
 * and at the fit. Returns 0, or -1 with e (an unknown preset, too many scenes,
 * a scene with no residual, the solver). */
int gtao_params_fit(const gtao_fit_problem *problem, gtao_fit_result *out, gt_error *e);

/* Whether fitted value k ended on a bound: -1 the lower, 1 the upper, 0 inside. */
int gtao_fit_at_bound(const gtao_fit_result *r, int k);

#endif
