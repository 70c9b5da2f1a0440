/* The height-field control variate against plain sampling
 * (`gtlab bench convergence`, issue 13 part 3): per built-in scene, the
 * RMSE of ao.V against a converged reference as a function of the wall time
 * of the whole render (Embree scene, G-buffer, the control variate's
 * horizons and pilot, sampling), plain and with --control-variate
 * heightfield, in one run on one machine; and the time each takes to reach
 * RMSE `target` and their ratio.
 *
 * The reference is a control-variate render of reference_spp samples with
 * its own seed (both estimators are unbiased, so a reference of either kind
 * serves both; its own error, about 1e-3 at the default 16384 spp, is not
 * taken out: a standard error from the samples overstates the error of
 * scrambled-Sobol' sampling). Each series renders 16, 32, ...
 * samples per pixel (a fresh render each, seed 1) until its RMSE is below
 * target / 2 or max_spp is reached. The time to the target is interpolated
 * log-log between the two renders around it, extrapolated from the last two
 * with RMSE ~ t^(-1/2) when the series never reaches it, and the first
 * render's time (an upper bound) when the first render already does. */
#ifndef GTLAB_AO_AO_CONVERGENCE_H
#define GTLAB_AO_AO_CONVERGENCE_H

#include "core/error.h"

enum { AO_CONVERGENCE_MAX_POINTS = 16, AO_CONVERGENCE_MAX_SCENES = 16, AO_CONVERGENCE_FIRST_SPP = 16 };
/* Each render of a series is timed this many times, the best kept (the
 * machine may be shared). */
enum { AO_CONVERGENCE_PASSES = 2 };

typedef enum { CONVERGENCE_PLAIN, CONVERGENCE_CV, CONVERGENCE_MODES } convergence_mode;

typedef struct {
    int width, height, threads;
    int reference_spp, max_spp;
    double target; /* RMSE */
} ao_convergence_request;

typedef struct {
    int spp;
    double seconds, rmse;
} convergence_point;

/* How a time to the target was found. */
typedef enum { TARGET_INTERPOLATED, TARGET_EXTRAPOLATED, TARGET_AT_FIRST } target_kind;

typedef struct {
    char scene[64];
    double reference_seconds;
    int count[CONVERGENCE_MODES];
    convergence_point points[CONVERGENCE_MODES][AO_CONVERGENCE_MAX_POINTS];
    double time_to_target[CONVERGENCE_MODES];
    target_kind kind[CONVERGENCE_MODES];
    double speedup; /* plain's time to the target over the control variate's */
} ao_convergence_scene;

typedef struct {
    ao_convergence_request request;
    int scene_count;
    ao_convergence_scene scenes[AO_CONVERGENCE_MAX_SCENES];
} ao_convergence_result;

/* The defaults: 48x48, reference 16384 spp, series up to 4096 spp, RMSE 0.01. */
ao_convergence_request ao_convergence_default_request(int threads);

/* Measures every built-in scene; progress lines go to stderr. Returns 0, or
 * -1 with e set. */
int ao_convergence_run(const ao_convergence_request *rq, ao_convergence_result *out, gt_error *e);

#endif
