/* BC4 through libsquish (specular_occlusion/bc4_codec.h) and the cone/lobe table as
 * shipped (so_lut_bc4):
 *  - every texel decodes within the format's bound of its 8-bit value:
 *    (hi - lo) / 14 + 1 in 8-bit units, [lo, hi] its block's span (the
 *    nearest of eight evenly spaced values, plus libsquish's decoder
 *    truncating each to 8 bits) —
 *    on a ramp with noise, on an image whose size is not a multiple of 4, and
 *    on every slice of a 16^3 GGX table;
 *  - a block of one value decodes to that value's 8-bit rounding exactly;
 *  - so_lut_bc4 keeps the table's layout and marks it. */
#include <math.h>
#include <stdlib.h>

#include "specular_occlusion/bc4_codec.h"
#include "specular_occlusion/specular_occlusion_lut.h"
#include "tests/check.h"

static double unorm8(float v) { return rint(255.0 * fmin(1.0, fmax(0.0, v))); }

/* The largest excess of |decoded - q| over the bound, in 8-bit units (<= 0,
 * to 1e-3 for the float of k / 255: every texel within it). */
static double worst_excess(const float *values, const float *decoded, int width, int height)
{
    double worst = -INFINITY;
    for (int by = 0; by < height; by += 4)
        for (int bx = 0; bx < width; bx += 4) {
            double lo = 255.0, hi = 0.0;
            for (int y = by; y < by + 4 && y < height; ++y)
                for (int x = bx; x < bx + 4 && x < width; ++x)
                    lo = fmin(lo, unorm8(values[y * width + x])), hi = fmax(hi, unorm8(values[y * width + x]));
            double bound = (hi - lo) / 14.0 + 1.0;
            for (int y = by; y < by + 4 && y < height; ++y)
                for (int x = bx; x < bx + 4 && x < width; ++x) {
                    double q = unorm8(values[y * width + x]), d = 255.0 * decoded[y * width + x];
                    worst = fmax(worst, fabs(d - q) - bound);
                }
        }
    return worst;
}

static double round_trip_excess(const float *values, int width, int height)
{
    unsigned char *blocks = malloc(bc4_storage_bytes(width, height));
    float *decoded = malloc(sizeof *decoded * (size_t)width * height);
    bc4_encode(values, width, height, blocks);
    bc4_decode(blocks, width, height, decoded);
    double excess = worst_excess(values, decoded, width, height);
    free(blocks), free(decoded);
    return excess;
}

static void test_ramp(void)
{
    enum { W = 32, H = 32 };
    static float values[W * H];
    unsigned state = 7u;
    for (int i = 0; i < W * H; ++i) {
        state = state * 1664525u + 1013904223u;
        values[i] = (float)((i % W) / (W - 1.0) * 0.8 + 0.1 * (state >> 8) / 16777216.0);
    }
    double excess = round_trip_excess(values, W, H);
    CHECK_MSG(excess <= 1e-3, "ramp: %.3f 8-bit units beyond the bound", excess);
    CHECK(round_trip_excess(values, 10, 6) <= 1e-3); /* partial blocks */
    CHECK(bc4_storage_bytes(10, 6) == 3 * 2 * BC4_BLOCK_BYTES);
}

static void test_constant_block(void)
{
    float values[16], decoded[16];
    unsigned char block[BC4_BLOCK_BYTES];
    for (int i = 0; i < 16; ++i)
        values[i] = 0.3f;
    bc4_encode(values, 4, 4, block);
    bc4_decode(block, 4, 4, decoded);
    for (int i = 0; i < 16; ++i)
        CHECK_NEAR(decoded[i], unorm8(0.3f) / 255.0, 1e-7);
}

static void test_lut(void)
{
    so_lut lut, shipped;
    CHECK(so_lut_build(&lut, 16, SO_LOBE_GGX, SO_AXES_ANGLES, 2) == 0);
    CHECK(so_lut_bc4(&lut, &shipped) == 0);
    CHECK(shipped.bc4 == 1 && lut.bc4 == 0 && shipped.size == 16 && shipped.lobe == lut.lobe);
    double worst = -INFINITY, largest = 0.0;
    for (int k = 0; k < 16; ++k) {
        const float *a = lut.data + 256 * k, *b = shipped.data + 256 * k;
        worst = fmax(worst, worst_excess(a, b, 16, 16));
        for (int i = 0; i < 256; ++i)
            largest = fmax(largest, fabs(a[i] - b[i]));
    }
    CHECK_MSG(worst <= 1e-3, "LUT: %.3f 8-bit units beyond the bound", worst);
    CHECK(largest > 0.0); /* the compression did something */
    so_lut_free(&lut), so_lut_free(&shipped);
}

int main(void)
{
    test_ramp();
    test_constant_block();
    test_lut();
    return check_report("test_bc4_codec");
}
