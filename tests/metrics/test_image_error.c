/* Error statistics of known differences, masks, percentiles, and the set-up
 * of a comparison of two images (sizes, channels, masks, bad values). */
#include <math.h>
#include <string.h>

#include "metrics/image_error.h"
#include "metrics/image_pair.h"
#include "tests/check.h"

/* Differences a - b over 6 pixels: 3, -4, 0, 1, -1, 0 (a 3x2 image). */
static const float A6[6] = {3.0f, 0.0f, 2.0f, 1.5f, 0.0f, 7.0f};
static const float B6[6] = {0.0f, 4.0f, 2.0f, 0.5f, 1.0f, 7.0f};

static void test_known_differences(void)
{
    image_error_stats s;
    gt_error e;
    CHECK(image_error_compute(A6, B6, NULL, 3, 2, "t", &s, &e) == 0);
    CHECK(s.pixels == 6);
    CHECK_NEAR(s.rmse, sqrt((9.0 + 16.0 + 0.0 + 1.0 + 1.0 + 0.0) / 6.0), 1e-15);
    CHECK_NEAR(s.mean_abs, 9.0 / 6.0, 1e-15);
    CHECK(s.max_abs == 4.0 && s.max_x == 1 && s.max_y == 0);
    CHECK_NEAR(s.mean_a, 13.5 / 6.0, 1e-15);
    CHECK_NEAR(s.mean_b, 14.5 / 6.0, 1e-15);

    /* Ties: the first pixel in row-major order. */
    const float a[4] = {0, 2, 0, 0}, b[4] = {0, 0, 0, -2};
    CHECK(image_error_compute(a, b, NULL, 2, 2, "t", &s, &e) == 0);
    CHECK(s.max_abs == 2.0 && s.max_x == 1 && s.max_y == 0);

    CHECK(image_error_compute(A6, A6, NULL, 3, 2, "t", &s, &e) == 0);
    CHECK(s.rmse == 0.0 && s.mean_abs == 0.0 && s.max_abs == 0.0);
}

/* Pixels outside the mask change nothing, however wrong they are. */
static void test_mask(void)
{
    const float mask[6] = {0.0f, 1.0f, 1.0f, 0.49f, 0.5f, 1.0f}; /* inside: pixels 1, 2, 4, 5 */
    float a[6], b[6];
    memcpy(a, A6, sizeof a);
    memcpy(b, B6, sizeof b);
    image_error_stats s1, s2;
    gt_error e;
    CHECK(image_error_compute(a, b, mask, 3, 2, "t", &s1, &e) == 0);
    a[0] = 1e6f;
    b[3] = -1e6f;
    CHECK(image_error_compute(a, b, mask, 3, 2, "t", &s2, &e) == 0);
    CHECK(s1.pixels == 4 && s2.pixels == 4);
    CHECK(memcmp(&s1, &s2, sizeof s1) == 0);
    CHECK_NEAR(s2.rmse, sqrt((16.0 + 0.0 + 1.0 + 0.0) / 4.0), 1e-15);
    CHECK_NEAR(s2.mean_abs, 5.0 / 4.0, 1e-15);
    CHECK(s2.max_abs == 4.0 && s2.max_x == 1 && s2.max_y == 0);
    CHECK_NEAR(s2.mean_a, 9.0 / 4.0, 1e-15);

    const float empty[6] = {0};
    CHECK(image_error_compute(a, b, empty, 3, 2, "x.exr", &s1, &e) == -1);
    CHECK(strcmp(e.message, "x.exr: no pixel to compare: the mask is empty") == 0);
}

static void test_percentile(void)
{
    float v[100], mask[100];
    for (int i = 0; i < 100; ++i) {
        v[i] = (float)((i * 37) % 100 + 1); /* 1..100, shuffled */
        mask[i] = v[i] <= 90.0f ? 1.0f : 0.0f;
    }
    float p;
    gt_error e;
    CHECK(metrics_percentile(v, NULL, 100, 99.0, "t", &p, &e) == 0 && p == 99.0f);
    CHECK(metrics_percentile(v, NULL, 100, 100.0, "t", &p, &e) == 0 && p == 100.0f);
    CHECK(metrics_percentile(v, NULL, 100, 50.0, "t", &p, &e) == 0 && p == 50.0f);
    CHECK(metrics_percentile(v, NULL, 100, 0.5, "t", &p, &e) == 0 && p == 1.0f);
    /* 90 values: the ceil(89.1) = 90th smallest. */
    CHECK(metrics_percentile(v, mask, 100, 99.0, "t", &p, &e) == 0 && p == 90.0f);
    /* NaN values (an SSIM map's border) are left out. */
    for (int i = 0; i < 100; ++i)
        if (v[i] > 98.0f)
            v[i] = NAN;
    CHECK(metrics_percentile(v, NULL, 100, 100.0, "t", &p, &e) == 0 && p == 98.0f);
    CHECK(metrics_percentile(v, NULL, 100, 0.0, "t", &p, &e) == -1);
    const float empty[100] = {0};
    CHECK(metrics_percentile(v, empty, 100, 99.0, "t", &p, &e) == -1);
}

/* An image with the named channels, channel c filled with c + 1. */
static void make_image(image *img, int w, int h, const char *const *names, int count)
{
    CHECK(image_init(img, w, h) == 0);
    for (int c = 0; c < count; ++c) {
        float *d = image_add_channel(img, names[c]);
        for (int i = 0; i < w * h; ++i)
            d[i] = (float)(c + 1);
    }
}

static void test_pair_channels(void)
{
    const char *const names_a[] = {"depth.Z", "ao.V", "multibounce.V"};
    const char *const names_b[] = {"multibounce.V", "specocc.V"};
    image a, b;
    make_image(&a, 12, 12, names_a, 3);
    make_image(&b, 12, 12, names_b, 2);
    metrics_pair pair;
    gt_error e;

    /* ao.V is only in a: the first default present in both is multibounce.V. */
    CHECK(metrics_pair_init(&pair, &a, "a.exr", &b, "b.exr", NULL, &e) == 0);
    CHECK(strcmp(pair.channel, "multibounce.V") == 0);
    CHECK(pair.a == image_channel_data(&a, "multibounce.V") && pair.b == image_channel_data(&b, "multibounce.V"));
    CHECK(pair.width == 12 && pair.height == 12);
    metrics_pair_free(&pair);

    CHECK(metrics_pair_init(&pair, &a, "a.exr", &b, "b.exr", "depth.Z", &e) == -1);
    CHECK(strcmp(e.message, "b.exr: no channel depth.Z (channels: multibounce.V, specocc.V)") == 0);
    CHECK(metrics_pair_init(&pair, &a, "a.exr", &b, "b.exr", "specocc.V", &e) == -1);
    CHECK(strcmp(e.message, "a.exr: no channel specocc.V (channels: depth.Z, ao.V, multibounce.V)") == 0);

    image c;
    const char *const names_c[] = {"N.X", "ao.V"};
    make_image(&c, 12, 12, names_c, 2);
    CHECK(metrics_pair_init(&pair, &b, "b.exr", &c, "c.exr", NULL, &e) == -1);
    CHECK(strcmp(e.message, "c.exr: no channel multibounce.V to compare with b.exr (channels: N.X, ao.V); name one "
                            "with --channel") == 0);
    const char *const names_g[] = {"depth.Z", "mask.A"};
    image g;
    make_image(&g, 12, 12, names_g, 2);
    CHECK(metrics_pair_init(&pair, &g, "g.exr", &a, "a.exr", NULL, &e) == -1);
    CHECK(strcmp(e.message, "g.exr: none of the default channels (ao.V, multibounce.V, specocc.V, ao.Vuniform) is "
                            "here (channels: depth.Z, mask.A); name one with --channel") == 0);
    image_free(&g);
    image_free(&c);

    /* A long channel list is cut with "..." and the message stays whole. */
    image many;
    CHECK(image_init(&many, 12, 12) == 0);
    for (int i = 0; i < 100; ++i) {
        char name[IMAGE_NAME_MAX];
        snprintf(name, sizeof name, "a_rather_long_layer_name_%02d.X", i);
        CHECK(image_add_channel(&many, name) != NULL);
    }
    CHECK(metrics_pair_init(&pair, &a, "a.exr", &many, "many.exr", "ao.V", &e) == -1);
    const char *tail = "a_rather_long_layer_name_19.X, ...)";
    CHECK(strstr(e.message, "many.exr: no channel ao.V (channels: a_rather_long_layer_name_00.X, ") == e.message);
    CHECK(strlen(e.message) > strlen(tail) &&
          strcmp(e.message + strlen(e.message) - strlen(tail), tail) == 0);
    image_free(&many);

    image d;
    make_image(&d, 12, 13, names_a, 3);
    CHECK(metrics_pair_init(&pair, &a, "a.exr", &d, "d.exr", NULL, &e) == -1);
    CHECK(strcmp(e.message, "d.exr: size 12x13 differs from a.exr's 12x12") == 0);
    image_free(&d);

    image_channel_data(&b, "multibounce.V")[3 * 12 + 2] = NAN;
    CHECK(metrics_pair_init(&pair, &a, "a.exr", &b, "b.exr", NULL, &e) == -1);
    CHECK(strcmp(e.message, "b.exr: channel multibounce.V holds nan at pixel (2, 3)") == 0);
    image_channel_data(&a, "multibounce.V")[0] = -INFINITY;
    CHECK(metrics_pair_init(&pair, &a, "a.exr", &b, "b.exr", NULL, &e) == -1);
    CHECK(strcmp(e.message, "a.exr: channel multibounce.V holds -inf at pixel (0, 0)") == 0);

    image_free(&a);
    image_free(&b);
}

/* The compared pixels are those inside both images' mask.A; no mask.A = all. */
static void test_pair_masks(void)
{
    const char *const names[] = {"ao.V", "mask.A"};
    image a, b, plain;
    make_image(&a, 12, 11, names, 2);
    make_image(&b, 12, 11, names, 2);
    make_image(&plain, 12, 11, names, 1);
    float *ma = image_channel_data(&a, "mask.A"), *mb = image_channel_data(&b, "mask.A");
    for (int y = 0; y < 11; ++y)
        for (int x = 0; x < 12; ++x) {
            ma[y * 12 + x] = x < 6 ? 1.0f : 0.0f; /* left half */
            mb[y * 12 + x] = y < 4 ? 1.0f : 0.3f; /* top rows; 0.3 counts as outside */
        }
    metrics_pair pair;
    gt_error e;
    CHECK(metrics_pair_init(&pair, &a, "a.exr", &b, "b.exr", NULL, &e) == 0);
    int agree = 1;
    for (int y = 0; y < 11; ++y)
        for (int x = 0; x < 12; ++x)
            agree &= pair.mask[y * 12 + x] == (x < 6 && y < 4 ? 1.0f : 0.0f);
    CHECK(agree);
    metrics_pair_free(&pair);

    CHECK(metrics_pair_init(&pair, &plain, "p.exr", &a, "a.exr", NULL, &e) == 0);
    CHECK(memcmp(pair.mask, ma, sizeof(float) * 12 * 11) == 0);
    metrics_pair_free(&pair);

    CHECK(metrics_pair_init(&pair, &plain, "p.exr", &plain, "p.exr", NULL, &e) == 0);
    int all = 1;
    for (int i = 0; i < 12 * 11; ++i)
        all &= pair.mask[i] == 1.0f;
    CHECK(all);
    metrics_pair_free(&pair);

    image_free(&a);
    image_free(&b);
    image_free(&plain);
}

int main(void)
{
    test_known_differences();
    test_mask();
    test_percentile();
    test_pair_channels();
    test_pair_masks();
    return check_report("metrics_image_error");
}
