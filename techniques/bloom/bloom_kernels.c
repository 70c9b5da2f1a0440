/* The bloom study's target kernels at any phase: see bloom_kernels.h. */
#include "bloom/bloom_kernels.h"

#include <math.h>

static double half_texel_variance(double sigma)
{
    double num = 0.0, den = 0.0;
    for (int k = 0; k < 3; ++k) {
        double x = k + 0.5, g = exp(-0.5 * x * x / (sigma * sigma));
        num += g * x * x, den += g;
    }
    return num / den;
}

double bloom_gaussian_sigma(double variance)
{
    double lo = 0.2, hi = 20.0;
    for (int i = 0; i < 200; ++i) {
        double mid = 0.5 * (lo + hi);
        if (half_texel_variance(mid) < variance)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

/* The Gaussian's weights along one axis: texel centres at i - 7/2 - phase
 * within (-window, window), normalised. */
static void gaussian_axis(double sigma, double phase, double window, double w[BLOOM_GRID])
{
    double sum = 0.0;
    for (int i = 0; i < BLOOM_GRID; ++i) {
        double x = i - 3.5 - phase;
        w[i] = fabs(x) < window ? exp(-0.5 * x * x / (sigma * sigma)) : 0.0;
        sum += w[i];
    }
    for (int i = 0; i < BLOOM_GRID; ++i)
        w[i] /= sum;
}

void bloom_target_grid(int target, double sigma, double phase_x, double phase_y, double grid[BLOOM_GRID][BLOOM_GRID])
{
    if (target == 0) {
        bloom_tap taps[BLOOM_JIMENEZ_TAPS];
        bloom_jimenez13(taps);
        bloom_texel_weights(taps, BLOOM_JIMENEZ_TAPS, phase_x, phase_y, grid);
        return;
    }
    double wx[BLOOM_GRID], wy[BLOOM_GRID], window = target == BLOOM_TARGET_GAUSSIAN_6 ? 3.0 : 4.5;
    gaussian_axis(sigma, phase_x, window, wx);
    gaussian_axis(sigma, phase_y, window, wy);
    for (int j = 0; j < BLOOM_GRID; ++j)
        for (int i = 0; i < BLOOM_GRID; ++i)
            grid[j][i] = wx[i] * wy[j];
}

static int clamp_index(int i, int n) { return i < 0 ? 0 : i >= n ? n - 1 : i; }

void bloom_target_downsample(int target, double sigma, const float *src, int sw, int sh, float *dst, int dw, int dh)
{
    double grid[BLOOM_GRID][BLOOM_GRID];
    for (int j = 0; j < dh; ++j)
        for (int i = 0; i < dw; ++i) {
            double cx = (i + 0.5) * sw / dw, cy = (j + 0.5) * sh / dh, sum = 0.0;
            int x0 = (int)floor(cx), y0 = (int)floor(cy);
            bloom_target_grid(target, sigma, cx - x0, cy - y0, grid);
            for (int v = 0; v < BLOOM_GRID; ++v)
                for (int u = 0; u < BLOOM_GRID; ++u)
                    sum += grid[v][u] * src[(long)clamp_index(y0 - 4 + v, sh) * sw + clamp_index(x0 - 4 + u, sw)];
            dst[(long)j * dw + i] = (float)sum;
        }
}
