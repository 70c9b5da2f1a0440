/* Pixel reconstruction filters (pixel_filter.h). */
#include "core/sampling/pixel_filter.h"

#include <math.h>
#include <stddef.h>

#include "core/vec3.h" /* M_PI */

static const char *const names[PIXEL_FILTER_COUNT] = {"box", "blackman-harris"};

const char *pixel_filter_name(int filter)
{
    return filter >= 0 && filter < PIXEL_FILTER_COUNT ? names[filter] : "?";
}

double pixel_filter_radius(pixel_filter f)
{
    return f == PIXEL_FILTER_BOX ? 0.5 : 1.5;
}

static double blackman_harris(double d, double r)
{
    if (fabs(d) > r)
        return 0.0;
    double t = (d + r) / (2.0 * r);
    return 0.35875 - 0.48829 * cos(2.0 * M_PI * t) + 0.14128 * cos(4.0 * M_PI * t) - 0.01168 * cos(6.0 * M_PI * t);
}

double pixel_filter_weight(pixel_filter f, double dx, double dy)
{
    if (f == PIXEL_FILTER_BOX)
        return fabs(dx) <= 0.5 && fabs(dy) <= 0.5 ? 1.0 : 0.0;
    if (fabs(dx) > 1.5 || fabs(dy) > 1.5) /* the product's zero, without its cosines */
        return 0.0;
    return blackman_harris(dx, 1.5) * blackman_harris(dy, 1.5);
}

/* Pixel (i, j): the samples of the pixels within the radius. */
static void resolve_pixel(pixel_filter f, const float *rgb, const float *xy, int width, int height, int s, int i, int j,
                          float out[3])
{
    int reach = (int)ceil(pixel_filter_radius(f)), w = width * s;
    double sum[3] = {0, 0, 0}, wsum = 0.0, cx = i + 0.5, cy = j + 0.5;
    for (int pj = j - reach; pj <= j + reach; ++pj)
        for (int pi = i - reach; pi <= i + reach; ++pi) {
            if (pi < 0 || pj < 0 || pi >= width || pj >= height)
                continue;
            for (int sj = pj * s; sj < (pj + 1) * s; ++sj)
                for (int si = pi * s; si < (pi + 1) * s; ++si) {
                    size_t k = (size_t)sj * w + si;
                    double wt = pixel_filter_weight(f, xy[2 * k] - cx, xy[2 * k + 1] - cy);
                    if (wt == 0.0)
                        continue; /* outside the support: adds nothing (and costs no cosine below) */
                    wsum += wt;
                    for (int c = 0; c < 3; ++c)
                        sum[c] += wt * rgb[3 * k + c];
                }
        }
    for (int c = 0; c < 3; ++c)
        out[c] = (float)(wsum > 0.0 ? sum[c] / wsum : 0.0);
}

void pixel_filter_resolve(pixel_filter f, const float *rgb, const float *xy, int width, int height, int s,
                          int threads, float *out)
{
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i)
            resolve_pixel(f, rgb, xy, width, height, s, i, j, out + 3 * ((size_t)j * width + i));
}
