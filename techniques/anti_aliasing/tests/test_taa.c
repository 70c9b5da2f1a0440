/* Temporal anti-aliasing (issue 19): the talk's edge-sample pattern, the
 * techniques returning their input where the image is constant under a
 * static camera, the edge TAA's kernel reproducing linear images, the
 * checkerboard resolve exact for a static scene after two frames, and
 * thread independence. */
#include <stdlib.h>
#include <string.h>

#include "anti_aliasing/checkerboard.h"
#include "anti_aliasing/taa_accumulate.h"
#include "anti_aliasing/taa_edge.h"
#include "anti_aliasing/taa_sampling.h"
#include "tests/check.h"

enum { W = 40, H = 30, PX = W * H };

/* Frames k and k + 1 together put pixel (i, j)'s samples, and those of its
 * left and upper neighbours, on the midpoints of its four edges. */
static void test_edge_pattern(void)
{
    for (int k = 0; k < 4; ++k) {
        float a[2], b[2];
        taa_edge_jitter(k, a), taa_edge_jitter(k + 1, b);
        CHECK((a[0] == 0.5f && a[1] == 0.0f) != (b[0] == 0.5f && b[1] == 0.0f)); /* one horizontal, one vertical */
        CHECK(k % 2 ? a[0] == 0.5f && a[1] == 0.0f : a[0] == 0.0f && a[1] == 0.5f);
    }
    float h[2], v[2];
    taa_edge_jitter(1, h), taa_edge_jitter(0, v);
    int i = 7, j = 5, found = 0; /* pixel (i, j): edges midpoints (i, j+.5) (i+1, j+.5) (i+.5, j) (i+.5, j+1) */
    const double edge[4][2] = {{i, j + 0.5}, {i + 1, j + 0.5}, {i + 0.5, j}, {i + 0.5, j + 1}};
    for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di)
            for (int f = 0; f < 2; ++f) {
                const float *o = f ? h : v;
                double x = i + di + 0.5 + o[0], y = j + dj + 0.5 + o[1];
                for (int e = 0; e < 4; ++e)
                    found += x == edge[e][0] && y == edge[e][1];
            }
    CHECK_MSG(found == 4, "%d of the 4 edge midpoints sampled", found);
    for (int k = 0; k < 8; ++k) {
        float p[2];
        taa_halton_jitter(k, 8, p);
        CHECK(p[0] > -0.5f && p[0] < 0.5f && p[1] > -0.5f && p[1] < 0.5f);
    }
    CHECK_NEAR(taa_radical_inverse(6, 2), 0.375, 0.0);
    CHECK_NEAR(taa_radical_inverse(5, 3), 7.0 / 9.0, 1e-15);
}

/* Left of column W/2 colour A, right colour B. */
static void two_colours(float *rgb)
{
    for (int k = 0; k < PX; ++k)
        for (int c = 0; c < 3; ++c)
            rgb[3 * k + c] = k % W < W / 2 ? 0.2f + 0.1f * c : 0.9f - 0.2f * c;
}

/* Pixels at least 4 columns from the step equal the input. */
static int constant_parts_kept(const float *in, const float *out)
{
    int kept = 1;
    for (int k = 0; k < PX; ++k)
        if (abs(k % W - W / 2) >= 4)
            kept &= memcmp(in + 3 * k, out + 3 * k, 3 * sizeof(float)) == 0;
    return kept;
}

static void test_constant_regions(void)
{
    float *in = malloc(3 * sizeof(float) * PX), *out = malloc(3 * sizeof(float) * PX);
    float *sharp = malloc(3 * sizeof(float) * PX), *plain = malloc(3 * sizeof(float) * PX);
    float *motion = calloc(2 * PX, sizeof(float));
    two_colours(in);
    taa_accumulate_settings ts = taa_accumulate_default_settings();
    taa_accumulate(&ts, in, motion, NULL, W, H, 2, out);
    CHECK(constant_parts_kept(in, out));
    taa_accumulate(&ts, in, motion, in, W, H, 2, out);
    CHECK(constant_parts_kept(in, out));
    edge_taa_settings es = edge_taa_default_settings();
    for (int frame = 0; frame < 2; ++frame) {
        CHECK(edge_taa_resample(&es, in, frame, W, H, 2, sharp, plain) == 0);
        CHECK(constant_parts_kept(in, sharp) && constant_parts_kept(in, plain));
        edge_taa_resolve(sharp, plain, frame ? sharp : NULL, motion, W, H, 2, out);
        CHECK(constant_parts_kept(in, out));
    }
    checkerboard_settings cs = checkerboard_default_settings();
    checkerboard_grid g0, g1;
    CHECK(checkerboard_grid_build(&cs, in, W, H, 0, 2, &g0) == 0 && checkerboard_grid_build(&cs, in, W, H, 1, 2, &g1) == 0);
    CHECK(checkerboard_resolve(&cs, &g0, NULL, motion, 2, out) == 0 && constant_parts_kept(in, out));
    CHECK(checkerboard_resolve(&cs, &g1, &g0, motion, 2, out) == 0 && constant_parts_kept(in, out));
    checkerboard_grid_free(&g0), checkerboard_grid_free(&g1);
    free(in), free(out), free(sharp), free(plain), free(motion);
}

/* On f(x, y) = 0.01 x + 0.002 y (no FXAA), odd frames' samples at
 * (i + 1, j + 0.5): both the plain and the sharpened resample give f at the
 * centre (the kernel's weights sum to 1 and its lobes cancel on a line). */
static void test_edge_kernel_linear(void)
{
    float *in = malloc(3 * sizeof(float) * PX), *sharp = malloc(3 * sizeof(float) * PX), *plain = malloc(3 * sizeof(float) * PX);
    for (int k = 0; k < PX; ++k)
        for (int c = 0; c < 3; ++c)
            in[3 * k + c] = (float)(0.01 * (k % W + 1) + 0.002 * (k / W + 0.5));
    edge_taa_settings es = edge_taa_default_settings();
    es.fxaa = 0;
    CHECK(edge_taa_resample(&es, in, 1, W, H, 1, sharp, plain) == 0);
    double worst = 0.0;
    for (int k = 0; k < PX; ++k)
        if (k % W >= 2 && k % W < W - 2)
            for (int c = 0; c < 3; ++c) {
                double f = 0.01 * (k % W + 0.5) + 0.002 * (k / W + 0.5);
                worst = fmax(worst, fmax(fabs(sharp[3 * k + c] - f), fabs(plain[3 * k + c] - f)));
            }
    CHECK_MSG(worst < 1e-6, "edge resample off a linear image by %g", worst);
    free(in), free(sharp), free(plain);
}

static float uniform(unsigned *state)
{
    *state = *state * 1664525u + 1013904223u;
    return (float)(*state >> 8) * 0x1.0p-24f;
}

/* Static scene: after frames 0 and 1 each interior pixel is the mean of its
 * four corners; corners a frame does not render are never read. */
static void test_checkerboard_exact(int reject, int smooth)
{
    float *corners = malloc(3 * sizeof(float) * PX), *other = malloc(3 * sizeof(float) * PX);
    float *out = malloc(3 * sizeof(float) * PX), *motion = calloc(2 * PX, sizeof(float));
    unsigned state = 5u;
    for (int k = 0; k < 3 * PX; ++k)
        corners[k] = smooth ? 0.01f * (k / 3 % W) + 0.013f * (k / 3 / W) + 0.1f * (k % 3) : uniform(&state);
    checkerboard_settings cs = checkerboard_default_settings();
    cs.fxaa = 0, cs.reject = reject;
    checkerboard_grid g0, g1, g0b;
    memcpy(other, corners, 3 * sizeof(float) * PX);
    for (int k = 0; k < PX; ++k)
        if (!checkerboard_renders(0, k % W, k / W))
            other[3 * k] = -7.0f;
    CHECK(checkerboard_grid_build(&cs, corners, W, H, 0, 1, &g0) == 0 && checkerboard_grid_build(&cs, other, W, H, 0, 2, &g0b) == 0);
    size_t cells = 3 * (size_t)g0.a_count * g0.b_count;
    CHECK(memcmp(g0.rgb, g0b.rgb, cells * sizeof(float)) == 0);
    CHECK(checkerboard_grid_build(&cs, corners, W, H, 1, 1, &g1) == 0);
    CHECK(checkerboard_resolve(&cs, &g1, &g0, motion, 2, out) == 0);
    double worst = 0.0;
    for (int j = 0; j < H - 1; ++j)
        for (int i = 0; i < W - 1; ++i)
            for (int c = 0; c < 3; ++c) {
                const float *p = corners + 3 * ((size_t)j * W + i) + c;
                double mean = 0.25 * ((double)p[0] + p[3] + p[3 * W] + p[3 * W + 3]);
                worst = fmax(worst, fabs(out[3 * ((size_t)j * W + i) + c] - mean));
            }
    CHECK_MSG(worst < 1e-6, "checkerboard after two static frames off the 4-corner mean by %g", worst);
    checkerboard_grid_free(&g0), checkerboard_grid_free(&g1), checkerboard_grid_free(&g0b);
    free(corners), free(other), free(out), free(motion);
}

/* Every technique: the same bits on 1 and 2 threads, with motion. */
static void test_threads(void)
{
    float *in = malloc(3 * sizeof(float) * PX), *hist = malloc(3 * sizeof(float) * PX), *motion = malloc(2 * sizeof(float) * PX);
    float *a = malloc(3 * sizeof(float) * PX), *b = malloc(3 * sizeof(float) * PX);
    float *s = malloc(3 * sizeof(float) * PX), *p = malloc(3 * sizeof(float) * PX);
    unsigned state = 9u;
    for (int k = 0; k < 3 * PX; ++k)
        in[k] = uniform(&state), hist[k] = uniform(&state);
    for (int k = 0; k < 2 * PX; ++k)
        motion[k] = 3.0f * uniform(&state) - 1.5f;
    taa_accumulate_settings ts = taa_accumulate_default_settings();
    taa_accumulate(&ts, in, motion, hist, W, H, 1, a);
    taa_accumulate(&ts, in, motion, hist, W, H, 2, b);
    CHECK(memcmp(a, b, 3 * sizeof(float) * PX) == 0);
    edge_taa_settings es = edge_taa_default_settings();
    for (int t = 1; t <= 2; ++t) {
        CHECK(edge_taa_resample(&es, in, 1, W, H, t, s, p) == 0);
        edge_taa_resolve(s, p, hist, motion, W, H, t, t == 1 ? a : b);
    }
    CHECK(memcmp(a, b, 3 * sizeof(float) * PX) == 0);
    checkerboard_settings cs = checkerboard_default_settings();
    for (int t = 1; t <= 2; ++t) {
        checkerboard_grid g0, g1;
        CHECK(checkerboard_grid_build(&cs, hist, W, H, 0, t, &g0) == 0 && checkerboard_grid_build(&cs, in, W, H, 1, t, &g1) == 0);
        CHECK(checkerboard_resolve(&cs, &g1, &g0, motion, t, t == 1 ? a : b) == 0);
        checkerboard_grid_free(&g0), checkerboard_grid_free(&g1);
    }
    CHECK(memcmp(a, b, 3 * sizeof(float) * PX) == 0);
    free(in), free(hist), free(motion), free(a), free(b), free(s), free(p);
}

int main(void)
{
    test_edge_pattern();
    test_constant_regions();
    test_edge_kernel_linear();
    test_checkerboard_exact(0, 0);
    test_checkerboard_exact(1, 1);
    test_threads();
    return check_report("test_taa");
}
