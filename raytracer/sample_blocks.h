/* The header attribute that says which samples a reference render holds
 * (ATTR_BLOCKS, core/reference_schema.h): blocks "seed:offset+count"
 * separated by spaces, each the samples offset .. offset + count - 1 of the
 * sequence of one seed. A render writes one block; a merge, the union of its
 * inputs' blocks.
 *
 * The text comes from a file, so it is read as hostile input: decimal digits
 * only, every number overflow-checked, a seed below 2^32, a count of at least
 * 1, and the block within the 32-bit sample indices a render can take
 * (offset + count <= 2^32, as `gtlab render` checks --sample-offset + --spp);
 * at most SAMPLE_BLOCKS_MAX blocks, no recursion, no buffer sized by the
 * input. The largest total a merge can then hold, 1024 * 2^32 samples, fits
 * in 64 bits. */
#ifndef GTLAB_RAYTRACER_SAMPLE_BLOCKS_H
#define GTLAB_RAYTRACER_SAMPLE_BLOCKS_H

#include <stdint.h>

#include "core/error.h"

typedef struct {
    uint32_t seed;
    uint64_t begin, end; /* samples [begin, end) of the seed's sequence */
} sample_block;

#define SAMPLE_BLOCKS_MAX 1024
#define SAMPLE_INDEX_LIMIT ((uint64_t)1 << 32)

/* Parses text (NULL: the attribute is absent) into blocks[0, *count), at
 * most `capacity` of them. Returns 0, or -1 with e = "<what>: header
 * attribute gtlab.sample_blocks: <problem>", quoting at most GT_QUOTE_MAX
 * characters of the text. */
int sample_blocks_parse(const char *text, const char *what, sample_block *blocks, int capacity, int *count,
                        gt_error *e);

/* The attribute's text for blocks[0, count) (malloc'd; free()), or NULL
 * when out of memory. */
char *sample_blocks_format(const sample_block *blocks, int count);

/* Sorts blocks[0, *count) by seed and offset and joins the ones that touch
 * ("1:16+16 1:0+16" becomes "1:0+32"), so one set of samples has one text
 * whatever parts it was rendered in. The blocks must not overlap. */
void sample_blocks_coalesce(sample_block *blocks, int *count);
/* Whether every sample of b is in one of plan[0, n) (coalesced). */
int sample_blocks_within(const sample_block *b, const sample_block *plan, int n);
/* The first samples of plan[0, n_plan) in none of have[0, n_have) (both
 * coalesced, have within plan): 1 with *gap set, or 0 when have covers plan. */
int sample_blocks_first_gap(const sample_block *have, int n_have, const sample_block *plan, int n_plan,
                            sample_block *gap);

#endif
