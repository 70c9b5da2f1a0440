/* The talk's 2-frame edge-sample TAA (taa_edge.h). */
#include "anti_aliasing/taa_edge.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "anti_aliasing/taa_sampling.h"

edge_taa_settings edge_taa_default_settings(void)
{
    edge_taa_settings s = {1.0 / 16.0, 1, fxaa_default_settings()};
    return s;
}

static double luma(const float *p) { return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]; }

static int clamp_index(int i, int n) { return i < 0 ? 0 : (i >= n ? n - 1 : i); }

/* Pixel (i, j) from the four taps along the frame's direction (dx, dy). */
static void resample_pixel(const edge_taa_settings *s, const float *im, int width, int height, int i, int j, int dx,
                           int dy, float *sharpened, float *plain)
{
    const float *t[4];
    double lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < 4; ++k) { /* offsets -2, -1, 0, +1: the samples at -1.5, -0.5, +0.5, +1.5 */
        t[k] = im + 3 * ((size_t)clamp_index(j + (k - 2) * dy, height) * width + clamp_index(i + (k - 2) * dx, width));
        lo = fmin(lo, luma(t[k])), hi = fmax(hi, luma(t[k]));
    }
    double w = s->sharpen * (1.0 - fmin(fmax(hi - lo, 0.0), 1.0));
    for (int c = 0; c < 3; ++c) {
        double p = 0.5 * ((double)t[1][c] + t[2][c]);
        plain[c] = (float)p;
        sharpened[c] = (float)fmin(fmax(p + w * (((double)t[1][c] - t[0][c]) + ((double)t[2][c] - t[3][c])), 0.0), 1.0);
    }
}

int edge_taa_resample(const edge_taa_settings *s, const float *samples, int frame, int width, int height, int threads,
                      float *sharpened, float *plain)
{
    float *filtered = NULL;
    if (s->fxaa) {
        if (!(filtered = malloc(3 * sizeof(float) * (size_t)width * height)) ||
            fxaa_apply(&s->fx, samples, width, height, threads, filtered) != 0) {
            free(filtered);
            return -1;
        }
    }
    const float *im = filtered ? filtered : samples;
    int odd = frame % 2 != 0, dx = odd ? 1 : 0, dy = odd ? 0 : 1;
    /* odd: samples at x = i + 1, so pixel i sits between samples i - 1 and i: taps i - 2 .. i + 1 */
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            size_t k = 3 * ((size_t)j * width + i);
            resample_pixel(s, im, width, height, i, j, dx, dy, sharpened + k, plain + k);
        }
    free(filtered);
    return 0;
}

static int inside_box(const float *v, const float lo[3], const float hi[3])
{
    return v[0] >= lo[0] && v[0] <= hi[0] && v[1] >= lo[1] && v[1] <= hi[1] && v[2] >= lo[2] && v[2] <= hi[2];
}

static void resolve_pixel(const float *sharpened, const float *plain, const float *previous, const float *motion,
                          int width, int height, int i, int j, float *out)
{
    size_t k = (size_t)j * width + i;
    double x = i + 0.5 + motion[2 * k], y = j + 0.5 + motion[2 * k + 1];
    float h[3], lo[3], hi[3];
    int accept = previous && taa_inside(width, height, x, y);
    if (accept) {
        taa_bilinear(previous, width, height, x, y, h);
        taa_neighbourhood_box(sharpened, width, height, i, j, lo, hi);
        accept = inside_box(h, lo, hi);
    }
    for (int c = 0; c < 3; ++c)
        out[3 * k + c] = accept ? 0.5f * sharpened[3 * k + c] + 0.5f * h[c] : plain[3 * k + c];
}

void edge_taa_resolve(const float *sharpened, const float *plain, const float *previous_sharpened, const float *motion,
                      int width, int height, int threads, float *out)
{
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i)
            resolve_pixel(sharpened, plain, previous_sharpened, motion, width, height, i, j, out);
}
