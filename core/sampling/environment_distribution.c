#include "core/sampling/environment_distribution.h"

#include <stdlib.h>
#include <string.h>

int distribution_1d_init(distribution_1d *d, const double *weights, int count, gt_error *e)
{
    memset(d, 0, sizeof *d);
    d->cdf = malloc(sizeof(double) * (size_t)(count + 1));
    d->guide = malloc(sizeof(int) * (size_t)count);
    if (!d->cdf || !d->guide) {
        distribution_1d_free(d);
        return gt_error_set(e, "distribution", "out of memory for %d bins", count);
    }
    d->count = count;
    double running = 0.0;
    d->cdf[0] = 0.0;
    for (int i = 0; i < count; ++i)
        d->cdf[i + 1] = running += weights[i];
    d->total = running;
    /* Bins after the last positive one hold running == total: exactly 1. */
    for (int i = 1; i <= count; ++i)
        d->cdf[i] = running > 0.0 ? d->cdf[i] / running : (double)i / count;
    d->cdf[count] = 1.0;
    for (int j = 0, i = 0; j < count; ++j) {
        while (d->cdf[i + 1] <= (double)j / count)
            ++i;
        d->guide[j] = i;
    }
    return 0;
}

void distribution_1d_free(distribution_1d *d)
{
    free(d->cdf);
    free(d->guide);
    memset(d, 0, sizeof *d);
}

const int *distribution_1d_guide_of(const distribution_1d *d, double u)
{
    int j = (int)(u * d->count);
    return &d->guide[j < 0 ? 0 : (j < d->count ? j : d->count - 1)];
}

/* The i with cdf_i <= u < cdf_{i+1}, walking up from `lo`: never a bin of
 * weight 0. */
int distribution_1d_sample_from(const distribution_1d *d, double u, int lo, double *offset)
{
    while (lo < d->count - 1 && d->cdf[lo + 1] <= u)
        ++lo;
    if (offset) {
        double width = d->cdf[lo + 1] - d->cdf[lo];
        double t = width > 0.0 ? (u - d->cdf[lo]) / width : 0.0;
        *offset = t < 0.0 ? 0.0 : (t < 1.0 ? t : 0x1.fffffffffffffp-1);
    }
    return lo;
}

int distribution_1d_sample(const distribution_1d *d, double u, double *offset)
{
    return distribution_1d_sample_from(d, u, *distribution_1d_guide_of(d, u), offset);
}

double distribution_1d_probability(const distribution_1d *d, int i)
{
    return d->cdf[i + 1] - d->cdf[i];
}

int distribution_2d_init(distribution_2d *d, const double *weights, int rows, int columns, gt_error *e)
{
    memset(d, 0, sizeof *d);
    double *row_sums = malloc(sizeof(double) * (size_t)rows);
    d->conditional = calloc((size_t)rows, sizeof *d->conditional);
    if (!row_sums || !d->conditional) {
        free(row_sums);
        free(d->conditional);
        return gt_error_set(e, "distribution", "out of memory for %d rows", rows);
    }
    d->rows = rows, d->columns = columns;
    int rc = 0;
    for (int r = 0; r < rows && rc == 0; ++r) {
        rc = distribution_1d_init(&d->conditional[r], weights + (size_t)r * columns, columns, e);
        row_sums[r] = d->conditional[r].total;
    }
    if (rc == 0)
        rc = distribution_1d_init(&d->marginal, row_sums, rows, e);
    free(row_sums);
    if (rc != 0)
        distribution_2d_free(d);
    return rc;
}

void distribution_2d_free(distribution_2d *d)
{
    for (int r = 0; d->conditional && r < d->rows; ++r)
        distribution_1d_free(&d->conditional[r]);
    free(d->conditional);
    distribution_1d_free(&d->marginal);
    memset(d, 0, sizeof *d);
}

void distribution_2d_sample(const distribution_2d *d, const double u[2], int *row, int *column, double offset[2])
{
    *row = distribution_1d_sample(&d->marginal, u[0], &offset[0]);
    *column = distribution_1d_sample(&d->conditional[*row], u[1], &offset[1]);
}

double distribution_2d_probability(const distribution_2d *d, int row, int column)
{
    return distribution_1d_probability(&d->marginal, row) *
           distribution_1d_probability(&d->conditional[row], column);
}
