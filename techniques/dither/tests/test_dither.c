/* Dithered quantisation (dither/dither.c, metrics/dither_metrics.c) against
 * the theory of nonsubtractive dither (Lipshitz, Wannamaker, Vanderkooy 1992;
 * Christou 2008 ch. 2), by Monte Carlo with fixed seeds, within 5 standard
 * errors of the run itself, at 41 signals per LSB:
 *  - TPDF of 2 LSB (u0 + u1 - 1/2, and the talk's remap_tri of one uniform):
 *    E[e] = 0 and Var[e] = 1/4 LSB^2 at every signal, floor and round
 *    quantisers (with dither_offset);
 *  - RPDF: E[e] = 0, Var[e] = f (1 - f);
 *  - the talk's "(rand + rand) / 2" as written: a 1-LSB triangle, biased by
 *    2 f^2 - f for f <= 1/2 (-1/8 LSB at f = 1/4) and with Var -> 0 at f = 0;
 *  - remap_tri's distribution: its CDF on a fine grid of v is the triangle's;
 *  - UNORM and R11G11B10 rounding against an independent brute force over
 *    every representable small float (ties to the even mantissa);
 *  - Bayer's 8 x 8 matrix: the published first row 0 32 8 40 2 34 10 42 and
 *    each index once;
 *  - banding: an undithered 4-LSB ramp over 256 pixels has runs of 64, the
 *    TPDF-dithered one (p = 3/4 of keeping a value at integers) under a third. */
#include <math.h>

#include "dither/dither.h"
#include "luts/blue_noise.h"
#include "metrics/dither_metrics.h"
#include "realtime/dither_patterns.h"
#include "tests/check.h"

#define SAMPLES 40000
#define SIGNALS 41

typedef struct {
    double mean, variance, mean_se, variance_se;
} error_moments;

/* Moments of e = q - s over SAMPLES dither draws at signal s. */
static error_moments moments_at(double s, dither_kind kind, dither_quantiser qz, uint64_t seed)
{
    double m1 = 0, m2 = 0, m4 = 0;
    for (int i = 0; i < SAMPLES; ++i) {
        double d = dither_value(kind, blue_noise_uniform(seed, 2 * i), blue_noise_uniform(seed, 2 * i + 1));
        double err = dither_quantise_lsb(s + d + dither_offset(qz), qz) - s;
        m1 += err, m2 += err * err;
    }
    m1 /= SAMPLES, m2 /= SAMPLES;
    for (int i = 0; i < SAMPLES; ++i) { /* fourth central moment, for the variance's error */
        double d = dither_value(kind, blue_noise_uniform(seed, 2 * i), blue_noise_uniform(seed, 2 * i + 1));
        double c = dither_quantise_lsb(s + d + dither_offset(qz), qz) - s - m1;
        m4 += c * c * c * c / SAMPLES;
    }
    error_moments r = {m1, m2 - m1 * m1, 0, 0};
    r.mean_se = sqrt(r.variance / SAMPLES) + 1e-12;
    r.variance_se = sqrt(fmax(m4 - r.variance * r.variance, 0) / SAMPLES) + 1e-12;
    return r;
}

static void check_signal_independent_variance(dither_kind kind, dither_quantiser qz)
{
    for (int i = 0; i < SIGNALS; ++i) {
        double s = 3.0 + (double)i / (SIGNALS - 1);
        error_moments m = moments_at(s, kind, qz, 100 + i);
        CHECK_MSG(fabs(m.mean) <= 5 * m.mean_se, "%s s=%g mean %g se %g", dither_kind_name(kind), s, m.mean, m.mean_se);
        CHECK_MSG(fabs(m.variance - 0.25) <= 5 * m.variance_se, "%s s=%g var %g se %g", dither_kind_name(kind), s,
                  m.variance, m.variance_se);
    }
}

static void check_rpdf(void)
{
    for (int i = 0; i < SIGNALS; ++i) {
        double s = 7.0 + (double)i / (SIGNALS - 1), f = s - floor(s);
        error_moments m = moments_at(s, DITHER_RPDF, DITHER_FLOOR, 300 + i);
        CHECK_MSG(fabs(m.mean) <= 5 * m.mean_se, "rpdf s=%g mean %g", s, m.mean);
        CHECK_MSG(fabs(m.variance - f * (1 - f)) <= 5 * m.variance_se, "rpdf s=%g var %g want %g", s, m.variance,
                  f * (1 - f));
    }
}

static void check_average_as_written(void)
{
    error_moments quarter = moments_at(5.25, DITHER_TPDF_AVERAGE, DITHER_FLOOR, 7);
    CHECK_MSG(fabs(quarter.mean - (-0.125)) <= 5 * quarter.mean_se, "average bias %g", quarter.mean);
    error_moments whole = moments_at(5.0, DITHER_TPDF_AVERAGE, DITHER_FLOOR, 8);
    CHECK(whole.variance < 1e-3);
    error_moments half = moments_at(5.5, DITHER_TPDF_AVERAGE, DITHER_FLOOR, 9);
    CHECK_NEAR(half.variance, 0.25, 5 * half.variance_se);
}

static double triangle_cdf(double x)
{
    if (x <= -0.5)
        return 0.0;
    if (x >= 1.5)
        return 1.0;
    return x < 0.5 ? 0.5 * (x + 0.5) * (x + 0.5) : 1.0 - 0.5 * (1.5 - x) * (1.5 - x);
}

static void check_remap_distribution(void)
{
    enum { M = 100000 };
    for (double x = -0.4; x < 1.5; x += 0.1) {
        int below = 0;
        for (int i = 0; i < M; ++i)
            below += dither_remap_triangular((i + 0.5) / M) <= x;
        CHECK_NEAR((double)below / M, triangle_cdf(x), 2.0 / M);
    }
    CHECK(dither_remap_triangular(0.5) == -0.5);
    CHECK(fabs(dither_remap_triangular(0.0) - 0.5) < 1e-12 && dither_remap_triangular(0.4999999) > 1.49);
}

/* Brute force: the representable small float nearest to x, ties to the even mantissa. */
static double small_float_brute(double x, int m)
{
    double best = 0.0, best_d = fabs(x);
    int best_even = 1;
    for (int e = 0; e < 31; ++e)
        for (int k = 0; k < (1 << m); ++k) {
            double v = e == 0 ? ldexp(k, -14 - m) : ldexp(1.0 + ldexp(k, -m), e - 15);
            double d = fabs(x - v);
            if (d < best_d || (d == best_d && !best_even && (k % 2 == 0)))
                best = v, best_d = d, best_even = k % 2 == 0;
        }
    return best;
}

static void check_quantisers(void)
{
    for (int k = 0; k < 256; ++k)
        CHECK(dither_unorm(k / 255.0, 8, 0.0) == k / 255.0);
    CHECK(dither_unorm(2.0, 10, 0.0) == 1.0 && dither_unorm(-1.0, 10, 0.0) == 0.0);
    CHECK(dither_small_float(1e9, 6) == 65024.0 && dither_small_float(1e9, 5) == 64512.0);
    CHECK(dither_small_float(1.0 + 1.0 / 128, 6) == 1.0 && dither_small_float(1.0 + 3.0 / 128, 6) == 1.03125);
    int mismatches = 0;
    for (int i = 0; i < 3000; ++i) {
        double x = ldexp(blue_noise_uniform(77, i), (int)(blue_noise_uniform(78, i) * 34) - 18);
        mismatches += dither_small_float(x, 6) != small_float_brute(x, 6);
        mismatches += dither_small_float(x, 5) != small_float_brute(x, 5);
    }
    CHECK_MSG(mismatches == 0, "%d small-float mismatches", mismatches);
}

static void check_banding(void)
{
    enum { W = 256, H = 4 };
    double plain[W * H], dithered[W * H];
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            double s = 4.0 * x / W;
            double d = dither_value(DITHER_TPDF_SUM, blue_noise_uniform(5, y * W + x), blue_noise_uniform(6, y * W + x));
            plain[y * W + x] = dither_quantise_lsb(s, DITHER_FLOOR);
            dithered[y * W + x] = dither_quantise_lsb(s + d, DITHER_FLOOR);
        }
    CHECK(dither_longest_run(plain, W, H) == 64);
    CHECK_MSG(dither_longest_run(dithered, W, H) <= 64 / 3, "dithered run %d", dither_longest_run(dithered, W, H));
}

/* Bayer's 8 x 8 matrix: its published first row, and every index once. */
static void check_bayer(void)
{
    static const int first_row[8] = {0, 32, 8, 40, 2, 34, 10, 42};
    int seen[64] = {0};
    for (int x = 0; x < 8; ++x)
        CHECK(dither_bayer8(x, 0) == (first_row[x] + 0.5) / 64.0);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            seen[(int)(dither_bayer8(x, y) * 64.0)]++;
    for (int k = 0; k < 64; ++k)
        CHECK(seen[k] == 1);
    CHECK(dither_bayer8(3, 5) == dither_bayer8(11, 13));
}

int main(void)
{
    check_bayer();
    check_signal_independent_variance(DITHER_TPDF_SUM, DITHER_FLOOR);
    check_signal_independent_variance(DITHER_TPDF_SUM, DITHER_ROUND);
    check_signal_independent_variance(DITHER_TPDF_REMAP, DITHER_FLOOR);
    check_rpdf();
    check_average_as_written();
    check_remap_distribution();
    check_quantisers();
    check_banding();
    return check_report("test_dither");
}
