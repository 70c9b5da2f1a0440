/* SSIM against the paper's definition computed independently here (the 2-D
 * Gaussian window written out, two-pass variances), against closed forms that
 * need no window weights at all, and its exact properties: identical images
 * give 1, swapping images changes nothing, the thread count changes nothing. */
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <string.h>

#include "metrics/ssim.h"
#include "tests/check.h"

static const double C1 = 0.01 * 0.01, C2 = 0.03 * 0.03;

/* SSIM of the 11x11 window centred at (cx, cy), written from Wang et al.
 * 2004 without the library: 2-D weights exp(-r^2 / (2 * 1.5^2)) normalised
 * over the window, weighted means, then population variances and covariance
 * as weighted means of centred products. */
static double hand_ssim(const float *a, const float *b, int width, int cx, int cy)
{
    double w[11][11], total = 0.0;
    for (int j = 0; j < 11; ++j)
        for (int i = 0; i < 11; ++i) {
            double dx = i - 5, dy = j - 5;
            w[j][i] = exp(-(dx * dx + dy * dy) / (2.0 * 1.5 * 1.5));
            total += w[j][i];
        }
    double mu_a = 0.0, mu_b = 0.0;
    for (int j = 0; j < 11; ++j)
        for (int i = 0; i < 11; ++i) {
            size_t p = (size_t)(cy - 5 + j) * (size_t)width + (size_t)(cx - 5 + i);
            mu_a += w[j][i] / total * a[p];
            mu_b += w[j][i] / total * b[p];
        }
    double var_a = 0.0, var_b = 0.0, cov = 0.0;
    for (int j = 0; j < 11; ++j)
        for (int i = 0; i < 11; ++i) {
            size_t p = (size_t)(cy - 5 + j) * (size_t)width + (size_t)(cx - 5 + i);
            double da = a[p] - mu_a, db = b[p] - mu_b;
            var_a += w[j][i] / total * da * da;
            var_b += w[j][i] / total * db * db;
            cov += w[j][i] / total * da * db;
        }
    return (2 * mu_a * mu_b + C1) * (2 * cov + C2) / ((mu_a * mu_a + mu_b * mu_b + C1) * (var_a + var_b + C2));
}

static uint64_t rng_state = 0x9E3779B97F4A7C15ull;
static double uniform01(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (double)(rng_state >> 11) * 0x1.0p-53;
}

/* b: a correlated but different image (a blurred-ish copy plus noise and an offset). */
static void random_pair(float *a, float *b, size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        a[i] = (float)uniform01();
        b[i] = (float)(0.6 * a[i] + 0.3 * uniform01() + 0.05);
    }
}

static void test_weights(void)
{
    double g[SSIM_WINDOW], sum = 0.0;
    ssim_gaussian_weights(g);
    for (int k = 0; k < SSIM_WINDOW; ++k) {
        sum += g[k];
        CHECK_NEAR(g[k] / g[5], exp(-(k - 5) * (k - 5) / 4.5), 1e-15);
    }
    CHECK_NEAR(sum, 1.0, 1e-15);
}

static void test_single_window(void)
{
    float a[121], b[121], map[121];
    random_pair(a, b, 121);
    ssim_result r;
    gt_error e;
    CHECK(ssim_compute(a, b, NULL, 11, 11, "t", map, &r, &e) == 0);
    double expected = hand_ssim(a, b, 11, 5, 5);
    CHECK(expected < 0.99 && expected > 0.1); /* a case where the terms matter */
    CHECK_NEAR(r.ssim, expected, 1e-12);
    CHECK_NEAR(r.dssim, (1.0 - expected) / 2.0, 1e-12);
    CHECK(r.centres == 1);
    CHECK_NEAR(map[5 * 11 + 5], expected, 1e-7);
    int nan_elsewhere = 1;
    for (int i = 0; i < 121; ++i)
        if (i != 5 * 11 + 5 && !isnan(map[i]))
            nan_elsewhere = 0;
    CHECK(nan_elsewhere);
}

/* Every valid centre of a non-square image, against the hand computation;
 * the mean over a mask against the hand average over the same centres. */
static void test_map_and_mask(void)
{
    enum { W = 29, H = 19 };
    static float a[W * H], b[W * H], map[W * H], mask[W * H];
    random_pair(a, b, W * H);
    for (int i = 0; i < W * H; ++i)
        mask[i] = uniform01() < 0.5 ? 0.0f : 1.0f;
    mask[7 * W + 9] = 0.4f; /* below the 0.5 threshold: outside */
    mask[8 * W + 9] = 0.6f; /* inside */
    ssim_result r;
    gt_error e;
    CHECK(ssim_compute(a, b, mask, W, H, "t", map, &r, &e) == 0);
    double sum = 0.0, worst = 0.0;
    size_t count = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            int valid = x >= 5 && x < W - 5 && y >= 5 && y < H - 5;
            CHECK(valid == ssim_centre_valid(x, y, W, H));
            if (!valid) {
                CHECK(isnan(map[y * W + x]));
                continue;
            }
            double s = hand_ssim(a, b, W, x, y);
            worst = fmax(worst, fabs(map[y * W + x] - s));
            if (mask[y * W + x] >= 0.5f) {
                sum += s;
                count++;
            }
        }
    CHECK_NEAR(worst, 0.0, 1e-7); /* the map is float */
    CHECK(r.centres == count);
    CHECK_NEAR(r.ssim, sum / (double)count, 1e-12);

    /* NULL mask: every valid centre. */
    ssim_result all;
    CHECK(ssim_compute(a, b, NULL, W, H, "t", NULL, &all, &e) == 0);
    CHECK(all.centres == (size_t)(W - 10) * (H - 10));

    /* A mask covering only the border (no valid centre) is an error. */
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            mask[y * W + x] = ssim_centre_valid(x, y, W, H) ? 0.0f : 1.0f;
    CHECK(ssim_compute(a, b, mask, W, H, "t.exr", NULL, &r, &e) == -1);
    CHECK(strncmp(e.message, "t.exr: no SSIM window centre inside the mask", 44) == 0);
}

static void test_identical_and_symmetric(void)
{
    enum { W = 40, H = 31 };
    static float a[W * H], b[W * H], map_ab[W * H], map_ba[W * H];
    random_pair(a, b, W * H);
    ssim_result r, ab, ba;
    gt_error e;
    CHECK(ssim_compute(a, a, NULL, W, H, "t", NULL, &r, &e) == 0);
    CHECK(r.ssim == 1.0);
    CHECK(r.dssim == 0.0);
    CHECK(ssim_compute(a, b, NULL, W, H, "t", map_ab, &ab, &e) == 0);
    CHECK(ssim_compute(b, a, NULL, W, H, "t", map_ba, &ba, &e) == 0);
    CHECK(ab.ssim == ba.ssim);
    CHECK(memcmp(map_ab, map_ba, sizeof map_ab) == 0);
    CHECK(ab.ssim < 1.0);
}

/* Constant images: variances and covariance vanish, so
 * SSIM = (2ab + C1) / (a^2 + b^2 + C1) exactly. Values above 1 are not clamped. */
static void test_constants(void)
{
    const float pairs[][2] = {{0.3f, 0.7f}, {0.0f, 0.05f}, {2.5f, 0.1f}, {0.5f, 0.5f}};
    for (size_t k = 0; k < sizeof pairs / sizeof pairs[0]; ++k) {
        enum { W = 15, H = 13 };
        float a[W * H], b[W * H];
        for (int i = 0; i < W * H; ++i) {
            a[i] = pairs[k][0];
            b[i] = pairs[k][1];
        }
        double x = pairs[k][0], y = pairs[k][1];
        ssim_result r;
        gt_error e;
        CHECK(ssim_compute(a, b, NULL, W, H, "t", NULL, &r, &e) == 0);
        CHECK_NEAR(r.ssim, (2 * x * y + C1) / (x * x + y * y + C1), 1e-12);
    }
}

/* A = c B with B of large amplitude and point-antisymmetric about the window
 * centre: both means are 0 whatever the (symmetric) weights, and C2 is
 * negligible against the variances, so SSIM = 2c / (1 + c^2) whatever the
 * window: a check of the formula's structure term independent of the weights. */
static void test_scaled_copy(void)
{
    float b[121];
    for (int j = 0; j < 11; ++j)
        for (int i = 0; i < 11; ++i) {
            int mirror = (10 - j) * 11 + (10 - i), p = j * 11 + i;
            if (p < mirror)
                b[p] = (float)floor((uniform01() - 0.5) * 2e6);
            else if (p == mirror)
                b[p] = 0.0f;
            else
                b[p] = -b[mirror];
        }
    const double scales[] = {3.0, -1.0, 0.5, 1.0};
    for (size_t k = 0; k < sizeof scales / sizeof scales[0]; ++k) {
        float a[121];
        for (int p = 0; p < 121; ++p)
            a[p] = (float)(scales[k] * b[p]); /* exact: small integers times 3, -1, 0.5 */
        ssim_result r;
        gt_error e;
        CHECK(ssim_compute(a, b, NULL, 11, 11, "t", NULL, &r, &e) == 0);
        double c = scales[k];
        CHECK_NEAR(r.ssim, 2 * c / (1 + c * c), 1e-12);
    }
}

static void test_small_images(void)
{
    static float a[40 * 40];
    ssim_result r;
    gt_error e;
    CHECK(ssim_compute(a, a, NULL, 10, 40, "small.exr", NULL, &r, &e) == -1);
    CHECK(strcmp(e.message, "small.exr: image is 10x40, smaller than the 11x11 SSIM window") == 0);
    CHECK(ssim_compute(a, a, NULL, 40, 10, "small.exr", NULL, &r, &e) == -1);
    CHECK(ssim_compute(a, a, NULL, 11, 11, "small.exr", NULL, &r, &e) == 0);
}

static void test_thread_count(void)
{
    enum { W = 301, H = 157 };
    static float a[W * H], b[W * H], map1[W * H], map2[W * H];
    random_pair(a, b, W * H);
    ssim_result r1, r2;
    gt_error e;
    omp_set_num_threads(1);
    CHECK(ssim_compute(a, b, NULL, W, H, "t", map1, &r1, &e) == 0);
    omp_set_num_threads(3);
    CHECK(ssim_compute(a, b, NULL, W, H, "t", map2, &r2, &e) == 0);
    CHECK(r1.ssim == r2.ssim);
    CHECK(memcmp(map1, map2, sizeof map1) == 0);
}

int main(void)
{
    test_weights();
    test_single_window();
    test_map_and_mask();
    test_identical_and_symmetric();
    test_constants();
    test_scaled_copy();
    test_small_images();
    test_thread_count();
    return check_report("metrics_ssim");
}
