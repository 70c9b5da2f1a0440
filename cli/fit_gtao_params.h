/* The GTAO parameter fit behind `gtlab fit gtao-params` (issue 4, item 6):
 * radius (a fraction of each camera's distance to its target), falloff and
 * thickness that minimise DSSIM (or RMSE) of GTAO against 3-D ray-traced AO
 * references of training scenes, scored before and after on held-out ones. */
#ifndef GTLAB_CLI_FIT_GTAO_PARAMS_H
#define GTLAB_CLI_FIT_GTAO_PARAMS_H

#include <cjson/cJSON.h>

#include "core/error.h"

typedef enum { GTAO_FIT_DSSIM, GTAO_FIT_RMSE } gtao_fit_objective;
enum { GTAO_FIT_PARAMS = 3, GTAO_FIT_MAX_SCENES = 16 };
extern const char *const gtao_fit_param_names[GTAO_FIT_PARAMS];
extern const char *const gtao_fit_objective_names[2];

typedef struct {
    const char *refs_dir;     /* <scene>.exr AO references with G-buffer and camera */
    const char *train, *test; /* comma-separated scene names */
    const char *preset;       /* GTAO preset the parameters override */
    gtao_fit_objective objective;
} gtao_fit_request;

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

/* Loads the references, fits, scores. Returns 0, or -1 with e (a missing or
 * unreadable reference, an unknown preset, no covered pixel, the solver). */
int gtao_params_fit(const gtao_fit_request *rq, gtao_fit_result *out, gt_error *e);
/* The fit as JSON: request, values, standard errors, start, scores. */
cJSON *gtao_fit_json(const gtao_fit_request *rq, const gtao_fit_result *r);

#endif
