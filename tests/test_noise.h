/* Deterministic noise for tests: splitmix64 (Steele, Lea and Flood 2014) as
 * a hash of the sample's key, uniform variates from its top 53 bits, and
 * Box-Muller Gaussians. The same keys give the same numbers on every
 * machine, so Monte Carlo tests run with fixed seeds. */
#ifndef GTLAB_TESTS_TEST_NOISE_H
#define GTLAB_TESTS_TEST_NOISE_H

#include <math.h>
#include <stdint.h>

static inline uint64_t splitmix64(uint64_t z)
{
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* Uniform in (0, 1): 53 random bits, offset by half a step. */
static inline double uniform01(uint64_t key) { return ((double)(splitmix64(key) >> 11) + 0.5) * 0x1p-53; }

/* Standard normal number i of stream `seed` (Box-Muller on two uniforms). */
static inline double gaussian(uint64_t seed, uint64_t i)
{
    double u1 = uniform01(seed * 0x100000000ull + 2 * i), u2 = uniform01(seed * 0x100000000ull + 2 * i + 1);
    return sqrt(-2.0 * log(u1)) * cos(6.283185307179586 * u2); /* 2 pi u2 */
}

#endif
