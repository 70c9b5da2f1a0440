/* The multi-bounce reference's throughput (`gtlab bench multibounce`):
 * multibounce_throughput.h's figures on scene `spec` seen by its
 * default camera at width x height. */
#ifndef GTLAB_MULTIBOUNCE_MULTIBOUNCE_BENCH_H
#define GTLAB_MULTIBOUNCE_MULTIBOUNCE_BENCH_H

#include <stdio.h>

#include "multibounce/multibounce_throughput.h"

/* Returns 0, or -1 with e set. */
int multibounce_bench_run(const char *spec, int width, int height, const multibounce_settings *settings, int spp,
                          int threads, int repeats, multibounce_benchmark *out, gt_error *e);

/* The figures as `gtlab bench multibounce` prints them: paths/s and rays/s
 * against raw Embree on 1 and N threads, and one pass of N albedos against
 * N renders. */
void multibounce_benchmark_print(FILE *out, const char *spec, const multibounce_settings *s,
                                 const multibounce_benchmark *b);

#endif
