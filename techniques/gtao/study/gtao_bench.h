/* The cost of GTAO (`gtlab bench gtao`), measured in one run on one scene
 * and camera:
 *  - the talk's configuration (seeds/001, "Achieving the Performance
 *    Target"): GTAO for a 1920x1080 frame at half resolution (960x540), the
 *    medium preset (1 direction per pixel, 8 samples per direction, the 4x4
 *    spatio-temporal pattern, spatial and temporal denoisers) over the
 *    24-frame cycle, seconds per frame on 1 and on `threads` threads;
 *  - VBAO in the same configuration with a 32-sector bitmask (issue 27);
 *  - the cost per pixel of one frame of every preset on a 240x136 image of the
 *    same view, next to the height-field Monte Carlo reference's at 64 spp.
 * Each GTAO figure is the best of `repeats` passes; the radius is a quarter
 * of the camera's distance to its target. Writes no file. */
#ifndef GTLAB_GTAO_GTAO_BENCH_H
#define GTLAB_GTAO_GTAO_BENCH_H

#include <stdio.h>

#include "core/error.h"
#include "gtao/gtao.h"
#include "gtao/vbao_bench.h"

enum { GTAO_BENCH_HALF_WIDTH = 960, GTAO_BENCH_HALF_HEIGHT = 540, GTAO_BENCH_FRAMES = 24 };
enum { GTAO_BENCH_SMALL_WIDTH = 240, GTAO_BENCH_SMALL_HEIGHT = 136, GTAO_BENCH_HEIGHTFIELD_SPP = 64 };

typedef struct {
    char settings[512];                   /* gtao_params_text of the talk's configuration */
    double talk_seconds_1_thread;         /* per frame, GTAO and denoisers */
    double talk_seconds_threads;
    vbao_bench_result vbao;               /* VBAO in the talk's configuration (vbao_bench.h) */
    int small_width, small_height;        /* the per-pixel figures' image */
    double preset_ns[GTAO_PRESET_COUNT];  /* ns per pixel of one frame, by gtao_preset_id */
    double heightfield_ns;                /* ns per pixel of the height-field reference */
} gtao_bench_result;

/* Loads scene `spec` (builtin:NAME or a glTF file) and measures; leaves
 * OpenMP at `threads` threads. Returns 0, or -1 with e set. */
int gtao_bench_run(const char *spec, int threads, int repeats, gtao_bench_result *out, gt_error *e);

/* The benchmark's table (`gtlab bench gtao`) for `spec` run with `threads`. */
void gtao_bench_print(FILE *f, const char *spec, int threads, const gtao_bench_result *r);

#endif
