/* The mean of n independent observations and the standard error of that
 * mean, s / sqrt(n) with s^2 the unbiased sample variance (two passes: no
 * cancellation). */
#ifndef GTLAB_CORE_SAMPLE_MEAN_H
#define GTLAB_CORE_SAMPLE_MEAN_H

/* *se is NaN for n < 2. */
void sample_mean_se(const double *x, int n, double *mean, double *se);

#endif
