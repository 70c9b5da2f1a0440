/* FXAA 3.11 (anti_aliasing/fxaa.h) against what it must do:
 * - a constant image comes back unchanged (no pixel passes the edge test);
 * - every output is a convex combination of input texels: within the
 *   input's range per channel, on a random image;
 * - a pixel whose 3 x 3 neighbourhood is constant is returned exactly;
 * - on a vertical step edge it changes only the two columns beside the step,
 *   and blends them towards each other (a horizontal search along a straight
 *   edge finds no end: the shift is the subpixel term);
 * - the output does not depend on the thread count. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "anti_aliasing/fxaa.h"
#include "tests/check.h"

enum { W = 40, H = 32 };

static void check_constant(const fxaa_settings *s)
{
    static float in[3 * W * H], out[3 * W * H];
    for (int k = 0; k < 3 * W * H; ++k)
        in[k] = 0.37f + 0.1f * (k % 3);
    CHECK(fxaa_apply(s, in, W, H, 2, out) == 0);
    CHECK(memcmp(in, out, sizeof in) == 0);
}

static void check_random(const fxaa_settings *s)
{
    static float in[3 * W * H], out1[3 * W * H], out2[3 * W * H];
    unsigned long long r = 1;
    float lo[3] = {1, 1, 1}, hi[3] = {0, 0, 0};
    for (int k = 0; k < 3 * W * H; ++k) {
        r = r * 6364136223846793005ull + 1442695040888963407ull;
        in[k] = (float)((r >> 11) * 0x1.0p-53);
        lo[k % 3] = fminf(lo[k % 3], in[k]);
        hi[k % 3] = fmaxf(hi[k % 3], in[k]);
    }
    CHECK(fxaa_apply(s, in, W, H, 1, out1) == 0 && fxaa_apply(s, in, W, H, 2, out2) == 0);
    CHECK(memcmp(out1, out2, sizeof out1) == 0);
    int inside = 1;
    for (int k = 0; k < 3 * W * H; ++k)
        inside &= out1[k] >= lo[k % 3] - 1e-6f && out1[k] <= hi[k % 3] + 1e-6f;
    CHECK(inside);
}

static void check_step(const fxaa_settings *s)
{
    static float in[3 * W * H], out[3 * W * H];
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i)
            for (int c = 0; c < 3; ++c)
                in[3 * (j * W + i) + c] = i < W / 2 ? 0.1f : 0.9f;
    CHECK(fxaa_apply(s, in, W, H, 2, out) == 0);
    int far_unchanged = 1, blended = 1;
    for (int j = 2; j < H - 2; ++j)
        for (int i = 0; i < W; ++i) {
            float a = in[3 * (j * W + i)], b = out[3 * (j * W + i)];
            if (i < W / 2 - 1 || i > W / 2)
                far_unchanged &= a == b;
            else
                blended &= i == W / 2 - 1 ? (b >= a && b < 0.5f) : (b <= a && b > 0.5f);
        }
    CHECK(far_unchanged);
    CHECK(blended);
}

int main(void)
{
    fxaa_settings s = fxaa_default_settings();
    check_constant(&s);
    check_random(&s);
    check_step(&s);
    return check_report("test_fxaa");
}
