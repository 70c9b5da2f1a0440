/* Throughput measurements for `gtlab bench multibounce`: the multi-bounce
 * reference loop (paths/s and rays/s) next to raw Embree closest-hit
 * queries on the same scene, and the cost of N albedos in one pass against
 * N single-albedo renders. */
#ifndef GTLAB_MULTIBOUNCE_MULTIBOUNCE_THROUGHPUT_H
#define GTLAB_MULTIBOUNCE_MULTIBOUNCE_THROUGHPUT_H

#include "core/error.h"
#include "multibounce/multibounce_integrator.h"
#include "scene/scene.h"

typedef struct {
    int threads, spp;
    long raw_rays;                    /* rays in the raw set */
    /* [0]: 1 thread, [1]: `threads` threads; best of the passes */
    double paths_per_s[2], rays_per_s[2]; /* the reference loop, all albedos in one pass */
    double raw_intersect1[2];         /* rtcIntersect1 rays/s on the first-bounce rays */
    double raw_intersect1m[2];        /* rtcIntersect1M, streams of 64 */
    double seconds_one_pass;          /* `threads` threads: every albedo in one render */
    double seconds_separate;          /* the same albedos, one render each */
} multibounce_benchmark;

/* Measures on scene s seen by cam at spp samples per pixel with the given
 * albedos and bounces; every figure is the best of `repeats` passes. */
int multibounce_benchmark_run(const scene *s, const camera *cam, const multibounce_settings *settings, int spp,
                              int threads, int repeats, multibounce_benchmark *out, gt_error *e);

#endif
