#include "core/sampling/sobol.h"

uint32_t hash_combine(uint32_t a, uint32_t b)
{
    /* The "lowbias32" integer hash (Chris Wellons' hash-prospector) of a
     * boost-style combine of the two words. */
    uint32_t x = a ^ (b + 0x9e3779b9u + (a << 6) + (a >> 2));
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

uint32_t pixel_seed(uint32_t seed, uint32_t x, uint32_t y)
{
    return hash_combine(hash_combine(seed, x), y);
}

static uint32_t reverse_bits(uint32_t x)
{
    x = __builtin_bswap32(x);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    return ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
}

/* Sobol' dimension 0 is the van der Corput sequence: the index bit-reversed. */
uint32_t sobol_dimension0(uint32_t index) { return reverse_bits(index); }

/* Sobol' dimension 1 (primitive polynomial x + 1) has Pascal's triangle mod 2
 * as generator matrix: index bit k contributes C(k, j) mod 2 to output digit
 * j (counted from the most significant). By Lucas' theorem C(k, j) is odd iff
 * the bits of j are a subset of those of k, so output digit j is the XOR of
 * the index bits k that are supersets of j: a superset transform over the five
 * bits of the position, done in five shifts. Returned in reversed bit order
 * (digit j at bit j), the form the scrambler works in. */
static uint32_t sobol_dimension1_reversed(uint32_t index)
{
    uint32_t y = index;
    y ^= (y >> 1) & 0x55555555u;
    y ^= (y >> 2) & 0x33333333u;
    y ^= (y >> 4) & 0x0f0f0f0fu;
    y ^= (y >> 8) & 0x00ff00ffu;
    y ^= (y >> 16) & 0x0000ffffu;
    return y;
}

uint32_t sobol_dimension1(uint32_t index) { return reverse_bits(sobol_dimension1_reversed(index)); }

/* A Laine-Karras permutation: each output bit depends only on the input bits
 * below it, which is what makes it an Owen scramble of the reversed bits. */
static uint32_t laine_karras_permutation(uint32_t x, uint32_t seed)
{
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

uint32_t owen_scramble(uint32_t x, uint32_t seed)
{
    return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
}

static float unit_float(uint32_t bits)
{
    /* The top 24 bits, so the result is exactly representable and < 1. */
    return (float)(bits >> 8) * 0x1p-24f;
}

sobol_pair_seeds sobol_owen_pair_seeds(uint32_t seed, uint32_t pair)
{
    sobol_pair_seeds s;
    s.shuffle = hash_combine(seed, pair);
    s.x = hash_combine(s.shuffle, 0xa511e9b3u);
    s.y = hash_combine(s.shuffle, 0x63d83595u);
    return s;
}

/* Burley 2020, section 4, with the bit reversals that cancel removed:
 * owen_scramble(x) = reverse(LK(reverse(x))), and dimension 0 is
 * reverse(index), so both coordinates are scrambled in reversed-bit form. */
void sobol_owen_point(const sobol_pair_seeds *seeds, uint32_t index, float out[2])
{
    /* The shuffled index, reversed: it is also Sobol' dimension 0 of the
     * shuffled index. */
    uint32_t shuffled_reversed = laine_karras_permutation(reverse_bits(index), seeds->shuffle);
    uint32_t shuffled = reverse_bits(shuffled_reversed);
    uint32_t x = reverse_bits(laine_karras_permutation(shuffled, seeds->x));
    uint32_t y = reverse_bits(laine_karras_permutation(sobol_dimension1_reversed(shuffled), seeds->y));
    out[0] = unit_float(x);
    out[1] = unit_float(y);
}

/* Vectorised with AVX2 where the CPU has it (the clone is chosen at load
 * time); the arithmetic is integer, so both clones give identical results. */
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target_clones("avx2", "default")))
#endif
void sobol_owen_points(const sobol_pair_seeds *seeds, uint32_t first, int count, float *u0, float *u1)
{
    const uint32_t shuffle_seed = seeds->shuffle, x_seed = seeds->x, y_seed = seeds->y;
    for (int k = 0; k < count; ++k) {
        uint32_t shuffled = reverse_bits(laine_karras_permutation(reverse_bits(first + (uint32_t)k), shuffle_seed));
        u0[k] = unit_float(reverse_bits(laine_karras_permutation(shuffled, x_seed)));
        u1[k] = unit_float(reverse_bits(laine_karras_permutation(sobol_dimension1_reversed(shuffled), y_seed)));
    }
}

void sobol_owen_2d(uint32_t seed, uint32_t index, uint32_t pair, float out[2])
{
    sobol_pair_seeds seeds = sobol_owen_pair_seeds(seed, pair);
    sobol_owen_point(&seeds, index, out);
}
