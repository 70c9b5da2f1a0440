/* `gtlab bench scale` (issue 20): the strong scaling of MPI renders
 * (raytracer/distributed_render.h), measured. Alone it times one process;
 * under `mpirun -n N` the job's N ranks. One AO reference (builtin:cornell,
 * SCALE_BENCH_WIDTH x SCALE_BENCH_HEIGHT, SCALE_BENCH_SPP samples, all
 * threads of each rank) gives the sampling time (the longest rank's) and
 * the samples/s of the job and of a rank; then one film of that size is
 * reduced to rank 0 again on its own, which gives the gather's cost per
 * rank. Rank 0 prints them and the projection for M nodes of this job's
 * throughput,
 *
 *     T(M) = T_sampling / M + (M - 1) t_film,
 *
 * for M = 1, 16, 256: the sampling divides (every rank does 1/M of every
 * pixel's samples), the linear gather does not. */
#ifndef GTLAB_SCALE_SCALE_BENCH_H
#define GTLAB_SCALE_SCALE_BENCH_H

#include <stdio.h>

#include "core/error.h"

enum { SCALE_BENCH_WIDTH = 192, SCALE_BENCH_HEIGHT = 128, SCALE_BENCH_SPP = 128 };

/* Runs the bench and prints its table to out on rank 0. Returns 0, or -1 with e. */
int scale_bench_run(FILE *out, gt_error *e);

#endif
