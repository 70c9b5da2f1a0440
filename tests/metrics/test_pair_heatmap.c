/* The figures and the error heatmap of an image pair (metrics/image_pair.h):
 * the figures are image_error's and ssim's, the heatmap holds |A-B| or the
 * per-window DSSIM inside the mask and 0 outside, and its full scale falls
 * back from the percentile to the maximum to 1. */
#include <math.h>
#include <string.h>

#include "metrics/image_pair.h"
#include "tests/check.h"

enum { W = 16, H = 16, N = W * H };

/* ao.V and mask.A: a gradient plus `bump` at the pixels where i % every == 0
 * (every 0: nowhere); the left column outside the mask. */
static void make_image(image *img, float bump, int every)
{
    CHECK(image_init(img, W, H) == 0);
    float *v = image_add_channel(img, "ao.V"), *m = image_add_channel(img, "mask.A");
    for (int i = 0; i < N; ++i) {
        v[i] = 0.25f + 0.5f * (float)i / N + (every && i % every == 0 ? bump : 0.0f);
        m[i] = i % W == 0 ? 0.0f : 1.0f;
    }
}

static void test_figures_are_the_metrics(void)
{
    image a, b;
    make_image(&a, 0.0f, 0);
    make_image(&b, 0.1f, 3);
    metrics_pair pair;
    metrics_pair_figures f;
    image_error_stats error;
    ssim_result ssim;
    gt_error e;
    CHECK(metrics_pair_init(&pair, &a, "a", &b, "b", NULL, &e) == 0);
    CHECK(metrics_pair_measure(&pair, &a, "a", &b, "b", 0, NULL, &f, &e) == 0);
    CHECK(image_error_compute(pair.a, pair.b, pair.mask, W, H, "a", &error, &e) == 0);
    CHECK(ssim_compute(pair.a, pair.b, pair.mask, W, H, "a", NULL, &ssim, &e) == 0);
    CHECK(f.error.pixels == error.pixels && f.error.rmse == error.rmse && f.error.max_abs == error.max_abs);
    CHECK(f.ssim.ssim == ssim.ssim && f.ssim.centres == ssim.centres);
    flip_result flip; /* the figures' FLIP is flip_grey's, a the reference */
    CHECK(flip_grey(pair.a, pair.b, pair.mask, W, H, "a", NULL, &flip, &e) == 0);
    CHECK(f.flip.mean == flip.mean && f.flip.hdr == flip.hdr && f.flip.mean > 0.0 && f.flip.mean <= 1.0);
    CHECK(!f.has_floor_a && !f.has_floor_b);
    CHECK(!metrics_is_reference_of(&a, "ao.V"));
    CHECK(image_add_channel(&a, "ao.V.sum") != NULL);
    CHECK(metrics_is_reference_of(&a, "ao.V"));
    metrics_pair_free(&pair);
    image_free(&a);
    image_free(&b);
}

/* |A-B| inside the mask, 0 outside; full scale the 99th percentile. */
static void test_abs_heatmap(void)
{
    image a, b;
    make_image(&a, 0.0f, 0);
    make_image(&b, 0.1f, 3);
    metrics_pair pair;
    metrics_heatmap h;
    gt_error e;
    CHECK(metrics_pair_init(&pair, &a, "a", &b, "b", NULL, &e) == 0);
    CHECK(metrics_pair_heatmap(&pair, NULL, 99.0, "h.png", &h, &e) == 0);
    for (int i = 0; i < N; ++i) {
        CHECK(h.mask[i] == pair.mask[i]);
        CHECK(h.values[i] == (pair.mask[i] != 0.0f ? (float)fabs((double)pair.a[i] - (double)pair.b[i]) : 0.0f));
    }
    float p99;
    CHECK(metrics_percentile(h.values, h.mask, N, 99.0, "h", &p99, &e) == 0);
    CHECK(h.scale == HEATMAP_SCALE_PERCENTILE && h.vmax == p99 && h.vmax > 0.0f);
    metrics_heatmap_free(&h);
    metrics_pair_free(&pair);
    image_free(&b);

    /* One differing pixel: the 99th percentile is 0, the maximum is the scale. */
    make_image(&b, 0.5f, N - 1);
    CHECK(metrics_pair_init(&pair, &a, "a", &b, "b", NULL, &e) == 0);
    CHECK(metrics_pair_heatmap(&pair, NULL, 99.0, "h.png", &h, &e) == 0);
    CHECK(h.scale == HEATMAP_SCALE_MAXIMUM);
    CHECK_NEAR(h.vmax, 0.5, 1e-6);
    metrics_heatmap_free(&h);
    metrics_pair_free(&pair);

    /* No difference at all: an arbitrary scale of 1. */
    CHECK(metrics_pair_init(&pair, &a, "a", &a, "a", NULL, &e) == 0);
    CHECK(metrics_pair_heatmap(&pair, NULL, 99.0, "h.png", &h, &e) == 0);
    CHECK(h.scale == HEATMAP_SCALE_ARBITRARY && h.vmax == 1.0f);
    metrics_heatmap_free(&h);
    metrics_pair_free(&pair);
    image_free(&a);
    image_free(&b);
}

/* The per-window DSSIM at the valid centres inside the mask, 0 elsewhere. */
static void test_dssim_heatmap(void)
{
    image a, b;
    make_image(&a, 0.0f, 0);
    make_image(&b, 0.2f, 5);
    metrics_pair pair;
    metrics_pair_figures f;
    metrics_heatmap h;
    float ssim_map[N];
    gt_error e;
    CHECK(metrics_pair_init(&pair, &a, "a", &b, "b", NULL, &e) == 0);
    CHECK(metrics_pair_measure(&pair, &a, "a", &b, "b", 0, ssim_map, &f, &e) == 0);
    CHECK(metrics_pair_heatmap(&pair, ssim_map, 99.0, "h.png", &h, &e) == 0);
    size_t inside = 0;
    for (int i = 0; i < N; ++i) {
        int valid = pair.mask[i] != 0.0f && !isnan(ssim_map[i]);
        inside += valid;
        CHECK(h.mask[i] == (valid ? 1.0f : 0.0f));
        CHECK(h.values[i] == (valid ? (float)((1.0 - ssim_map[i]) / 2.0) : 0.0f));
    }
    CHECK(inside == f.ssim.centres && inside > 0);
    /* Centres lie 5 pixels from the borders (11x11 windows). */
    CHECK(h.mask[W * 5 + 4] == 0.0f && h.mask[W * 4 + 5] == 0.0f && h.mask[W * 5 + 5] == 1.0f);
    metrics_heatmap_free(&h);
    metrics_pair_free(&pair);
    image_free(&a);
    image_free(&b);
}

int main(void)
{
    test_figures_are_the_metrics();
    test_abs_heatmap();
    test_dssim_heatmap();
    return check_report("metrics_pair_heatmap");
}
