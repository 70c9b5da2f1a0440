/* The accuracy of GetNoHSquared over a dense sweep of configurations: the
 * shortfall of (N.H)^2 below its brute-force maximum over the light for
 * Karis's point (0 Newton steps), 1 and 2 steps, and 1 step guarded (taken
 * only where f''(0) < 0). Used by
 * `gtlab check sphere-noh` and the sphere-light stage of `gtlab all`. */
#ifndef GTLAB_CLI_CHECK_SPHERE_NOH_H
#define GTLAB_CLI_CHECK_SPHERE_NOH_H

#include "core/error.h"

typedef struct {
    int nv_steps, theta_steps, phi_steps, size_steps; /* grid of the sweep */
    int rim_steps;                                    /* brute-force angles on the rim */
} sphere_noh_sweep;

enum { NOH_KARIS, NOH_STEP1, NOH_STEP2, NOH_GUARDED, NOH_METHODS };
extern const char *const sphere_noh_method_names[NOH_METHODS];
/* What each method is compared with for "worse"/"better": the previous
 * number of steps, or Karis for the guarded step (-1 for Karis itself). */
extern const int sphere_noh_baseline[NOH_METHODS];

typedef struct {
    long configurations, r_inside;                          /* R inside the light: all exact (1) */
    double mean[NOH_METHODS], p99[NOH_METHODS], worst[NOH_METHODS]; /* shortfalls, R outside */
    double share_worse[NOH_METHODS], share_better[NOH_METHODS];     /* against the baseline */
} sphere_noh_stats;

/* Runs the sweep and writes DIR/sphere_noh.csv (every configuration),
 * DIR/sphere_noh_map.csv and the plots DIR/sphere_noh_map.png (where the
 * step helps or hurts over n.v and the light's elevation) and
 * DIR/sphere_noh_error.png (mean shortfall against n.v). */
int sphere_noh_sweep_run(const sphere_noh_sweep *sweep, const char *dir, sphere_noh_stats *stats, gt_error *e);

#endif
