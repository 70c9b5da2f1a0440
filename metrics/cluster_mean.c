/* Block-clustered means and standard errors; see cluster_mean.h. */
#include "metrics/cluster_mean.h"

#include <math.h>
#include <stdlib.h>

#include "metrics/image_error.h"

/* Sum and count of block (bx, by)'s pixels inside the mask. */
static void block_total(const float *x, const float *mask, int width, int height, int side, int bx, int by,
                        double *sum, size_t *count)
{
    *sum = 0.0;
    *count = 0;
    for (int y = by * side; y < (by + 1) * side && y < height; ++y)
        for (int i = bx * side; i < (bx + 1) * side && i < width; ++i) {
            size_t k = (size_t)y * width + i;
            if (metrics_in_mask(mask, k)) {
                *sum += x[k];
                ++*count;
            }
        }
}

int cluster_mean_compute(const float *x, const float *mask, int width, int height, int side, cluster_mean *out)
{
    int nx = (width + side - 1) / side, ny = (height + side - 1) / side;
    double total = 0.0, squares = 0.0, mean;
    size_t pixels = 0;
    int blocks = 0;
    for (int pass = 0; pass < 2; ++pass) {
        mean = pixels ? total / (double)pixels : 0.0;
        for (int b = 0; b < nx * ny; ++b) {
            double t;
            size_t n;
            block_total(x, mask, width, height, side, b % nx, b / nx, &t, &n);
            if (n == 0)
                continue;
            if (pass == 0) {
                total += t;
                pixels += n;
                ++blocks;
            } else
                squares += (t - mean * (double)n) * (t - mean * (double)n);
        }
        if (pixels == 0)
            return -1;
    }
    out->mean = mean;
    out->pixels = pixels;
    out->blocks = blocks;
    out->se = blocks > 1 ? sqrt((double)blocks / (blocks - 1) * squares) / (double)pixels : 0.0;
    return 0;
}

int cluster_mean_paired_sq_error(const float *a, const float *b, const float *r, const float *mask, int width,
                               int height, int side, cluster_mean *out)
{
    size_t n = (size_t)width * height;
    float *d = malloc(sizeof *d * n);
    if (!d)
        return -1;
    for (size_t i = 0; i < n; ++i) {
        double ea = (double)a[i] - r[i], eb = (double)b[i] - r[i];
        d[i] = (float)(ea * ea - eb * eb);
    }
    int rc = cluster_mean_compute(d, mask, width, height, side, out);
    free(d);
    return rc;
}

int unorm8_code(float x)
{
    float c = x < 0.0f ? 0.0f : x > 1.0f ? 1.0f : x;
    return (int)lrintf(255.0f * c);
}

/* The block mean of per-pixel f(a, b). */
static int pixelwise_mean(const float *a, const float *b, const float *mask, int width, int height, int side,
                          float (*f)(float, float), cluster_mean *out)
{
    size_t n = (size_t)width * height;
    float *d = malloc(sizeof *d * n);
    if (!d)
        return -1;
    for (size_t i = 0; i < n; ++i)
        d[i] = f(a[i], b[i]);
    int rc = cluster_mean_compute(d, mask, width, height, side, out);
    free(d);
    return rc;
}

static float difference(float a, float b) { return a - b; }
static float abs_difference(float a, float b) { return fabsf(a - b); }
static float code_changed(float a, float b) { return unorm8_code(a) != unorm8_code(b) ? 1.0f : 0.0f; }

int cluster_mean_difference(const float *a, const float *b, const float *mask, int width, int height, int side,
                            cluster_mean *out)
{
    return pixelwise_mean(a, b, mask, width, height, side, difference, out);
}

int cluster_mean_abs_difference(const float *a, const float *b, const float *mask, int width, int height, int side,
                                cluster_mean *out)
{
    return pixelwise_mean(a, b, mask, width, height, side, abs_difference, out);
}

int cluster_mean_code_changes(const float *a, const float *b, const float *mask, int width, int height, int side,
                              cluster_mean *out)
{
    return pixelwise_mean(a, b, mask, width, height, side, code_changed, out);
}

cluster_mean cluster_mean_pool(const cluster_mean *parts, int count)
{
    cluster_mean out = {0.0, 0.0, 0, 0};
    double total = 0.0, variance = 0.0;
    for (int k = 0; k < count; ++k) {
        double n = (double)parts[k].pixels;
        total += n * parts[k].mean;
        variance += n * n * parts[k].se * parts[k].se;
        out.pixels += parts[k].pixels;
        out.blocks += parts[k].blocks;
    }
    if (out.pixels > 0) {
        out.mean = total / (double)out.pixels;
        out.se = sqrt(variance) / (double)out.pixels;
    }
    return out;
}
