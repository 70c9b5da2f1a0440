/* Moment sums (core/statistics/moment_sums.c) and the film's standard errors (core/
 * mc_film.c) on a synthetic sample stream spanning 1e-9 to 1e3 in one image
 * (issue 23), against long double and exact integer arithmetic:
 *   - every pixel's variance within the documented 2^-45 P^2 (P its largest
 *     |sample|) of the long-double one, its mean within 2^-48 P, the film's
 *     mean channel within its grid's 2^(E-25); no pixel with differing
 *     samples reports a standard error of 0;
 *   - the limbs hold exactly sum_i rint(x_i / 2^(24 b)) 2^(24 b), b from the
 *     peak as documented, for the values and for their squares (128-bit
 *     integers, an implementation independent of the digits);
 *   - accumulation in any order, any split into blocks merged in any order,
 *     and any thread count give the same bits, including when a late block
 *     raises the peak;
 *   - NaN samples, all-zero and constant pixels. */
#include <stdint.h>
#include <string.h>

#include "core/statistics/mc_film.h"
#include "core/statistics/moment_sums.h"
#include "tests/check.h"

__extension__ typedef __int128 int128;

#define PIXELS 60
#define SAMPLES 300
#define KINDS 6

static float samples[PIXELS][SAMPLES];

static uint32_t rng_state = 0x9e3779b9u;
static uint32_t xorshift(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 17;
    rng_state ^= rng_state << 5;
    return rng_state;
}
static double uniform01(void) { return (double)(xorshift() >> 8) * 0x1p-24; }

/* Pixel p's magnitude runs from 1e-9 to 1e3 across the image; its kind sets
 * the shape: wide, narrow (spread 1e-4 of the value: a variance 1e-9 of
 * the square of the peak), signed, a rare spike 1000x (some arriving last,
 * raising the peak late), two values (AO-like). */
static float sample_of(int kind, double m, int i)
{
    double u = uniform01();
    switch (kind) {
    case 0: return (float)(m * (0.5 + u));
    case 1: return (float)(m * (1.0 + 1e-4 * (u - 0.5)));
    case 2: return (float)(m * (2.0 * u - 1.0));
    case 3: return (float)(u < 0.02 ? 1000.0 * m : m * u);
    case 4: return (float)(i == SAMPLES - 1 ? 1000.0 * m : m * u); /* the spike comes last */
    default: return (float)(u < 0.3 ? m : 0.0);
    }
}

static void make_samples(void)
{
    for (int p = 0; p < PIXELS; ++p) {
        double m = pow(10.0, -9.0 + 12.0 * p / (PIXELS - 1));
        for (int i = 0; i < SAMPLES; ++i)
            samples[p][i] = sample_of(p % KINDS, m, i);
        samples[p][0] = (float)m; /* every pixel's samples differ */
    }
}

static double peak_of(int p)
{
    double peak = 0.0;
    for (int i = 0; i < SAMPLES; ++i)
        peak = fmax(peak, fabs((double)samples[p][i]));
    return peak;
}

/* ---- Against long double ------------------------------------------------ */

static void direct(int p, long double *mean, long double *variance)
{
    long double sum = 0, ss = 0;
    for (int i = 0; i < SAMPLES; ++i)
        sum += samples[p][i];
    *mean = sum / SAMPLES;
    for (int i = 0; i < SAMPLES; ++i)
        ss += (samples[p][i] - *mean) * (samples[p][i] - *mean);
    *variance = ss / (SAMPLES - 1);
}

static void add_pixel(mc_film *film, int p)
{
    mc_pixel acc;
    mc_pixel_clear(&acc, film);
    for (int first = 0; first < SAMPLES; first += 64) {
        int count = SAMPLES - first < 64 ? SAMPLES - first : 64;
        mc_pixel_add_samples(&acc, film, (uint32_t)first, count, &samples[p][first], SAMPLES);
    }
    mc_film_add_pixel(film, p, &acc);
}

static void test_against_long_double(void)
{
    const mc_quantity quantity = {"x.V", 10}; /* samples within 2^10 expected: the 1e3 end */
    mc_film film;
    CHECK(mc_film_init(&film, PIXELS, 1, &quantity, 1) == 0);
    for (int p = 0; p < PIXELS; ++p)
        add_pixel(&film, p);
    int bad_var = 0, bad_mean = 0, bad_grid_mean = 0, zero = 0;
    double worst_rel_stderr = 0.0;
    for (int p = 0; p < PIXELS; ++p) {
        long double mean, variance;
        direct(p, &mean, &variance);
        double peak = peak_of(p), err = mc_film_stderr(&film, 0, p);
        double var = moment_sums_variance(&film.moments[p], SAMPLES);
        double moment_mean = moment_sums_total(&film.moments[p]) / SAMPLES;
        if (!(fabs(var - (double)variance) <= 0x1p-45 * peak * peak) && bad_var++ < 5)
            fprintf(stderr, "pixel %d: variance %.17g, long double %.17Lg, peak %g\n", p, var, variance, peak);
        if (!(fabs(moment_mean - (double)mean) <= 0x1p-48 * peak) && bad_mean++ < 5)
            fprintf(stderr, "pixel %d: moment mean %.17g, long double %.17Lg\n", p, moment_mean, mean);
        bad_grid_mean += !(fabs(mc_film_mean(&film, 0, p) - (double)mean) <= ldexp(1.0, quantity.scale_exponent - 25));
        zero += !(err > 0.0);
        double want = sqrtl(variance / SAMPLES);
        worst_rel_stderr = fmax(worst_rel_stderr, fabs(err - want) / want);
    }
    CHECK_MSG(bad_var == 0, "%d variances beyond 2^-45 peak^2", bad_var);
    CHECK_MSG(bad_mean == 0, "%d moment means beyond 2^-48 peak", bad_mean);
    CHECK_MSG(bad_grid_mean == 0, "%d film means beyond 2^(E-25)", bad_grid_mean);
    CHECK_MSG(zero == 0, "%d pixels with differing samples report a standard error of 0", zero);
    /* The narrow pixels (P/s = 3.5e4) are the hardest: 2^-45 (P/s)^2 / 2. */
    CHECK_MSG(worst_rel_stderr < 2e-5, "standard errors off by %.3g relative", worst_rel_stderr);
    mc_film_free(&film);
}

/* ---- The limbs hold the documented exact sum --------------------------- */

/* rint(x / 2^shift) exactly, ties to even, as a 128-bit integer (x finite,
 * the result within 2^100). */
static int128 rounded_scaled(double x, int shift)
{
    int e;
    double f = frexp(fabs(x), &e);
    int64_t m = (int64_t)ldexp(f, 53); /* |x| = m 2^(e - 53) */
    int k = shift - (e - 53);          /* |x| / 2^shift = m / 2^k */
    int128 r;
    if (x == 0.0 || k >= 55)
        r = 0;
    else if (k <= 0)
        r = (int128)m << -k;
    else {
        int64_t q = m >> k, rem = m - (q << k), half = (int64_t)1 << (k - 1);
        r = q + (rem > half || (rem == half && (q & 1)));
    }
    return x < 0 ? -r : r;
}

static int window_top_of(double peak)
{
    int e;
    frexp(peak, &e);
    return (int)floor(e / 24.0);
}

/* sum_k limb[k] 2^(24 (2 - k)): the limbs' value in units of 2^(24 b). */
static int128 limbs_in_bottom_units(const int64_t limb[MOMENT_LIMBS])
{
    const int128 digit = (int128)1 << 24;
    return ((int128)limb[0] * digit + (int128)limb[1]) * digit + (int128)limb[2];
}

static void test_limbs_exact(void)
{
    int bad = 0;
    for (int p = 0; p < PIXELS; ++p) {
        moment_sums m;
        moment_sums_clear(&m);
        for (int i = 0; i < SAMPLES; ++i)
            moment_sums_add_run(&m, &samples[p][i], 1, moment_sums_run_peak(&samples[p][i], 1));
        double peak = peak_of(p);
        int b = window_top_of(peak) - 2, b_sq = window_top_of(peak * peak) - 2;
        int128 want = 0, want_sq = 0;
        for (int i = 0; i < SAMPLES; ++i) {
            double v = samples[p][i];
            want += rounded_scaled(v, 24 * b);
            want_sq += rounded_scaled(v * v, 24 * b_sq);
        }
        int ok = m.peak == peak && limbs_in_bottom_units(m.sum) == want && limbs_in_bottom_units(m.sum_sq) == want_sq;
        if (!ok && bad++ < 5)
            fprintf(stderr, "pixel %d: limbs differ from sum_i rint(x_i / 2^(24 b))\n", p);
    }
    CHECK_MSG(bad == 0, "%d pixels' limbs are not the documented sums", bad);
}

/* ---- Order, split, merge order, threads -------------------------------- */

/* Pixel p's samples i with i % blocks == block, in runs of varying length,
 * forwards or backwards. */
static moment_sums accumulate(int p, int blocks, int block, int reversed)
{
    float picked[SAMPLES];
    int n = 0;
    for (int k = 0; k < SAMPLES; ++k) {
        int i = reversed ? SAMPLES - 1 - k : k;
        if (i % blocks == block)
            picked[n++] = samples[p][i];
    }
    moment_sums m;
    moment_sums_clear(&m);
    for (int first = 0, run = 1; first < n; first += run, run = run % 37 + 3) {
        int count = first + run <= n ? run : n - first;
        moment_sums_add_run(&m, &picked[first], count, moment_sums_run_peak(&picked[first], count));
    }
    return m;
}

static void test_order_and_merges(void)
{
    int bad = 0;
    for (int p = 0; p < PIXELS; ++p) {
        moment_sums whole = accumulate(p, 1, 0, 0), backwards = accumulate(p, 1, 0, 1);
        moment_sums part[3] = {accumulate(p, 3, 0, 1), accumulate(p, 3, 1, 0), accumulate(p, 3, 2, 1)};
        static const int orders[3][3] = {{0, 1, 2}, {2, 0, 1}, {1, 2, 0}};
        moment_sums merged[4];
        for (int o = 0; o < 3; ++o) {
            merged[o] = part[orders[o][0]];
            moment_sums_merge(&merged[o], &part[orders[o][1]]);
            moment_sums_merge(&merged[o], &part[orders[o][2]]);
        }
        merged[3] = part[1]; /* a + (b + c) */
        moment_sums_merge(&merged[3], &part[2]);
        moment_sums tail = part[0];
        moment_sums_merge(&tail, &merged[3]);
        merged[3] = tail;
        int same = memcmp(&whole, &backwards, sizeof whole) == 0;
        for (int o = 0; o < 4; ++o)
            same &= memcmp(&whole, &merged[o], sizeof whole) == 0;
        if (!same && bad++ < 5)
            fprintf(stderr, "pixel %d: the order or the split changed the bits\n", p);
    }
    CHECK_MSG(bad == 0, "%d pixels depend on the order of accumulation", bad);
}

static void render_film(mc_film *film, int threads)
{
    const mc_quantity quantity = {"x.V", 10};
    mc_film_init(film, PIXELS, 1, &quantity, 1);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int p = 0; p < PIXELS; ++p)
        add_pixel(film, PIXELS - 1 - p);
}

static void test_threads(void)
{
    mc_film one, three;
    render_film(&one, 1);
    render_film(&three, 3);
    CHECK(memcmp(one.moments, three.moments, PIXELS * sizeof(moment_sums)) == 0);
    CHECK(memcmp(one.sum, three.sum, PIXELS * sizeof(double)) == 0);
    mc_film_free(&one);
    mc_film_free(&three);
}

/* ---- Special pixels ------------------------------------------------------ */

static moment_sums sums_of(const float *values, int count)
{
    moment_sums m;
    moment_sums_clear(&m);
    moment_sums_add_run(&m, values, count, moment_sums_run_peak(values, count));
    return m;
}

static void test_special_pixels(void)
{
    float zeros[8] = {0}, ones[8], with_nan[8];
    for (int i = 0; i < 8; ++i)
        ones[i] = 1.0f, with_nan[i] = (float)i;
    with_nan[5] = NAN;
    moment_sums z = sums_of(zeros, 8), o = sums_of(ones, 8), n = sums_of(with_nan, 8);
    CHECK(moment_sums_variance(&z, 8) == 0.0 && moment_sums_total(&z) == 0.0);
    CHECK(moment_sums_variance(&o, 8) == 0.0 && moment_sums_total(&o) == 8.0);
    CHECK(isnan(moment_sums_variance(&n, 8)) && isnan(moment_sums_total(&n)));
    /* Constants whose squares the window rounds: a variance within the bound. */
    for (int k = 0; k < 200; ++k) {
        float c[8];
        for (int i = 0; i < 8; ++i)
            c[i] = (float)(pow(10.0, -9.0 + 12.0 * uniform01()) * (0.5 + uniform01()));
        for (int i = 1; i < 8; ++i)
            c[i] = c[0];
        moment_sums m = sums_of(c, 8);
        CHECK_NEAR(moment_sums_variance(&m, 8), 0.0, 0x1p-45 * (double)c[0] * c[0]);
        CHECK_NEAR(moment_sums_total(&m), 8.0 * c[0], 0x1p-48 * c[0] * 8.0);
    }
    /* A NaN wins a merge from either side, with the same bits. */
    moment_sums a = o, b = n;
    moment_sums_merge(&a, &n);
    moment_sums_merge(&b, &o);
    CHECK(isnan(moment_sums_variance(&a, 16)) && memcmp(&a, &b, sizeof a) == 0);
}

int main(void)
{
    make_samples();
    test_against_long_double();
    test_limbs_exact();
    test_order_and_merges();
    test_threads();
    test_special_pixels();
    return check_report("test_moment_sums");
}
