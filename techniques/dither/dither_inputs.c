/* The dither study's inputs: see dither_inputs.h. */
#include "core/optics/srgb.h" /* linear_to_srgb */
#include "dither/dither_inputs.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/progress.h"
#include "core/reference_schema.h"
#include "dither/dither.h"
#include "metrics/dither_metrics.h"
#include "sphere_light/sphere_light_hdr_test_image.h"

int dither_gradient(const dither_request *rq, dither_input *out, gt_error *e)
{
    out->name = "gradient";
    out->mask = NULL;
    out->width = rq->gradient_width, out->height = rq->gradient_height;
    out->values = malloc((size_t)out->width * out->height * sizeof(double));
    if (!out->values)
        return gt_error_set(e, "dither", "out of memory");
    for (int y = 0; y < out->height; ++y)
        for (int x = 0; x < out->width; ++x)
            out->values[(size_t)y * out->width + x] = 0.2 + 0.1 * (x + 0.5) / out->width;
    return 0;
}

static int compare_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* The 99th percentile of the covered pixels of plane. */
static double percentile99(const float *plane, const float *mask, size_t n)
{
    float *v = malloc(n * sizeof(float));
    size_t m = 0;
    for (size_t i = 0; v && i < n; ++i)
        if (mask[i] != 0.0f)
            v[m++] = plane[i];
    if (m > 0)
        qsort(v, m, sizeof(float), compare_float);
    double p = m > 0 ? v[(size_t)(0.99 * (double)(m - 1))] : 1.0;
    free(v);
    return p > 0.0 ? p : 1.0;
}

static int tone_map(const image *ref, dither_input *out, gt_error *e)
{
    const float *g = image_channel_data(ref, CH_SPHERE_G), *mask = image_channel_data(ref, CH_MASK);
    size_t n = image_pixel_count(ref);
    out->name = "sphere light";
    out->width = ref->width, out->height = ref->height;
    out->values = malloc(n * sizeof(double));
    out->mask = malloc(n);
    if (!g || !mask || !out->values || !out->mask)
        return gt_error_set(e, "dither", "the sphere-light render lacks %s or %s, or out of memory", CH_SPHERE_G,
                            CH_MASK);
    double exposure = 1.0 / percentile99(g, mask, n);
    for (size_t i = 0; i < n; ++i) {
        double x = exposure * g[i];
        out->values[i] = linear_to_srgb(x / (1.0 + x));
        out->mask[i] = mask[i] != 0.0f;
    }
    return 0;
}

int dither_render(const study_context *ctx, const dither_request *rq, dither_input *out, gt_error *e)
{
    image ref;
    if (hdr_test_image_sphere_light(ctx, rq->render_width, rq->render_height, rq->render_spp, rq->seed, &ref, e) != 0)
        return -1;
    int rc = tone_map(&ref, out, e);
    image_free(&ref);
    return rc;
}

int dither_blur_display(float *plane, int width, int height, gt_error *e)
{
    enum { R = 3 };
    double w[2 * R + 1], sum = 0.0;
    for (int k = -R; k <= R; ++k)
        sum += w[k + R] = exp(-0.5 * k * k);
    float *tmp = malloc((size_t)width * height * sizeof(float));
    if (!tmp)
        return gt_error_set(e, "dither", "out of memory");
    for (int pass = 0; pass < 2; ++pass) {
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                double acc = 0.0;
                for (int k = -R; k <= R; ++k) {
                    int xx = pass ? x : x + k, yy = pass ? y + k : y;
                    xx = xx < 0 ? 0 : xx >= width ? width - 1 : xx;
                    yy = yy < 0 ? 0 : yy >= height ? height - 1 : yy;
                    acc += w[k + R] / sum * plane[(size_t)yy * width + xx];
                }
                tmp[(size_t)y * width + x] = (float)acc;
            }
        memcpy(plane, tmp, (size_t)width * height * sizeof(float));
    }
    free(tmp);
    return 0;
}

/* Ring means (rings 1..n/16, n/4..n/2) of the first channel's radial
 * spectrum, or of its remap_tri, over white noise's level `white`. */
static int ring_powers(const blue_noise_texture *blue, int remapped, double white, double *low, double *high,
                       gt_error *e)
{
    int n = blue->size;
    double *v = malloc((size_t)n * n * sizeof(double)), p[1025];
    if (!v)
        return gt_error_set(e, "dither", "out of memory");
    for (size_t i = 0; i < (size_t)n * n; ++i)
        v[i] = remapped ? dither_remap_triangular(blue->values[i]) : blue->values[i];
    int rc = dither_radial_power_spectrum(v, n, p, e);
    *low = *high = 0.0;
    for (int k = 1; k <= n / 16; ++k)
        *low += p[k] / (n / 16) / white;
    for (int k = n / 4; k <= n / 2; ++k)
        *high += p[k] / (n / 2 - n / 4 + 1) / white;
    free(v);
    return rc;
}

static int blue_noise_spectrum(const blue_noise_texture *blue, dither_result *out, gt_error *e)
{
    return ring_powers(blue, 0, 1.0 / 12.0, &out->blue_low_ring_power, &out->blue_high_ring_power, e) ||
           ring_powers(blue, 1, 1.0 / 6.0, &out->remapped_low_ring_power, &out->remapped_high_ring_power, e);
}

int dither_blue_noise(const char *dir, const dither_request *rq, blue_noise_texture *blue, dither_result *out,
                      gt_error *e)
{
    char stem[4200];
    double t0 = seconds_now();
    if (blue_noise_build(rq->blue_noise_size, 4, rq->seed, blue, e) != 0)
        return -1;
    out->blue_noise_seconds = seconds_now() - t0;
    snprintf(stem, sizeof stem, "%s/blue_noise_%d", dir, rq->blue_noise_size);
    if (blue_noise_write(blue, stem, e) == 0 && blue_noise_spectrum(blue, out, e) == 0)
        return 0;
    blue_noise_free(blue);
    return -1;
}

/* Worst bias and extreme variances (in local spacings) over 32 bins of x / ulp's fraction. */
static void small_float_row(dither_kind kind, unsigned seed, dither_small_float_row *row)
{
    enum { BINS = 32, SAMPLES = 200000 };
    double sum[BINS] = {0}, sum_sq[BINS] = {0};
    long count[BINS] = {0};
    for (int i = 0; i < SAMPLES; ++i) {
        double x = 0.5 + 3.5 * (i + 0.5) / SAMPLES, ulp = dither_small_float_ulp(x, 6);
        double d = dither_value(kind, blue_noise_uniform(seed, 2 * i), blue_noise_uniform(seed, 2 * i + 1));
        double err = (dither_small_float(x + (d - 0.5) * ulp, 6) - x) / ulp, f = x / ulp - floor(x / ulp);
        int b = (int)(f * BINS);
        sum[b] += err, sum_sq[b] += err * err, ++count[b];
    }
    row->kind = dither_kind_name(kind);
    row->worst_bias = 0.0, row->worst_variance = 0.0, row->best_variance = INFINITY;
    for (int b = 0; b < BINS; ++b) {
        double m = sum[b] / count[b], v = sum_sq[b] / count[b] - m * m;
        row->worst_bias = fmax(row->worst_bias, fabs(m));
        row->worst_variance = fmax(row->worst_variance, v), row->best_variance = fmin(row->best_variance, v);
    }
}

void dither_small_float_rows(unsigned seed, dither_small_float_row rows[DITHER_SMALL_FLOAT_ROWS])
{
    static const dither_kind kinds[DITHER_SMALL_FLOAT_ROWS] = {DITHER_NONE, DITHER_RPDF, DITHER_TPDF_SUM};
    for (int k = 0; k < DITHER_SMALL_FLOAT_ROWS; ++k)
        small_float_row(kinds[k], seed, &rows[k]);
}
