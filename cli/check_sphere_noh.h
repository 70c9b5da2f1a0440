/* The accuracy of GetNoHSquared over a dense sweep of configurations: the
 * shortfall of (N.H)^2 below its brute-force maximum over the light for
 * Karis's point (0 Newton steps) and 1 and 2 steps. Used by
 * `gtlab check sphere-noh` and the sphere-light stage of `gtlab all`. */
#ifndef GTLAB_CLI_CHECK_SPHERE_NOH_H
#define GTLAB_CLI_CHECK_SPHERE_NOH_H

#include "core/error.h"

typedef struct {
    int nv_steps, theta_steps, phi_steps, size_steps; /* grid of the sweep */
    int rim_steps;                                    /* brute-force angles on the rim */
} sphere_noh_sweep;

typedef struct {
    long configurations, r_inside; /* R inside the light: all methods exact (1) */
    double mean[3], p99[3], worst[3]; /* shortfall of 0, 1, 2 steps, outside */
    double share_worse[3];            /* [1]: 1 step below Karis, [2]: 2 steps below 1 step */
    double share_better[3];           /* [1]: 1 step above Karis, [2]: 2 steps above 1 step */
} sphere_noh_stats;

/* Runs the sweep and writes DIR/sphere_noh.csv (every configuration),
 * DIR/sphere_noh_map.csv and the plots DIR/sphere_noh_map.png (where the
 * step helps or hurts over n.v and the light's elevation) and
 * DIR/sphere_noh_error.png (mean shortfall against n.v). */
int sphere_noh_sweep_run(const sphere_noh_sweep *sweep, const char *dir, sphere_noh_stats *stats, gt_error *e);

#endif
