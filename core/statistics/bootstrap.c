/* The bootstrap standard error; see bootstrap.h. */
#include "core/statistics/bootstrap.h"

#include <math.h>
#include <stdlib.h>

#include "core/sampling/splitmix64.h"

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double quantile_nearest_rank(double *x, int n, double p)
{
    qsort(x, (size_t)n, sizeof *x, compare_doubles);
    int rank = (int)ceil(p * n);
    return x[(rank < 1 ? 1 : rank) - 1];
}

double bootstrap_quantile(double *values, int n, const void *context)
{
    return quantile_nearest_rank(values, n, *(const double *)context);
}

/* One resample of x into out, drawn from the stream's state. */
static void resample(const double *x, int n, double *out, unsigned long long *state)
{
    for (int i = 0; i < n; ++i) {
        int k = (int)(splitmix64_uniform01(state) * n);
        out[i] = x[k < n ? k : n - 1];
    }
}

/* The sample standard deviation of t[0..m), two passes. */
static double sample_deviation(const double *t, int m)
{
    double mean = 0.0, sum = 0.0;
    for (int b = 0; b < m; ++b)
        mean += t[b];
    mean /= m;
    for (int b = 0; b < m; ++b)
        sum += (t[b] - mean) * (t[b] - mean);
    return sqrt(sum / (m - 1));
}

double bootstrap_standard_error(const double *x, int n, bootstrap_statistic statistic, const void *context,
                                int resamples, unsigned long long seed)
{
    if (n < 2 || resamples < 2)
        return NAN;
    double *scratch = malloc(sizeof *scratch * (size_t)n), *t = malloc(sizeof *t * (size_t)resamples);
    if (!scratch || !t) {
        free(scratch), free(t);
        return -1.0;
    }
    unsigned long long state = seed;
    for (int b = 0; b < resamples; ++b) {
        resample(x, n, scratch, &state);
        t[b] = statistic(scratch, n, context);
    }
    double se = sample_deviation(t, resamples);
    free(scratch), free(t);
    return se;
}
