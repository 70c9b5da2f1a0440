/* The bootstrap standard error of a statistic (Efron and Tibshirani 1993,
 * "An Introduction to the Bootstrap", Algorithm 6.1): draw B samples of size
 * n from the n observations with replacement, evaluate the statistic on each,
 * and take the sample standard deviation of the B values,
 *
 *     se_B = sqrt( sum_b (t*_b - mean t*)^2 / (B - 1) ).
 *
 * It is what gtlab reports where a figure is not a mean (a percentile of
 * errors at random points, say) and no closed-form standard error applies.
 * The resamples come from splitmix64 (core/sampling/splitmix64.h) from `seed`, so the
 * figure is the same on every run and machine. */
#ifndef GTLAB_CORE_STATISTICS_BOOTSTRAP_H
#define GTLAB_CORE_STATISTICS_BOOTSTRAP_H

/* A statistic of n values; it may reorder them (they are a scratch copy). */
typedef double (*bootstrap_statistic)(double *values, int n, const void *context);

/* se_B of `statistic` over x[0..n) from `resamples` resamples (B >= 2).
 * Returns NaN for n < 2 and -1 when out of memory. */
double bootstrap_standard_error(const double *x, int n, bootstrap_statistic statistic, const void *context,
                                int resamples, unsigned long long seed);

/* The nearest-rank p-quantile (0 < p <= 1) of x[0..n): the ceil(p n)-th
 * smallest value. Sorts x. */
double quantile_nearest_rank(double *x, int n, double p);

/* A bootstrap_statistic: quantile_nearest_rank at *(const double *)context. */
double bootstrap_quantile(double *values, int n, const void *context);

#endif
