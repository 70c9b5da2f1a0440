/* Pixelwise error statistics; see image_error.h. */
#include "metrics/image_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int image_error_compute(const float *a, const float *b, const float *mask, int width, int height, const char *what,
                        image_error_stats *out, gt_error *e)
{
    size_t n = (size_t)width * (size_t)height, count = 0, max_i = 0;
    double sum_sq = 0.0, sum_abs = 0.0, max_abs = -1.0, sum_a = 0.0, sum_b = 0.0;
    for (size_t i = 0; i < n; ++i) {
        if (!metrics_in_mask(mask, i))
            continue;
        double d = (double)a[i] - (double)b[i], ad = fabs(d);
        sum_sq += d * d;
        sum_abs += ad;
        sum_a += a[i];
        sum_b += b[i];
        if (ad > max_abs) {
            max_abs = ad;
            max_i = i;
        }
        count++;
    }
    if (count == 0)
        return gt_error_set(e, what, "no pixel to compare: the mask is empty");
    out->pixels = count;
    out->rmse = sqrt(sum_sq / (double)count);
    out->mean_abs = sum_abs / (double)count;
    out->max_abs = max_abs;
    out->max_x = (int)(max_i % (size_t)width);
    out->max_y = (int)(max_i / (size_t)width);
    out->mean_a = sum_a / (double)count;
    out->mean_b = sum_b / (double)count;
    return 0;
}

static int compare_floats(const void *x, const void *y)
{
    float u = *(const float *)x, v = *(const float *)y;
    return (u > v) - (u < v);
}

int metrics_percentile(const float *values, const float *mask, size_t count, double p, const char *what,
                       float *out, gt_error *e)
{
    if (!(p > 0.0 && p <= 100.0))
        return gt_error_set(e, what, "percentile %g is outside (0, 100]", p);
    size_t n = 0;
    for (size_t i = 0; i < count; ++i)
        n += (size_t)(metrics_in_mask(mask, i) && !isnan(values[i]));
    if (n == 0)
        return gt_error_set(e, what, "no value inside the mask");
    float *sorted = malloc(sizeof *sorted * n);
    if (!sorted)
        return gt_error_set(e, what, "out of memory");
    size_t k = 0;
    for (size_t i = 0; i < count; ++i)
        if (metrics_in_mask(mask, i) && !isnan(values[i]))
            sorted[k++] = values[i];
    qsort(sorted, n, sizeof *sorted, compare_floats);
    size_t rank = (size_t)ceil(p * (double)n / 100.0); /* 1-based */
    *out = sorted[(rank < 1 ? 1 : rank) - 1];
    free(sorted);
    return 0;
}
