/* The specular-occlusion reference's throughput (`gtlab bench
 * specular-occlusion`): samples/s and rays/s (one ray per sample) of its
 * loop at SPECOCC_BENCH_SPP samples per pixel, roughness
 * SPECOCC_BENCH_ROUGHNESS, on 1 thread and on `threads`, each the best of
 * `repeats` renders (render_stats: samples and rays over seconds). */
#ifndef GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_BENCH_H
#define GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_BENCH_H

#include "core/error.h"

#define SPECOCC_BENCH_SPP 64
#define SPECOCC_BENCH_ROUGHNESS 0.5f

typedef struct {
    int width, height;
    double samples_per_s[2], rays_per_s[2]; /* [0]: 1 thread, [1]: `threads` */
} specular_occlusion_bench_result;

/* On scene `spec` seen by its default camera at width x height. Returns 0,
 * or -1 with e set. */
int specular_occlusion_bench_run(const char *spec, int width, int height, int threads, int repeats,
                                 specular_occlusion_bench_result *out, gt_error *e);

#endif
