/* FLIP (metrics/flip.h) against the papers' formulas computed here
 * independently, and its stated properties: identical images score 0, a
 * constant pair scores what the colour pipeline alone gives, the mean grows
 * with added noise, HDR-FLIP is the maximum of LDR-FLIP over the exposures
 * the rule gives, and the thread count changes no bit. */
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "metrics/flip.h"
#include "tests/check.h"

enum { W = 64, H = 48 };
#define N ((size_t)W * H)

static uint64_t rng_state;
static double uniform01(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (double)(rng_state >> 11) * 0x1.0p-53;
}

/* A smooth colour image with a disc, values in [0.1, 0.9]. */
static void structured_image(float *rgb[3])
{
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            size_t i = (size_t)y * W + (size_t)x;
            int disc = (x - 30) * (x - 30) + (y - 20) * (y - 20) < 100;
            rgb[0][i] = 0.1f + 0.8f * (float)x / W;
            rgb[1][i] = disc ? 0.8f : 0.3f;
            rgb[2][i] = 0.1f + 0.8f * (float)y / H;
        }
}

static flip_image image_of(float *planes[3])
{
    flip_image im = {W, H, {planes[0], planes[1], planes[2]}};
    return im;
}

static void test_identical(void)
{
    printf("identical images\n");
    float *p[3];
    for (int c = 0; c < 3; ++c)
        p[c] = malloc(sizeof(float) * N);
    structured_image(p);
    flip_image im = image_of(p);
    float *map = malloc(sizeof(float) * N);
    gt_error e;
    CHECK_MSG(flip_ldr(&im, &im, FLIP_DEFAULT_PPD, "identical", map, &e) == 0, "%s", e.message);
    int zero = 1;
    for (size_t i = 0; i < N; ++i)
        zero &= map[i] == 0.0f;
    CHECK_MSG(zero, "LDR-FLIP of an image against itself is not 0 everywhere");
    flip_exposures x = flip_exposure_range(&im, NULL);
    CHECK(flip_hdr(&im, &im, x, FLIP_DEFAULT_PPD, "identical", map, &e) == 0);
    zero = 1;
    for (size_t i = 0; i < N; ++i)
        zero &= map[i] == 0.0f;
    CHECK_MSG(zero, "HDR-FLIP of an image against itself is not 0 everywhere");
    free(map);
    for (int c = 0; c < 3; ++c)
        free(p[c]);
}

/* ---- the constant pair, by hand ----------------------------------------
 *
 * Reference linear RGB (0.5, 0.5, 0.5), test (0.5, 0.25, 0.25), each a
 * constant image. The CSF kernels sum to 1 and the edges are replicated, so
 * filtering leaves a constant image unchanged; the edge and point kernels'
 * taps sum to 1 - 1 = 0, so both images have no feature and dE_f = 0:
 * FLIP = dE_c^1, the colour pipeline alone.
 *
 *  XYZ (IEC 61966-2-1 matrix, D65 white Xn = 0.95047, Zn = 1.08883):
 *    reference (0.47524, 0.50000, 0.54442); test (0.34070, 0.30316, 0.27706)
 *  L*a*b* (f(t) = t^(1/3) above (6/29)^3):
 *    reference L* = 116 0.5^(1/3) - 16 = 76.069, a* = b* = 0 (a grey);
 *    test L* = 61.926, a* = 500 (f(0.35846) - f(0.30316)) = 19.299,
 *         b* = 200 (f(0.30316) - f(0.25445)) = 7.622
 *  Hunt (a, b) <- 0.01 L* (a, b): test (11.951, 4.720)
 *  HyAB = |76.069 - 61.926| + sqrt(11.951^2 + 4.720^2) = 14.143 + 12.849 = 26.993
 *  e = 26.993^0.7 = 10.043
 *  c_max: green (0, 1, 0) -> L* 87.736, Hunt (a, b) (-75.610, 72.981);
 *         blue (0, 0, 1)  -> L* 32.298, Hunt (a, b) (25.578, -34.836);
 *         HyAB = 55.438 + 147.864 = 203.302, c_max = 203.302^0.7 = 41.276
 *  p_c c_max = 16.510 > e, so dE_c = 0.95 / 16.510 x 10.043 = 0.5779.
 */
static const double srgb_to_xyz[3][3] = {
    {0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}};

static double f_lab(double t) { return t > 216.0 / 24389.0 ? cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0; }

static void hand_hunt_lab(const double rgb[3], double lab[3])
{
    double xyz[3], white[3];
    for (int i = 0; i < 3; ++i) {
        xyz[i] = srgb_to_xyz[i][0] * rgb[0] + srgb_to_xyz[i][1] * rgb[1] + srgb_to_xyz[i][2] * rgb[2];
        white[i] = srgb_to_xyz[i][0] + srgb_to_xyz[i][1] + srgb_to_xyz[i][2];
    }
    double fx = f_lab(xyz[0] / white[0]), fy = f_lab(xyz[1] / white[1]), fz = f_lab(xyz[2] / white[2]);
    double l = 116.0 * fy - 16.0;
    lab[0] = l, lab[1] = l / 100.0 * 500.0 * (fx - fy), lab[2] = l / 100.0 * 200.0 * (fy - fz);
}

static double hand_hyab(const double rgb_a[3], const double rgb_b[3])
{
    double a[3], b[3];
    hand_hunt_lab(rgb_a, a);
    hand_hunt_lab(rgb_b, b);
    return fabs(a[0] - b[0]) + sqrt((a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

static double hand_constant_flip(const double ref[3], const double test[3])
{
    const double green[3] = {0, 1, 0}, blue[3] = {0, 0, 1};
    double cmax = pow(hand_hyab(green, blue), 0.7), e = pow(hand_hyab(ref, test), 0.7);
    return e < 0.4 * cmax ? 0.95 * e / (0.4 * cmax) : 0.95 + 0.05 * (e - 0.4 * cmax) / (0.6 * cmax);
}

static void fill_constant(float *p[3], const double rgb[3])
{
    for (int c = 0; c < 3; ++c)
        for (size_t i = 0; i < N; ++i)
            p[c][i] = (float)rgb[c];
}

static void check_constant_pair(const double ref[3], const double test[3], double by_hand)
{
    float *a[3], *b[3];
    for (int c = 0; c < 3; ++c)
        a[c] = malloc(sizeof(float) * N), b[c] = malloc(sizeof(float) * N);
    fill_constant(a, ref);
    fill_constant(b, test);
    flip_image ia = image_of(a), ib = image_of(b);
    float *map = malloc(sizeof(float) * N);
    gt_error e;
    CHECK(flip_ldr(&ia, &ib, FLIP_DEFAULT_PPD, "constant", map, &e) == 0);
    double independent = hand_constant_flip(ref, test);
    float lo = map[0], hi = map[0];
    for (size_t i = 0; i < N; ++i)
        lo = fminf(lo, map[i]), hi = fmaxf(hi, map[i]);
    printf("  (%.2f %.2f %.2f) vs (%.2f %.2f %.2f): FLIP %.6f..%.6f, independent %.6f\n", ref[0], ref[1], ref[2],
           test[0], test[1], test[2], lo, hi, independent);
    CHECK_NEAR(lo, independent, 1e-3); /* the 4-digit matrix here against the exact fractions */
    CHECK_NEAR(hi, independent, 1e-3);
    if (by_hand >= 0.0)
        CHECK_NEAR(independent, by_hand, 1e-4);
    free(map);
    for (int c = 0; c < 3; ++c)
        free(a[c]), free(b[c]);
}

static void test_constant_pairs(void)
{
    printf("constant pairs\n");
    const double grey[3] = {0.5, 0.5, 0.5}, reddish[3] = {0.5, 0.25, 0.25};
    check_constant_pair(grey, reddish, 0.57788); /* the derivation above */
    /* beyond the knee (e > p_c c_max): black against green */
    const double black[3] = {0, 0, 0}, green[3] = {0.1, 0.9, 0.2};
    check_constant_pair(black, green, -1.0);
}

/* ---- noise ------------------------------------------------------------ */

static double mean_flip_with_noise(float *ref[3], const float *noise, double sigma)
{
    float *t[3];
    for (int c = 0; c < 3; ++c) {
        t[c] = malloc(sizeof(float) * N);
        for (size_t i = 0; i < N; ++i)
            t[c][i] = fminf(1.0f, fmaxf(0.0f, ref[c][i] + (float)sigma * noise[c * N + i]));
    }
    flip_image ir = image_of(ref), it = image_of(t);
    float *map = malloc(sizeof(float) * N);
    gt_error e;
    CHECK(flip_ldr(&ir, &it, FLIP_DEFAULT_PPD, "noise", map, &e) == 0);
    double m = flip_mean(map, NULL, N);
    free(map);
    for (int c = 0; c < 3; ++c)
        free(t[c]);
    return m;
}

static void test_noise_monotone(void)
{
    printf("mean FLIP against noise\n");
    float *ref[3], *noise = malloc(sizeof(float) * 3 * N);
    for (int c = 0; c < 3; ++c)
        ref[c] = malloc(sizeof(float) * N);
    structured_image(ref);
    rng_state = 0x2545F4914F6CDD1Dull;
    for (size_t i = 0; i < 3 * N; ++i)
        noise[i] = (float)(2.0 * uniform01() - 1.0);
    const double sigma[] = {0.0, 0.01, 0.02, 0.05, 0.1, 0.2};
    double previous = -1.0;
    for (int s = 0; s < 6; ++s) {
        double m = mean_flip_with_noise(ref, noise, sigma[s]);
        printf("  sigma %.2f: mean FLIP %.5f\n", sigma[s], m);
        CHECK_MSG(m > previous, "sigma %g: %g not above %g", sigma[s], m, previous);
        previous = m;
    }
    free(noise);
    for (int c = 0; c < 3; ++c)
        free(ref[c]);
}

/* ---- HDR -------------------------------------------------------------- */

/* Narkowicz's ACES fit with the 0.6 pre-exposure, written out. */
static double aces(double x)
{
    double y = (0.36 * 2.51 * x * x + 0.018 * x) / (0.36 * 2.43 * x * x + 0.354 * x + 0.14);
    return y < 0.0 ? 0.0 : y > 1.0 ? 1.0 : y;
}

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The HDR paper's start and stop exposures for a grey reference. */
static void hand_exposures(const float *ref, double *start, double *stop, int *count)
{
    double *y = malloc(sizeof(double) * N);
    for (size_t i = 0; i < N; ++i)
        y[i] = ref[i]; /* 0.2126 + 0.7152 + 0.0722 = 1 */
    qsort(y, N, sizeof *y, compare_double);
    double lo = 0.0, hi = 100.0; /* x_t: bisect aces(x) = 0.85 */
    for (int k = 0; k < 200; ++k)
        aces(0.5 * (lo + hi)) < 0.85 ? (lo = 0.5 * (lo + hi)) : (hi = 0.5 * (lo + hi));
    double median = 0.5 * (y[N / 2 - 1] + y[N / 2]); /* N is even */
    *start = log2(lo / y[N - 1]);
    *stop = log2(lo / median);
    *count = (int)fmax(2.0, ceil(*stop - *start));
    free(y);
}

/* A grey HDR pair: a ramp from 0.01 to 20 and a noisy copy. */
static void hdr_pair(float *ref, float *test)
{
    rng_state = 0x9E3779B97F4A7C15ull;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            size_t i = (size_t)y * W + (size_t)x;
            ref[i] = (float)(0.01 * pow(2000.0, (double)(x + W * y) / (double)N));
            test[i] = ref[i] * (float)(1.0 + 0.2 * (uniform01() - 0.5));
        }
}

static void test_hdr_exposures_and_maximum(void)
{
    printf("HDR-FLIP\n");
    float *ref = malloc(sizeof(float) * N), *test = malloc(sizeof(float) * N);
    hdr_pair(ref, test);
    flip_image ir = {W, H, {ref, ref, ref}}, it = {W, H, {test, test, test}};
    flip_exposures x = flip_exposure_range(&ir, NULL);
    double start, stop;
    int count;
    hand_exposures(ref, &start, &stop, &count);
    printf("  exposures %.4f .. %.4f, %d (independently %.4f .. %.4f, %d)\n", x.start, x.stop, x.count, start, stop,
           count);
    CHECK_NEAR(x.start, start, 1e-6);
    CHECK_NEAR(x.stop, stop, 1e-6);
    CHECK(x.count == count && count > 2);
    CHECK_NEAR(flip_tone_map(flip_tone_map_inverse(0.85)), 0.85, 1e-12);

    float *hdr = malloc(sizeof(float) * N), *ldr = malloc(sizeof(float) * N), *maximum = calloc(N, sizeof(float));
    float *tr = malloc(sizeof(float) * N), *tt = malloc(sizeof(float) * N);
    gt_error e;
    CHECK(flip_hdr(&ir, &it, x, FLIP_DEFAULT_PPD, "hdr", hdr, &e) == 0);
    for (int k = 0; k < count; ++k) {
        double scale = exp2(start + k * (stop - start) / (count - 1));
        for (size_t i = 0; i < N; ++i)
            tr[i] = (float)aces(scale * ref[i]), tt[i] = (float)aces(scale * test[i]);
        flip_image a = {W, H, {tr, tr, tr}}, b = {W, H, {tt, tt, tt}};
        CHECK(flip_ldr(&a, &b, FLIP_DEFAULT_PPD, "ldr", ldr, &e) == 0);
        for (size_t i = 0; i < N; ++i)
            maximum[i] = fmaxf(maximum[i], ldr[i]);
    }
    double worst = 0.0;
    int in_range = 1;
    for (size_t i = 0; i < N; ++i) {
        worst = fmax(worst, fabs((double)hdr[i] - maximum[i]));
        in_range &= hdr[i] >= 0.0f && hdr[i] <= 1.0f;
    }
    printf("  HDR-FLIP minus the maximum of LDR-FLIP over the exposures: at most %.2e\n", worst);
    CHECK(worst < 1e-5);
    CHECK(in_range);
    free(hdr), free(ldr), free(maximum), free(tr), free(tt), free(ref), free(test);
}

/* An LDR pair through HDR-FLIP: what holds is what the rule gives, LDR-FLIP
 * of the tone-mapped pair maximised over exposures. So the values stay in
 * LDR-FLIP's range [0, 1], and HDR-FLIP is at least the LDR-FLIP of the pair
 * tone mapped at the start exposure (where the reference's brightest pixel
 * maps to 0.85); scaling both images by 4 shifts the exposures by -2 and
 * changes no value (beyond rounding). */
static void test_hdr_of_ldr_pair(void)
{
    printf("HDR-FLIP of an LDR pair\n");
    float *ref[3], *test[3], *ref4[3], *test4[3];
    for (int c = 0; c < 3; ++c)
        ref[c] = malloc(sizeof(float) * N), test[c] = malloc(sizeof(float) * N), ref4[c] = malloc(sizeof(float) * N),
        test4[c] = malloc(sizeof(float) * N);
    structured_image(ref);
    rng_state = 0x1234567ull;
    for (int c = 0; c < 3; ++c)
        for (size_t i = 0; i < N; ++i) {
            test[c][i] = fminf(1.0f, fmaxf(0.0f, ref[c][i] + (float)(0.1 * (uniform01() - 0.5))));
            ref4[c][i] = 4.0f * ref[c][i], test4[c][i] = 4.0f * test[c][i];
        }
    flip_image ir = image_of(ref), it = image_of(test), ir4 = image_of(ref4), it4 = image_of(test4);
    flip_exposures x = flip_exposure_range(&ir, NULL), x4 = flip_exposure_range(&ir4, NULL);
    CHECK_NEAR(x4.start, x.start - 2.0, 1e-9);
    CHECK_NEAR(x4.stop, x.stop - 2.0, 1e-9);
    CHECK(x4.count == x.count);
    float *hdr = malloc(sizeof(float) * N), *hdr4 = malloc(sizeof(float) * N), *first = malloc(sizeof(float) * N);
    gt_error e;
    CHECK(flip_hdr(&ir, &it, x, FLIP_DEFAULT_PPD, "ldr pair", hdr, &e) == 0);
    CHECK(flip_hdr(&ir4, &it4, x4, FLIP_DEFAULT_PPD, "ldr pair x4", hdr4, &e) == 0);
    flip_exposures only_start = {x.start, x.start, 1};
    CHECK(flip_hdr(&ir, &it, only_start, FLIP_DEFAULT_PPD, "start", first, &e) == 0);
    double shift = 0.0;
    int ok = 1;
    for (size_t i = 0; i < N; ++i) {
        shift = fmax(shift, fabs((double)hdr[i] - hdr4[i]));
        ok &= hdr[i] >= 0.0f && hdr[i] <= 1.0f && hdr[i] >= first[i];
    }
    printf("  exposures %.3f .. %.3f (%d); scaled by 4: largest change %.2e; mean HDR %.4f, at start %.4f\n",
           x.start, x.stop, x.count, shift, flip_mean(hdr, NULL, N), flip_mean(first, NULL, N));
    CHECK(ok);
    CHECK(shift < 1e-4);
    free(hdr), free(hdr4), free(first);
    for (int c = 0; c < 3; ++c)
        free(ref[c]), free(test[c]), free(ref4[c]), free(test4[c]);
}

static void test_threads_and_grey(void)
{
    printf("threads and the grey figure\n");
    float *ref = malloc(sizeof(float) * N), *test = malloc(sizeof(float) * N), *mask = malloc(sizeof(float) * N);
    float *m1 = malloc(sizeof(float) * N), *m2 = malloc(sizeof(float) * N);
    hdr_pair(ref, test);
    for (size_t i = 0; i < N; ++i)
        mask[i] = (i % 7) != 0;
    flip_result r1, r2;
    gt_error e;
    omp_set_num_threads(1);
    CHECK(flip_grey(ref, test, mask, W, H, "grey", m1, &r1, &e) == 0);
    omp_set_num_threads(2);
    CHECK(flip_grey(ref, test, mask, W, H, "grey", m2, &r2, &e) == 0);
    CHECK(memcmp(m1, m2, sizeof(float) * N) == 0);
    CHECK(r1.hdr == 1 && r1.mean == r2.mean);
    CHECK_NEAR(r1.mean, flip_mean(m1, mask, N), 0.0);
    for (size_t i = 0; i < N; ++i)
        ref[i] = fminf(ref[i], 1.0f), test[i] = fminf(test[i], 1.0f);
    CHECK(flip_grey(ref, test, mask, W, H, "grey", NULL, &r1, &e) == 0 && r1.hdr == 0 && r1.mean > 0.0);
    float wrong_size = 0.0f;
    flip_image a = {W, H, {ref, ref, ref}}, b = {1, 1, {&wrong_size, &wrong_size, &wrong_size}};
    CHECK(flip_ldr(&a, &b, FLIP_DEFAULT_PPD, "sizes", m1, &e) != 0 && strstr(e.message, "sizes"));
    free(ref), free(test), free(mask), free(m1), free(m2);
}

int main(void)
{
    test_identical();
    test_constant_pairs();
    test_noise_monotone();
    test_hdr_exposures_and_maximum();
    test_hdr_of_ldr_pair();
    test_threads_and_grey();
    return check_report("metrics_flip");
}
