/* Throughput measurements for `gtlab bench rays`: raw Embree occlusion rays
 * (single, stream and packet calls) on a prepared array of the rays the AO
 * reference traces (incoherent, cosine- and uniform-distributed, leaving the
 * visible surfaces), against gtlab's own AO reference loop on the same scene
 * and camera, each with 1 and N threads. */
#ifndef GTLAB_THROUGHPUT_RAY_THROUGHPUT_H
#define GTLAB_THROUGHPUT_RAY_THROUGHPUT_H

#include "core/error.h"
#include "scene/scene.h"

enum { RAW_OCCLUDED1, RAW_OCCLUDED1M_64, RAW_OCCLUDED1M_128, RAW_OCCLUDED8, RAW_OCCLUDED16, RAW_CALL_COUNT };
extern const char *const raw_call_names[RAW_CALL_COUNT];

typedef struct {
    double by_call[RAW_CALL_COUNT]; /* rays/s of each Embree call form */
    double best;                    /* the best of them */
} raw_throughput;

typedef struct {
    int threads;
    long rays_per_pass;
    raw_throughput raw[2];  /* [0]: 1 thread, [1]: `threads` threads */
    double gtlab_ao[2];     /* rays/s of the AO reference loop */
} ray_benchmark;

/* Measures on scene s seen by cam; each figure is the best of `repeats` passes. */
int ray_benchmark_run(const scene *s, const camera *cam, int threads, int repeats, ray_benchmark *out, gt_error *e);

#endif
