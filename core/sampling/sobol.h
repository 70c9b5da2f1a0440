/* Owen-scrambled Sobol' points, after Burley 2020, "Practical Hash-based Owen
 * Scrambling" (JCGT 9(4)): every 2-D dimension pair uses the first two Sobol'
 * dimensions, with the sample index shuffled and each coordinate scrambled by
 * a nested-uniform (Owen) scramble keyed by (pixel seed, dimension pair).
 * Consequences the renderers rely on:
 *  - a sample is a pure function of (seed, index, dimension): any thread may
 *    compute it, so images are bit-identical whatever the thread count;
 *  - the points with index in any aligned block [k 2^m, (k+1) 2^m) form a
 *    (0, m, 2)-net in every pair, so renders split at multiples of a power of
 *    two (--sample-offset) are each well stratified;
 *  - different pixels and pairs are decorrelated by their seeds.
 * The hash is Vegdahl's improved Laine-Karras permutation (2021). */
#ifndef GTLAB_CORE_SAMPLING_SOBOL_H
#define GTLAB_CORE_SAMPLING_SOBOL_H

#include <stdint.h>

/* A well-mixed 32-bit hash of (a, b); used to derive seeds. */
uint32_t hash_combine(uint32_t a, uint32_t b);

/* Seed of pixel (x, y) for a render with global seed `seed`. */
uint32_t pixel_seed(uint32_t seed, uint32_t x, uint32_t y);

/* The scramble seeds of one dimension pair of one pixel: derived once, then
 * used for every sample of the pair. */
typedef struct {
    uint32_t shuffle, x, y;
} sobol_pair_seeds;

sobol_pair_seeds sobol_owen_pair_seeds(uint32_t seed, uint32_t pair);
/* The 2-D point `index` of a dimension pair, in [0,1)^2. */
void sobol_owen_point(const sobol_pair_seeds *seeds, uint32_t index, float out[2]);
/* Points first .. first + count - 1 of a dimension pair, as two arrays of
 * coordinates: the same values as sobol_owen_point, computed several at a
 * time (integer arithmetic only, so every CPU gives the same bits). */
void sobol_owen_points(const sobol_pair_seeds *seeds, uint32_t first, int count, float *u0, float *u1);
/* The same in one call: point `index` of pair `pair` for a pixel seed. */
void sobol_owen_2d(uint32_t seed, uint32_t index, uint32_t pair, float out[2]);

/* The raw, unscrambled first two Sobol' dimensions as 32-bit fixed point
 * (exposed for tests). */
uint32_t sobol_dimension0(uint32_t index);
uint32_t sobol_dimension1(uint32_t index);
/* Nested uniform scramble of the bits of x (exposed for tests). */
uint32_t owen_scramble(uint32_t x, uint32_t seed);

#endif
