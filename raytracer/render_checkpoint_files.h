/* Where the checkpoints of `gtlab render -o F.exr` live (issue 20,
 * raytracer/render_checkpoint.h), in one process and under mpirun:
 *
 *   one process:          F.checkpoint.exr
 *   rank r of N (N > 1):  F.checkpoint.rank<r>-of-<N>.exr
 *
 * Under mpirun every rank keeps its own share's exact accumulators in its
 * own file (its share depends on r and N: raytracer/distributed_render.h),
 * so a rank killed mid-way costs no other rank its work, and no rank sends
 * a film to checkpoint. A resume must therefore run on the same number of
 * processes: with --resume, a checkpoint of F.exr left by a run on another
 * number of processes is refused, naming the file. Every rank finds the
 * same files, so every rank refuses alike (rank 0 says it).
 *
 * Once rank 0 has written F.exr, every rank removes its own checkpoint
 * (they agree first: a failed write keeps them all). */
#ifndef GTLAB_RAYTRACER_RENDER_CHECKPOINT_FILES_H
#define GTLAB_RAYTRACER_RENDER_CHECKPOINT_FILES_H

#include "core/error.h"

/* This process's checkpoint for the output path (above) into out. */
void render_checkpoint_path(const char *output_path, char *out, int out_size);

/* render_checkpoint_path, and with `resume` a refusal (-1 with e, naming
 * the file) when a checkpoint of this output from a run on another number
 * of processes is there. Returns 0, or -1 with e. */
int render_checkpoint_prepare(const char *output_path, int resume, char *out, int out_size, gt_error *e);

/* Collective under mpirun (every rank calls it): when `written` is true on
 * every rank (rank 0 wrote the output), each removes its own checkpoint. */
void render_checkpoint_finish(const char *checkpoint_path, int written);

#endif
