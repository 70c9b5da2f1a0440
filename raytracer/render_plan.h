/* One reference render split into jobs for a batch scheduler (`gtlab plan`).
 *
 * A render of spp samples from sequence index K (`--sample-offset K
 * --spp S`) is the sum of renders of disjoint blocks of those samples:
 * sums are exact (core/statistics/mc_film.h), so merging the parts gives the bits of
 * the render in one process. The plan splits [K, K + S) into N blocks,
 * job j taking [K + floor(j S / N), K + floor((j + 1) S / N)), and writes
 * into its folder the files of core/files/batch_script.h: jobs.txt and job.sh
 * (job j: "gtlab render ... -o DIR/part-j.exr"), merge.sh (`gtlab merge` of
 * the parts with --expect-blocks: a part of another render, other samples or
 * seed, or a missing part is refused, raytracer/reference_merge.h; the other
 * checks are merge's own: scene hash, camera, settings, overlap) and
 * submit.sh (the array, then merge.sh).
 *
 * Adaptive renders (--target-stderr, --target-rel-stderr) are refused: each
 * pixel stops by its own samples, so their parts merge to no single render. */
#ifndef GTLAB_RAYTRACER_RENDER_PLAN_H
#define GTLAB_RAYTRACER_RENDER_PLAN_H

#include "core/error.h"

/* Writes the plan of the render command argv[0, argc) ("render",
 * QUANTITY, its options, as given to gtlab) in `jobs` jobs into `folder`
 * (created if absent). Returns 0, or -1 with e naming the option or file. */
int render_plan_write(int jobs, const char *folder, int argc, char *const *argv, gt_error *e);

#endif
