/* Half resolution, depth-aware upsample and accumulation; see
 * volumetric_light/volumetric_light_upsample.h. */
#include "volumetric_light/volumetric_light_upsample.h"

#include <math.h>

void raymarch_image_half(const raymarch_lighting *l, const raymarch_view *view, int steps, raymarch_noise noise,
                         const blue_noise_texture *blue, int frame, int threads, float *out, float *half_distance)
{
    int hw = (view->width + 1) / 2, hh = (view->height + 1) / 2;
#pragma omp parallel for schedule(static) num_threads(threads > 0 ? threads : 1)
    for (int j = 0; j < hh; ++j)
        for (int i = 0; i < hw; ++i) {
            long p = (long)(2 * j) * view->width + 2 * i, q = (long)j * hw + i;
            double xi = raymarch_offset(noise, blue, frame, i, j);
            half_distance[q] = view->distance[p];
            out[q] = (float)raymarch_ray(l, view->eye, v3_load(&view->dir[3 * p]), view->distance[p], steps, xi);
        }
}

static int clamp_index(int i, int n) { return i < 0 ? 0 : i >= n ? n - 1 : i; }

/* One full-resolution pixel from its four half-resolution taps. */
static float upsample_pixel(const float *half, const float *half_distance, int hw, int hh, double u, double v,
                            double depth)
{
    int i0 = (int)floor(u), j0 = (int)floor(v), nearest = -1;
    double fu = u - i0, fv = v - j0, sum = 0.0, weight = 0.0, nearest_gap = INFINITY;
    for (int k = 0; k < 4; ++k) {
        int i = clamp_index(i0 + (k & 1), hw), j = clamp_index(j0 + (k >> 1), hh), q = j * hw + i;
        double w = ((k & 1) ? fu : 1.0 - fu) * ((k >> 1) ? fv : 1.0 - fv), gap = fabs(half_distance[q] - depth);
        if (gap < nearest_gap)
            nearest_gap = gap, nearest = q;
        if (gap <= UPSAMPLE_DEPTH_TOLERANCE * depth && w > 0.0)
            sum += w * half[q], weight += w;
    }
    return weight > 0.0 ? (float)(sum / weight) : half[nearest];
}

void raymarch_upsample(const float *half, const float *half_distance, const raymarch_view *view, float *out)
{
    int hw = (view->width + 1) / 2, hh = (view->height + 1) / 2;
    for (int y = 0; y < view->height; ++y)
        for (int x = 0; x < view->width; ++x) {
            long p = (long)y * view->width + x;
            out[p] = view->distance[p] > 0.0f
                         ? upsample_pixel(half, half_distance, hw, hh, 0.5 * x, 0.5 * y, view->distance[p])
                         : 0.0f;
        }
}

/* Four taps at (u, v) + (+-1/2, +-1/2), nearest half pixel, equal weights. */
static float noisy_pixel(const float *half, const float *half_distance, int hw, int hh, double u, double v,
                         double depth)
{
    int nearest = -1, count = 0;
    double sum = 0.0, nearest_gap = INFINITY;
    for (int k = 0; k < 4; ++k) {
        int i = clamp_index((int)floor(u + ((k & 1) ? 0.5 : -0.5) + 0.5), hw);
        int j = clamp_index((int)floor(v + ((k >> 1) ? 0.5 : -0.5) + 0.5), hh), q = j * hw + i;
        double gap = fabs(half_distance[q] - depth);
        if (gap < nearest_gap)
            nearest_gap = gap, nearest = q;
        if (gap <= UPSAMPLE_DEPTH_TOLERANCE * depth)
            sum += half[q], ++count;
    }
    return count > 0 ? (float)(sum / count) : half[nearest];
}

void raymarch_upsample_noisy(const float *half, const float *half_distance, const raymarch_view *view,
                             const blue_noise_texture *blue, int frame, float *out)
{
    int hw = (view->width + 1) / 2, hh = (view->height + 1) / 2, shift = blue->size / 2 + 3;
    for (int y = 0; y < view->height; ++y)
        for (int x = 0; x < view->width; ++x) {
            long p = (long)y * view->width + x;
            double du = raymarch_offset(RAYMARCH_NOISE_BLUE, blue, frame, x, y) - 0.5;
            double dv = raymarch_offset(RAYMARCH_NOISE_BLUE, blue, frame, x + shift, y + shift) - 0.5;
            out[p] = view->distance[p] > 0.0f
                         ? noisy_pixel(half, half_distance, hw, hh, 0.5 * x + du, 0.5 * y + dv, view->distance[p])
                         : 0.0f;
        }
}

void raymarch_accumulate(float *history, const float *frame, long count, double alpha, int first)
{
    for (long p = 0; p < count; ++p)
        history[p] = first ? frame[p] : (float)((1.0 - alpha) * history[p] + alpha * frame[p]);
}
