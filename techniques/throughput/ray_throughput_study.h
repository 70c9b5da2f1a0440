/* Ray throughput (the `throughput` stage of `gtlab all`, the figures of
 * `gtlab bench rays`; throughput/ray_throughput.h): occlusion rays per second
 * of raw Embree calls on a prepared array of the very rays the AO reference
 * traces, against gtlab's AO reference loop end to end at 64 samples per
 * pixel, on one scene, with 1 and with all threads, the best of several
 * passes. Writes no file. */
#ifndef GTLAB_THROUGHPUT_RAY_THROUGHPUT_STUDY_H
#define GTLAB_THROUGHPUT_RAY_THROUGHPUT_STUDY_H

#include "throughput/ray_throughput.h"
#include "project/study_context.h"

/* One way of tracing the rays: rays/s with 1 thread and with `threads`. */
typedef struct {
    const char *name;     /* raw_call_names[], or the AO reference, or the ratio */
    int is_ratio;         /* 1: the row is gtlab's rays/s over the best raw call's */
    double one_thread, threads;
} ray_throughput_row;

enum { RAY_THROUGHPUT_ROWS = RAW_CALL_COUNT + 2 }; /* the raw calls, gtlab, the ratio */

typedef struct {
    const char *scene;
    int threads, repeats;
    long rays_per_pass;
    ray_throughput_row rows[RAY_THROUGHPUT_ROWS];
    double raw_best_1_thread, raw_best_threads;
    double gtlab_ao_1_thread, gtlab_ao_threads;
    double ratio_threads;                 /* gtlab_ao_threads / raw_best_threads */
    double speedup_gtlab, speedup_raw;    /* `threads` threads over 1 */
} ray_throughput_result;

/* The row of gtlab's AO loop and that of its ratio to the best raw call. */
enum { RAY_THROUGHPUT_GTLAB_ROW = RAW_CALL_COUNT, RAY_THROUGHPUT_RATIO_ROW = RAW_CALL_COUNT + 1 };

/* The figures on scene `spec` seen by its default camera at width x height
 * (`gtlab bench rays`); out->scene is spec. Returns 0, or -1 with e set. */
int ray_throughput_measure(const char *spec, int width, int height, int threads, int repeats,
                           ray_throughput_result *out, gt_error *e);

/* The `throughput` stage: builtin:menger at 256x256, its passes the quality
 * table's (the throughput row of techniques/quality_table.txt). */

int ray_throughput_study(const study_context *ctx, ray_throughput_result *out, gt_error *e);

#endif
