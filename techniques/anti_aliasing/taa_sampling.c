/* Shared temporal anti-aliasing helpers (taa_sampling.h). */
#include "anti_aliasing/taa_sampling.h"

#include <math.h>
#include <stddef.h>

double taa_radical_inverse(unsigned index, unsigned base)
{
    double result = 0.0, scale = 1.0 / base;
    for (; index > 0; index /= base, scale /= base)
        result += (index % base) * scale;
    return result;
}

void taa_halton_jitter(int frame, int period, float out[2])
{
    unsigned index = (unsigned)(frame % period) + 1u;
    out[0] = (float)(taa_radical_inverse(index, 2) - 0.5);
    out[1] = (float)(taa_radical_inverse(index, 3) - 0.5);
}

void taa_edge_jitter(int frame, float out[2])
{
    int odd = frame % 2 != 0;
    out[0] = odd ? 0.5f : 0.0f;
    out[1] = odd ? 0.0f : 0.5f;
}

static int clamp_index(int i, int n) { return i < 0 ? 0 : (i >= n ? n - 1 : i); }

void taa_bilinear(const float *rgb, int width, int height, double x, double y, float out[3])
{
    double fx = x - 0.5, fy = y - 0.5;
    int i = (int)floor(fx), j = (int)floor(fy);
    double a = fx - i, b = fy - j, w[4] = {(1 - a) * (1 - b), a * (1 - b), (1 - a) * b, a * b};
    const float *t[4] = {rgb + 3 * ((size_t)clamp_index(j, height) * width + clamp_index(i, width)),
                         rgb + 3 * ((size_t)clamp_index(j, height) * width + clamp_index(i + 1, width)),
                         rgb + 3 * ((size_t)clamp_index(j + 1, height) * width + clamp_index(i, width)),
                         rgb + 3 * ((size_t)clamp_index(j + 1, height) * width + clamp_index(i + 1, width))};
    for (int c = 0; c < 3; ++c)
        out[c] = (float)(w[0] * t[0][c] + w[1] * t[1][c] + w[2] * t[2][c] + w[3] * t[3][c]);
}

void taa_neighbourhood_box(const float *rgb, int width, int height, int i, int j, float lo[3], float hi[3])
{
    for (int c = 0; c < 3; ++c)
        lo[c] = INFINITY, hi[c] = -INFINITY;
    for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
            const float *p = rgb + 3 * ((size_t)clamp_index(j + dj, height) * width + clamp_index(i + di, width));
            for (int c = 0; c < 3; ++c)
                lo[c] = fminf(lo[c], p[c]), hi[c] = fmaxf(hi[c], p[c]);
        }
}

int taa_inside(int width, int height, double x, double y)
{
    return x >= 0.0 && x <= width && y >= 0.0 && y <= height;
}
