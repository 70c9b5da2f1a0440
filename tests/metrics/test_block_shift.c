/* metrics/block_mean.h and metrics/shift_fit.h against closed forms: block
 * means of a known image and their spread; the shift of a smooth image
 * displaced by a known sub-pixel amount, recovered by least squares, and a
 * zero shift for an unshifted copy with symmetric noise. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "metrics/block_mean.h"
#include "metrics/shift_fit.h"
#include "tests/check.h"

enum { W = 64, H = 48 };

static double smooth(double x, double y) { return sin(0.21 * x) * cos(0.17 * y) + 0.01 * x; }

static void test_block_mean(void)
{
    /* Block k (of 8 x 6 blocks of 8x8) holds the constant k: the mean and
     * the spread of 0..47 are known. */
    float *v = malloc(sizeof(float) * W * H);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            v[y * W + x] = (float)((y / 8) * (W / 8) + x / 8);
    block_mean m = {0};
    block_mean_add(&m, v, NULL, W, H, 8);
    double n = 48.0, mean = 23.5, var = n * (n + 1.0) / 12.0; /* of 0..47, sample variance */
    CHECK(m.blocks == 48);
    CHECK_NEAR(block_mean_value(&m), mean, 1e-12);
    CHECK_NEAR(block_mean_se(&m), sqrt(var / n), 1e-9);
    free(v);
}

static void test_shift(double dx, double dy)
{
    float *a = malloc(sizeof(float) * W * H), *b = malloc(sizeof(float) * W * H);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            b[y * W + x] = (float)smooth(x, y);
            a[y * W + x] = (float)smooth(x + dx, y + dy); /* a(x) = b(x + d) ~ b + d . grad b */
        }
    shift_fit s = {0};
    shift_fit_add(&s, a, b, NULL, W, H, 8);
    double d[2], se[2];
    shift_fit_solve(&s, d, se);
    printf("shift (%.2f, %.2f): fitted (%.4f, %.4f) +- (%.4f, %.4f)\n", dx, dy, d[0], d[1], se[0], se[1]);
    CHECK_NEAR(d[0], dx, 0.02);
    CHECK_NEAR(d[1], dy, 0.02);
    free(a);
    free(b);
}

/* b = c x + e y: central differences are exact, so the RMS change per pixel
 * of shift along u is |c u_x + e u_y| at every usable pixel (the border
 * row and column have no four neighbours and are left out). */
static void test_rms_gradient(void)
{
    float *b = malloc(sizeof(float) * W * H);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            b[y * W + x] = (float)(0.01 * x - 0.004 * y);
    shift_fit s = {0};
    shift_fit_add(&s, b, b, NULL, W, H, 8);
    CHECK(s.pixels == (long)(W - 2) * (H - 2));
    const double ux[2] = {1.0, 0.0}, diagonal[2] = {0.5, 0.5};
    CHECK_NEAR(shift_fit_rms_gradient(&s, ux), 0.01, 1e-6);
    CHECK_NEAR(shift_fit_rms_gradient(&s, diagonal), 0.003, 1e-6);
    shift_fit empty = {0};
    CHECK(shift_fit_rms_gradient(&empty, ux) == 0.0);
    free(b);
}

int main(void)
{
    test_rms_gradient();
    test_block_mean();
    test_shift(0.5, 0.5);
    test_shift(-0.25, 0.1);
    test_shift(0.0, 0.0);
    return check_report("test_block_shift");
}
