/* `gtlab fit gtao-params` as a study: GTAO's radius, falloff and thickness
 * fitted (gtao_params_fit.h) to a folder of 3-D ray-traced AO
 * references, <dir>/<scene>.exr with their G-buffer and camera (the `ao`
 * stage's output), trained on some scenes and scored on held-out ones. */
#ifndef GTLAB_GTAO_GTAO_PARAMS_H
#define GTLAB_GTAO_GTAO_PARAMS_H

#include <stdio.h>

#include "core/error.h"
#include "gtao/gtao_params_fit.h"

typedef struct {
    const char *refs_dir;     /* <scene>.exr AO references with G-buffer and camera */
    const char *train, *test; /* comma-separated scene names */
    const char *preset;       /* GTAO preset the parameters override */
    gtao_fit_objective objective;
} gtao_fit_request;

/* The defaults of `gtlab fit gtao-params` and of `gtlab all`: trained on
 * boxes, corner and cornell, held out menger and sphere-on-plane, high
 * preset, DSSIM objective. */
#define GTAO_FIT_DEFAULT_TRAIN "boxes,corner,cornell"
#define GTAO_FIT_DEFAULT_TEST "menger,sphere-on-plane"
#define GTAO_FIT_DEFAULT_PRESET "high"

/* Loads the references, fits, scores. Returns 0, or -1 with e (a missing or
 * unreadable reference, an unknown preset, no covered pixel, the solver). */
int gtao_params_study(const gtao_fit_request *rq, gtao_fit_result *out, gt_error *e);

/* The fit as `gtlab fit gtao-params` prints it: each parameter with its
 * standard error and start, then each scene's RMSE and DSSIM before and
 * after, training scenes first. */
void gtao_params_print(FILE *f, const gtao_fit_request *rq, const gtao_fit_result *r);

#endif
