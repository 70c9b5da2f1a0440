/* Merging partial reference renders: renders of the same quantity, scene and
 * camera over disjoint blocks of the sample sequence (or with different
 * seeds) combine exactly, because their accumulators hold exact sums
 * (core/mc_film.h). The result equals one render over the union of the
 * blocks, bit for bit. */
#ifndef GTLAB_RAYTRACER_REFERENCE_MERGE_H
#define GTLAB_RAYTRACER_REFERENCE_MERGE_H

#include "core/error.h"
#include "core/image.h"

/* inputs[i] was read from names[i] (for errors). `out` is initialised here. */
int reference_merge(const image *inputs, const char *const *names, int count, image *out, gt_error *e);

#endif
