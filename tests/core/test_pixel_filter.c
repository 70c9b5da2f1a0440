/* Pixel filters (core/sampling/pixel_filter.h): a constant image resolves to the
 * constant with both filters (the weights are normalised, borders too); the
 * box filter is the mean of each pixel's own samples; the Blackman-Harris
 * window is 1 at the centre, 0 at its radius and symmetric, and with
 * samples at stratum centres it reproduces a linear ramp exactly at
 * interior pixels (a symmetric filter over a symmetric sample layout);
 * the result does not depend on the thread count. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/sampling/pixel_filter.h"
#include "tests/check.h"

enum { W = 12, H = 10, S = 4 };

static void layout(float *rgb, float *xy, int mode)
{
    for (int j = 0; j < H * S; ++j)
        for (int i = 0; i < W * S; ++i) {
            size_t k = (size_t)j * W * S + i;
            xy[2 * k] = (i + 0.5f) / S, xy[2 * k + 1] = (j + 0.5f) / S;
            for (int c = 0; c < 3; ++c)
                rgb[3 * k + c] = mode == 0 ? 0.25f * (c + 1) : (mode == 1 ? xy[2 * k] * 0.1f + xy[2 * k + 1] * 0.05f
                                                                         : (float)((k * 2654435761u) % 1000) / 1000.0f);
        }
}

int main(void)
{
    static float rgb[3 * W * H * S * S], xy[2 * W * H * S * S], out[3 * W * H], out2[3 * W * H];
    CHECK_NEAR(pixel_filter_weight(PIXEL_FILTER_BLACKMAN_HARRIS, 0, 0), 1.0, 1e-12);
    CHECK_NEAR(pixel_filter_weight(PIXEL_FILTER_BLACKMAN_HARRIS, 1.5, 0), 0.0, 1e-4);
    CHECK_NEAR(pixel_filter_weight(PIXEL_FILTER_BLACKMAN_HARRIS, 0.7, -0.3),
               pixel_filter_weight(PIXEL_FILTER_BLACKMAN_HARRIS, -0.7, 0.3), 1e-15);
    layout(rgb, xy, 0);
    for (int f = 0; f < PIXEL_FILTER_COUNT; ++f) {
        pixel_filter_resolve((pixel_filter)f, rgb, xy, W, H, S, 2, out);
        int constant = 1;
        for (int k = 0; k < 3 * W * H; ++k)
            constant &= fabsf(out[k] - 0.25f * (k % 3 + 1)) < 1e-6f;
        CHECK(constant);
    }
    layout(rgb, xy, 1);
    pixel_filter_resolve(PIXEL_FILTER_BLACKMAN_HARRIS, rgb, xy, W, H, S, 2, out);
    for (int j = 2; j < H - 2; ++j)
        for (int i = 2; i < W - 2; ++i)
            CHECK_NEAR(out[3 * (j * W + i)], (i + 0.5) * 0.1 + (j + 0.5) * 0.05, 1e-5);
    layout(rgb, xy, 2);
    pixel_filter_resolve(PIXEL_FILTER_BOX, rgb, xy, W, H, S, 1, out);
    double mean = 0.0;
    for (int sj = 0; sj < S; ++sj)
        for (int si = 0; si < S; ++si)
            mean += rgb[3 * ((size_t)(3 * S + sj) * W * S + (5 * S + si))];
    CHECK_NEAR(out[3 * (3 * W + 5)], mean / (S * S), 1e-6);
    pixel_filter_resolve(PIXEL_FILTER_BLACKMAN_HARRIS, rgb, xy, W, H, S, 1, out);
    pixel_filter_resolve(PIXEL_FILTER_BLACKMAN_HARRIS, rgb, xy, W, H, S, 2, out2);
    CHECK(memcmp(out, out2, sizeof out) == 0);
    return check_report("test_pixel_filter");
}
