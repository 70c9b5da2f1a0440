/* Jimenez's 13-tap bloom downsample and 9-tap refits: see bloom_downsample.h. */
#include "bloom/bloom_downsample.h"

#include <math.h>

void bloom_jimenez13(bloom_tap taps[BLOOM_JIMENEZ_TAPS])
{
    int n = 0;
    for (int j = -1; j <= 1; ++j) /* the 3 x 3 outer taps: 1/32 corners, 2/32 edges, 4/32 centre */
        for (int i = -1; i <= 1; ++i)
            taps[n++] = (bloom_tap){2.0 * i, 2.0 * j, (double)((2 - (i != 0)) * (2 - (j != 0))) / 32.0};
    for (int j = -1; j <= 1; j += 2) /* the centre box: 1/2 over 4 taps */
        for (int i = -1; i <= 1; i += 2)
            taps[n++] = (bloom_tap){(double)i, (double)j, 0.125};
}

void bloom_block_centre(int k, double *x, double *y)
{
    *x = 2.0 * (k % 3 - 1);
    *y = 2.0 * (k / 3 - 1);
}

static double tent(double d) { return fmax(0.0, 1.0 - fabs(d)); }

void bloom_texel_weights(const bloom_tap *taps, int count, double phase_x, double phase_y,
                         double grid[BLOOM_GRID][BLOOM_GRID])
{
    for (int j = 0; j < BLOOM_GRID; ++j)
        for (int i = 0; i < BLOOM_GRID; ++i) {
            double tx = i - 3.5 - phase_x, ty = j - 3.5 - phase_y, sum = 0.0;
            for (int k = 0; k < count; ++k)
                sum += taps[k].w * tent(taps[k].x - tx) * tent(taps[k].y - ty);
            grid[j][i] = sum;
        }
}

double bloom_frequency_response(const double grid[BLOOM_GRID][BLOOM_GRID], double wx, double wy)
{
    double h = 0.0;
    for (int j = 0; j < BLOOM_GRID; ++j)
        for (int i = 0; i < BLOOM_GRID; ++i)
            h += grid[j][i] * cos(wx * (i - 3.5) + wy * (j - 3.5));
    return h;
}

static int clamp_index(int i, int n) { return i < 0 ? 0 : i >= n ? n - 1 : i; }

double bloom_fetch(const float *src, int w, int h, double x, double y)
{
    double fx = x - 0.5, fy = y - 0.5, x0 = floor(fx), y0 = floor(fy), ax = fx - x0, ay = fy - y0;
    int i0 = clamp_index((int)x0, w), i1 = clamp_index((int)x0 + 1, w);
    int j0 = clamp_index((int)y0, h), j1 = clamp_index((int)y0 + 1, h);
    double top = (1 - ax) * src[(long)j0 * w + i0] + ax * src[(long)j0 * w + i1];
    double bottom = (1 - ax) * src[(long)j1 * w + i0] + ax * src[(long)j1 * w + i1];
    return (1 - ay) * top + ay * bottom;
}

void bloom_downsample(const float *src, int sw, int sh, float *dst, int dw, int dh, const bloom_tap *taps, int count)
{
    for (int j = 0; j < dh; ++j)
        for (int i = 0; i < dw; ++i) {
            double cx = (i + 0.5) * sw / dw, cy = (j + 0.5) * sh / dh, sum = 0.0;
            for (int k = 0; k < count; ++k)
                sum += taps[k].w * bloom_fetch(src, sw, sh, cx + taps[k].x, cy + taps[k].y);
            dst[(long)j * dw + i] = (float)sum;
        }
}
