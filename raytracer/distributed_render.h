/* One render shared by the processes of an MPI job (issue 20):
 *
 *     mpirun -n N gtlab render ao|multibounce|... --spp S ... -o F.exr
 *
 * Every rank loads the scene and traces the G-buffer (cheap next to the
 * samples), then takes its share of the samples:
 *
 *   - a fixed spp: rank r renders every pixel's samples
 *     [K + floor(r S / N), K + floor((r + 1) S / N)) of the render's block
 *     [K, K + S) (--sample-offset K): the same split as `gtlab plan`, every
 *     rank with the same cost per pixel, so no load balancing is needed;
 *   - a stopping target (--target-stderr): each pixel stops by its own
 *     samples, so a pixel is not split: rank r renders whole rows r, r + N,
 *     r + 2N, ... (interleaved, so a costly region is shared), and the stop
 *     rule is decided where all of the pixel's samples are.
 *
 * Then the exact accumulators (grid sums, moment sums, counts; core/statistics/mc_film.h)
 * of ranks 1 .. N-1 are sent to rank 0 and added there in rank order. Those
 * sums are exact integers, so the total does not depend on how the samples
 * were shared: rank 0 holds the film of one process, bit for bit, and it
 * alone writes the output.
 *
 * The interface is the same without MPI (GTLAB_MPI=OFF, or MPI not found
 * when configured): one process, rank 0 of 1; under mpirun such a build
 * refuses to run, rather than render N copies. */
#ifndef GTLAB_RAYTRACER_DISTRIBUTED_RENDER_H
#define GTLAB_RAYTRACER_DISTRIBUTED_RENDER_H

#include "core/error.h"
#include "core/statistics/mc_film.h"
#include "raytracer/render_loop.h"

typedef struct {
    int rank, ranks;
} render_share;

/* Joins the MPI job this process was started in by mpirun, if any: the
 * renders after it share their samples among the job's ranks (MPI is
 * finalised at exit). Outside mpirun: nothing. Returns 0, or -1 with e. */
int distributed_begin(gt_error *e);
/* This process's place: its rank in the joined job, else rank 0 of 1. */
render_share distributed_share(void);
/* The job's own place, rank and ranks, whatever distributed_share says. */
render_share distributed_job(void);
/* From now on every rank renders alone: distributed_share() is rank 0 of 1
 * and films are not reduced, while distributed_job() and distributed_all
 * still see the job. For ranks that run different work (`mpirun gtlab all`:
 * each rank its stages, cli/all_plan.h). */
void distributed_render_alone(void);
/* Whether this process writes the outputs: rank 0. */
int distributed_is_writer(void);
/* On rank 0 the film becomes the sum of every rank's (same size and
 * quantities), added in rank order, and stats the job's (rays and samples
 * summed, seconds the longest rank's); other ranks send theirs and keep
 * them. Alone: nothing. Returns 0, or -1 with e. */
int distributed_reduce_film(mc_film *film, render_stats *stats, gt_error *e);
/* Whether ok is non-zero on every rank of the job (all ranks must call it;
 * a barrier); outside a job: ok. */
int distributed_all(int ok);

/* The block of the samples [ss->sample_offset, + ss->spp) rank r of n
 * renders with a fixed spp: floor(r spp / n) to floor((r + 1) spp / n). */
sampling_settings distributed_sample_share(const sampling_settings *ss, render_share share);

#endif
