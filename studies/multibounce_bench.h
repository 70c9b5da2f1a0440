/* The multi-bounce reference's throughput (`gtlab bench multibounce`):
 * raytracer/multibounce_throughput.h's figures on scene `spec` seen by its
 * default camera at width x height. */
#ifndef GTLAB_STUDIES_MULTIBOUNCE_BENCH_H
#define GTLAB_STUDIES_MULTIBOUNCE_BENCH_H

#include "raytracer/multibounce_throughput.h"

/* Returns 0, or -1 with e set. */
int multibounce_bench_run(const char *spec, int width, int height, const multibounce_settings *settings, int spp,
                          int threads, int repeats, multibounce_benchmark *out, gt_error *e);

#endif
