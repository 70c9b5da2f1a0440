/* Owen-scrambled Sobol' points (core/sampling/sobol.c), checked against independent
 * mathematics:
 *  - the raw dimensions against direction numbers rebuilt here from the
 *    Joe-Kuo recurrence, and against published first points;
 *  - owen_scramble against the defining property of a nested uniform
 *    scramble (each output digit is the input digit, flipped or not by a
 *    function of the digits before it);
 *  - sobol_owen_2d against the (0, m, 2)-net property in every aligned block
 *    of 2^m indices, for several seeds and dimension pairs. */
#include <stdint.h>
#include <string.h>

#include "core/sampling/sobol.h"
#include "tests/check.h"

static uint32_t xorshift(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

static double unit(uint32_t fixed_point) { return (double)fixed_point * 0x1p-32; }

/* Direction numbers V_k = m_k / 2^k (k = 1..32) as 32-bit fixed point, from
 * the recurrence of Joe & Kuo 2008 ("Constructing Sobol sequences with better
 * two-dimensional projections", eq. 2) for a primitive polynomial of degree
 * s = 1 with no inner coefficients: m_k = 2 m_{k-1} XOR m_{k-1}, m_1 = 1.
 * For the first dimension every m_k = 1 (the van der Corput sequence). */
static void direction_numbers(int second, uint32_t v[32])
{
    uint64_t m = 1;
    for (int k = 1; k <= 32; ++k) {
        if (k > 1 && second)
            m = (2 * m) ^ m;
        v[k - 1] = (uint32_t)(m << (32 - k));
    }
}

/* The Sobol' point of index i: XOR of the direction numbers of its set bits. */
static uint32_t sobol_reference(const uint32_t v[32], uint32_t i)
{
    uint32_t x = 0;
    for (int k = 0; k < 32; ++k)
        if (i >> k & 1u)
            x ^= v[k];
    return x;
}

static void test_raw_dimensions(void)
{
    uint32_t v0[32], v1[32];
    direction_numbers(0, v0);
    direction_numbers(1, v1);
    /* The recurrence gives m = 1, 3, 5, 15, 17, 51, 85, 255 for x + 1. */
    const uint32_t m_expected[8] = {1, 3, 5, 15, 17, 51, 85, 255};
    for (int k = 1; k <= 8; ++k)
        CHECK(v1[k - 1] >> (32 - k) == m_expected[k - 1]);

    int wrong0 = 0, wrong1 = 0;
    for (uint32_t i = 0; i < (1u << 16); ++i) {
        wrong0 += sobol_dimension0(i) != sobol_reference(v0, i);
        wrong1 += sobol_dimension1(i) != sobol_reference(v1, i);
    }
    uint32_t s = 99;
    for (int n = 0; n < 100000; ++n) {
        uint32_t i = xorshift(&s);
        wrong0 += sobol_dimension0(i) != sobol_reference(v0, i);
        wrong1 += sobol_dimension1(i) != sobol_reference(v1, i);
    }
    CHECK_MSG(wrong0 == 0, "dimension 0 differs from the recurrence at %d indices", wrong0);
    CHECK_MSG(wrong1 == 0, "dimension 1 differs from the recurrence at %d indices", wrong1);

    /* The first 8 unscrambled Sobol' points as published (Joe-Kuo direction
     * numbers, Gray-code order of Antonov-Saleev; e.g. the example in SciPy's
     * scipy.stats.qmc.Sobol documentation): Gray-code index g(i) = i ^ (i >> 1). */
    const double first_dim[8] = {0, 0.5, 0.75, 0.25, 0.375, 0.875, 0.625, 0.125};
    const double second_dim[8] = {0, 0.5, 0.25, 0.75, 0.375, 0.875, 0.125, 0.625};
    for (uint32_t i = 0; i < 8; ++i) {
        uint32_t g = i ^ (i >> 1);
        CHECK_MSG(unit(sobol_dimension0(g)) == first_dim[i], "dimension 0, point %u: %g", i,
                  unit(sobol_dimension0(g)));
        CHECK_MSG(unit(sobol_dimension1(g)) == second_dim[i], "dimension 1, point %u: %g", i,
                  unit(sobol_dimension1(g)));
    }
}

/* Bit j counted from the most significant (j = 0 is the 1/2 digit). */
static uint32_t digit_mask(int j) { return 1u << (31 - j); }

static void test_owen_scramble(void)
{
    /* A bijection of the 16-bit prefixes: 2^16 inputs x << 16 give 2^16
     * distinct top halves. */
    static unsigned char seen[1u << 16];
    const uint32_t seeds[] = {0u, 1u, 0xdeadbeefu, 0x9e3779b9u};
    for (size_t s = 0; s < sizeof seeds / sizeof seeds[0]; ++s) {
        memset(seen, 0, sizeof seen);
        int distinct = 0;
        for (uint32_t x = 0; x < (1u << 16); ++x) {
            uint32_t top = owen_scramble(x << 16, seeds[s]) >> 16;
            distinct += !seen[top];
            seen[top] = 1;
        }
        CHECK_MSG(distinct == 1 << 16, "seed %#x: %d distinct prefixes", seeds[s], distinct);
    }

    /* Nested uniform scrambling (Owen 1995): output digit j is input digit j
     * XOR a function of input digits 0..j-1. So flipping input digit j
     * flips output digit j and leaves digits 0..j-1 alone; equivalently,
     * points sharing their top j digits still share them afterwards. */
    uint32_t state = 12345;
    int violations = 0;
    for (int n = 0; n < 20000; ++n) {
        uint32_t x = xorshift(&state), seed = xorshift(&state);
        int j = (int)(xorshift(&state) % 32);
        uint32_t diff = owen_scramble(x, seed) ^ owen_scramble(x ^ digit_mask(j), seed);
        uint32_t above = j == 0 ? 0 : diff >> (32 - j);
        if (above != 0 || !(diff & digit_mask(j)))
            ++violations;
    }
    CHECK_MSG(violations == 0, "%d of 20000 digit flips broke the nesting", violations);

    /* Uniform: over many seeds, each digit of the image of 0 is a fair coin
     * (within 5 standard deviations of 1/2). */
    const int n_seeds = 1 << 14;
    for (int j = 0; j < 24; ++j) {
        int ones = 0;
        for (int s = 0; s < n_seeds; ++s)
            ones += (owen_scramble(0, hash_combine((uint32_t)s, 7u)) & digit_mask(j)) != 0;
        double fraction = (double)ones / n_seeds;
        CHECK_NEAR(fraction, 0.5, 5.0 * sqrt(0.25 / n_seeds));
    }
    /* Different seeds, different scrambles. */
    CHECK(owen_scramble(0x12345678u, 1u) != owen_scramble(0x12345678u, 2u));
}

/* The 2^m points of indices [block 2^m, (block+1) 2^m) have exactly one point
 * in each elementary interval [a/2^i, (a+1)/2^i) x [b/2^(m-i), (b+1)/2^(m-i)),
 * for every i = 0..m. Returns the number of intervals that do not. */
static int net_defects(uint32_t seed, uint32_t pair, int m, uint32_t block)
{
    static unsigned short count[1 << 10];
    int defects = 0;
    for (int i = 0; i <= m; ++i) {
        memset(count, 0, sizeof(count[0]) << m);
        for (uint32_t k = 0; k < (1u << m); ++k) {
            float u[2];
            sobol_owen_2d(seed, (block << m) + k, pair, u);
            if (!(u[0] >= 0.0f && u[0] < 1.0f && u[1] >= 0.0f && u[1] < 1.0f))
                return 1 << m;
            /* u has 24 bits, so these products are exact. */
            uint32_t a = (uint32_t)(u[0] * (float)(1u << i)), b = (uint32_t)(u[1] * (float)(1u << (m - i)));
            count[(a << (m - i)) | b]++;
        }
        for (uint32_t c = 0; c < (1u << m); ++c)
            defects += count[c] != 1;
    }
    return defects;
}

static void test_nets(void)
{
    const uint32_t seeds[] = {0u, 1u, 0xabcdef01u, pixel_seed(7u, 100u, 200u)};
    const uint32_t pairs[] = {0u, 1u, 5u};
    const uint32_t blocks[] = {0u, 1u, 3u, 1000u};
    int failures = 0;
    for (size_t s = 0; s < 4; ++s)
        for (size_t p = 0; p < 3; ++p)
            for (int m = 0; m <= 10; ++m)
                for (size_t b = 0; b < 4; ++b) {
                    int d = net_defects(seeds[s], pairs[p], m, blocks[b]);
                    if (d && failures++ < 5)
                        fprintf(stderr, "seed %#x pair %u m %d block %u: %d bad intervals\n", seeds[s], pairs[p], m,
                                blocks[b], d);
                }
    CHECK_MSG(failures == 0, "%d (seed, pair, m, block) cases are not (0, m, 2)-nets", failures);

    /* Different seeds and different pairs give different points, and the
     * same arguments the same point. */
    int same_seed_diff = 0, same_pair_diff = 0, repeat_diff = 0;
    for (uint32_t i = 0; i < 256; ++i) {
        float a[2], b[2], c[2], d[2];
        sobol_owen_2d(1u, i, 0u, a);
        sobol_owen_2d(2u, i, 0u, b);
        sobol_owen_2d(1u, i, 1u, c);
        sobol_owen_2d(1u, i, 0u, d);
        same_seed_diff += a[0] == b[0] && a[1] == b[1];
        same_pair_diff += a[0] == c[0] && a[1] == c[1];
        repeat_diff += a[0] != d[0] || a[1] != d[1];
    }
    CHECK_MSG(same_seed_diff == 0, "%d points equal for seeds 1 and 2", same_seed_diff);
    CHECK_MSG(same_pair_diff == 0, "%d points equal for pairs 0 and 1", same_pair_diff);
    CHECK(repeat_diff == 0);

    /* Pixel seeds of a 256 x 256 image: a 32-bit hash gives about 0.5
     * collisions in expectation; more than a handful means a weak hash. */
    static uint32_t seeds_seen[1 << 16];
    for (uint32_t y = 0; y < 256; ++y)
        for (uint32_t x = 0; x < 256; ++x)
            seeds_seen[y * 256 + x] = pixel_seed(1u, x, y);
    /* Duplicates counted through an open-addressing set. */
    int collisions = 0;
    static uint32_t table[1 << 18];
    static unsigned char used[1 << 18];
    memset(used, 0, sizeof used);
    for (int i = 0; i < (1 << 16); ++i) {
        uint32_t h = (seeds_seen[i] * 2654435761u) >> 14;
        while (used[h] && table[h] != seeds_seen[i])
            h = (h + 1) & ((1u << 18) - 1);
        collisions += used[h];
        used[h] = 1;
        table[h] = seeds_seen[i];
    }
    CHECK_MSG(collisions <= 4, "%d pixel seed collisions in 256 x 256 pixels", collisions);
}

int main(void)
{
    test_raw_dimensions();
    test_owen_scramble();
    test_nets();
    return check_report("test_sobol");
}
