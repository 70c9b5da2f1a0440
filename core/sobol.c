#include "core/sobol.h"

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
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    return (x >> 16) | (x << 16);
}

/* Sobol' dimension 0 is the van der Corput sequence: the index bit-reversed. */
uint32_t sobol_dimension0(uint32_t index) { return reverse_bits(index); }

/* Sobol' dimension 1 (primitive polynomial x + 1): its generator matrix is
 * Pascal's triangle mod 2, so direction number v_{k+1} = v_k ^ (v_k >> 1). */
uint32_t sobol_dimension1(uint32_t index)
{
    uint32_t result = 0;
    for (uint32_t v = 1u << 31; index; index >>= 1, v ^= v >> 1)
        if (index & 1u)
            result ^= v;
    return result;
}

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

void sobol_owen_2d(uint32_t seed, uint32_t index, uint32_t pair, float out[2])
{
    uint32_t pair_seed = hash_combine(seed, pair);
    uint32_t shuffled = owen_scramble(index, pair_seed);
    out[0] = unit_float(owen_scramble(sobol_dimension0(shuffled), hash_combine(pair_seed, 0xa511e9b3u)));
    out[1] = unit_float(owen_scramble(sobol_dimension1(shuffled), hash_combine(pair_seed, 0x63d83595u)));
}
