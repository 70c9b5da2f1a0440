/* Merging partial reference renders: renders of the same quantity, scene and
 * camera over disjoint blocks of the sample sequence (or with different
 * seeds) combine exactly, because their accumulators hold exact sums
 * (core/statistics/mc_film.h). The result equals one render over the union of the
 * blocks, bit for bit. */
#ifndef GTLAB_RAYTRACER_REFERENCE_MERGE_H
#define GTLAB_RAYTRACER_REFERENCE_MERGE_H

#include "core/error.h"
#include "core/image.h"
#include "raytracer/reference_quantity.h"

/* inputs[i] was read from names[i] (for errors). `out` is initialised here.
 * The header's gtlab.quantity is looked up in `quantities` (the program's
 * registry) for its derived channels (the descriptor's finish); a quantity
 * not there has none. */
int reference_merge(const reference_registry *quantities, const image *inputs, const char *const *names, int count,
                    image *out, gt_error *e);

/* reference_merge of the parts of one planned render (`gtlab plan`):
 * `planned` is the sample blocks the parts must make up together
 * (ATTR_BLOCKS' syntax, raytracer/sample_blocks.h). An input with samples
 * outside them (another seed, another range) is refused naming it, and so
 * is a merge that leaves some of them out ("a part is missing"). */
int reference_merge_planned(const reference_registry *quantities, const image *inputs, const char *const *names,
                            int count, const char *planned, image *out, gt_error *e);

#endif
