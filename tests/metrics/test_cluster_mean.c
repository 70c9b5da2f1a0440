/* Block-clustered means (metrics/cluster_mean.h) against closed forms: a
 * constant, independent pixels (se = sigma / sqrt(N)), whole blocks sharing
 * one value (se = sigma / sqrt(B): the per-pixel formula would be 8x too
 * small), the paired squared-error identity, pooling, and a change's mean
 * |a - b| and share of 8-bit codes changed. */
#include <math.h>
#include <stdlib.h>

#include "metrics/cluster_mean.h"
#include "tests/check.h"
#include "tests/test_noise.h"

enum { W = 256, H = 128 };

static void test_constant(void)
{
    float *x = malloc(sizeof *x * W * H);
    for (int i = 0; i < W * H; ++i)
        x[i] = 0.25f;
    cluster_mean m;
    CHECK(cluster_mean_compute(x, NULL, W, H, 8, &m) == 0);
    CHECK_NEAR(m.mean, 0.25, 1e-12);
    CHECK(m.se == 0.0);
    CHECK(m.pixels == (size_t)W * H && m.blocks == (W / 8) * (H / 8));
    float mask[4] = {0, 0, 0, 0};
    CHECK(cluster_mean_compute(x, mask, 2, 2, 8, &m) != 0);
    free(x);
}

/* sigma = 1: iid pixels, then one value per 8x8 block. The estimate of a
 * standard error from B blocks has relative spread 1/sqrt(2 (B - 1)): 2.2%
 * for 512 blocks; 5 of them allowed. */
static void test_correlation(void)
{
    float *x = malloc(sizeof *x * W * H);
    for (int i = 0; i < W * H; ++i)
        x[i] = (float)gaussian(11, (uint64_t)i);
    cluster_mean m;
    cluster_mean_compute(x, NULL, W, H, 8, &m);
    CHECK_NEAR(m.se / (1.0 / sqrt((double)W * H)), 1.0, 0.11);
    for (int y = 0; y < H; ++y)
        for (int i = 0; i < W; ++i)
            x[y * W + i] = (float)gaussian(12, (uint64_t)((y / 8) * (W / 8) + i / 8));
    cluster_mean_compute(x, NULL, W, H, 8, &m);
    CHECK_NEAR(m.se / (1.0 / sqrt((double)(W / 8) * (H / 8))), 1.0, 0.11);
    free(x);
}

static void test_paired_and_pool(void)
{
    float *a = malloc(sizeof *a * W * H), *b = malloc(sizeof *b * W * H), *r = malloc(sizeof *r * W * H);
    double expected = 0.0;
    for (int i = 0; i < W * H; ++i) {
        r[i] = (float)uniform01((uint64_t)i);
        a[i] = r[i] + 0.1f;
        b[i] = r[i] - 0.2f;
        expected += ((double)a[i] - r[i]) * ((double)a[i] - r[i]) - ((double)b[i] - r[i]) * ((double)b[i] - r[i]);
    }
    cluster_mean m;
    CHECK(cluster_mean_paired_sq_error(a, b, r, NULL, W, H, 8, &m) == 0);
    CHECK_NEAR(m.mean, expected / (W * H), 1e-6);
    CHECK_NEAR(m.mean, 0.01 - 0.04, 1e-5);
    cluster_mean parts[2] = {{1.0, 0.3, 100, 4}, {4.0, 0.1, 300, 12}}, p = cluster_mean_pool(parts, 2);
    CHECK_NEAR(p.mean, (100.0 * 1.0 + 300.0 * 4.0) / 400.0, 1e-12);
    CHECK_NEAR(p.se, sqrt(30.0 * 30.0 + 30.0 * 30.0) / 400.0, 1e-12);
    CHECK(p.pixels == 400 && p.blocks == 16);
    free(a);
    free(b);
    free(r);
}

/* a - b = 0.3 everywhere; codes k/255 moved by 0.4 (kept) or 0.6 (changed)
 * of a code value on alternate pixels: half change. */
static void test_change(void)
{
    float *a = malloc(sizeof *a * W * H), *b = malloc(sizeof *b * W * H);
    for (int i = 0; i < W * H; ++i) {
        a[i] = (float)uniform01((uint64_t)i);
        b[i] = a[i] - 0.3f;
    }
    cluster_mean m;
    CHECK(cluster_mean_abs_difference(a, b, NULL, W, H, 8, &m) == 0);
    CHECK_NEAR(m.mean, 0.3, 1e-6);
    CHECK(cluster_mean_difference(b, a, NULL, W, H, 8, &m) == 0);
    CHECK_NEAR(m.mean, -0.3, 1e-6);
    for (int i = 0; i < W * H; ++i) {
        a[i] = (float)(i % 254) / 255.0f;
        b[i] = a[i] + (i % 2 ? 0.6f : 0.4f) / 255.0f;
    }
    CHECK(cluster_mean_code_changes(a, b, NULL, W, H, 8, &m) == 0);
    CHECK_NEAR(m.mean, 0.5, 1e-12);
    CHECK(m.se == 0.0); /* every 8x8 block holds 32 of each */
    CHECK(unorm8_code(-0.3f) == 0 && unorm8_code(1.7f) == 255 && unorm8_code(0.1f) == 26);
    free(a);
    free(b);
}

int main(void)
{
    test_change();
    test_constant();
    test_correlation();
    test_paired_and_pool();
    return check_report("test_cluster_mean");
}
