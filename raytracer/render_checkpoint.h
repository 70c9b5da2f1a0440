/* A render that survives its interruption (issue 20): the samples are
 * rendered in blocks of CHECKPOINT_BLOCK per pixel, and the exact
 * accumulators of the completed blocks (core/statistics/mc_film.h) are saved beside
 * the output as "F.checkpoint.exr" (render_checkpoint_files.h): every
 * CHECKPOINT_SECONDS, and when SIGINT, SIGTERM or SIGHUP arrives (the block
 * under way is dropped, the checkpoint written, then the signal takes its
 * course: gtlab's handler rolls the outputs back and exits 128 + signal).
 * A killed job (SIGKILL) keeps the last periodic checkpoint.
 *
 * Resuming reads the checkpoint and renders the blocks after it. Sums are
 * exact integers, so the film is the one an uninterrupted render makes,
 * bit for bit. The checkpoint names the render it belongs to (its header,
 * ATTR_CHECKPOINT_OF) and holds the one block of samples done
 * (ATTR_BLOCKS, "seed:offset+done"): another render's checkpoint is
 * refused. It is written to a hidden temporary and renamed into place
 * outside the verb's output set, so a rollback never removes it, and it is
 * never the output path. gtlab render removes it once the output is
 * written.
 *
 * For tests and operators two environment variables: GTLAB_STOP_AFTER_BLOCKS=K
 * stops the render as SIGTERM would after K blocks of this run, and
 * GTLAB_CHECKPOINT_SECONDS=S sets the interval (0: after every block).
 *
 * A render with a stopping target (--target-stderr, --target-rel-stderr)
 * decides per pixel over all its samples, so its blocks are rows instead:
 * CHECKPOINT_ROWS rows at a time (or 4 per thread if more), every pixel to
 * its target, the rows
 * finished in ATTR_CHECKPOINT_ROWS (its ATTR_BLOCKS names the whole sample
 * range). A pixel's samples depend only on the pixel and the seed, so the
 * resumed film is again the uninterrupted one, bit for bit.
 *
 * Under mpirun every rank checkpoints its own share (its block of every
 * pixel's samples, or its rows) in a file of its own, marked with its rank
 * of N (ATTR_CHECKPOINT_RANK), and resumes it alone; the finished shares
 * are then reduced to rank 0 (raytracer/distributed_render.h) as without
 * checkpoints, so the bits are again one process's. Where the files live:
 * raytracer/render_checkpoint_files.h. */
#ifndef GTLAB_RAYTRACER_RENDER_CHECKPOINT_H
#define GTLAB_RAYTRACER_RENDER_CHECKPOINT_H

#include "core/error.h"
#include "raytracer/render_checkpoint_files.h"
#include "raytracer/render_loop.h"

enum { CHECKPOINT_BLOCK = 64, CHECKPOINT_ROWS = 8 };
#define CHECKPOINT_SECONDS 60.0

typedef struct {
    const char *path;     /* this process's checkpoint file (render_checkpoint_path) */
    const char *identity; /* the render's header as text: what the checkpoint must belong to */
    int resume;           /* continue from the checkpoint at path, if there is one */
} render_checkpoint;

/* render_estimates in blocks, with checkpoints. Returns 0, or -1 with e. */
int render_estimates_checkpointed(const gbuffer *gb, const integrator *it, const sampling_settings *ss,
                                  const render_checkpoint *cp, mc_film *film, render_stats *stats, gt_error *e);

#endif
