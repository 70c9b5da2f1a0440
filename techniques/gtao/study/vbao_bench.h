/* VBAO's cost beside GTAO's in `gtlab bench gtao` (gtao_bench.h):
 * the talk's configuration (GTAO medium: 1 direction, 4 samples per side,
 * the pattern, fast maths, the 4x4 denoiser, the 24-frame cycle) with the
 * slice's horizons replaced by a 32-sector bitmask with the paper's choices
 * (vbao.h), thickness 0.05 camera distances, at the same half
 * resolution of a 1920x1080 frame, seconds per frame on 1 and T threads. */
#ifndef GTLAB_GTAO_VBAO_BENCH_H
#define GTLAB_GTAO_VBAO_BENCH_H

#include "gtao/vbao.h"

typedef struct {
    char settings[768]; /* vbao_params_text */
    double seconds_1_thread, seconds_threads;
} vbao_bench_result;

/* Times VBAO on g (radius and thickness in view-space units; ao scratch of
 * g's size); leaves OpenMP at `threads` threads. */
void vbao_bench_time(const ss_gbuffer *g, float radius, float thickness, int threads, int repeats, float *ao,
                     vbao_bench_result *out);

#endif
