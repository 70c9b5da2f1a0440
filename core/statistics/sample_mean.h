/* The mean of n independent observations and the standard error of that
 * mean, s / sqrt(n) with s^2 the unbiased sample variance (two passes: no
 * cancellation). */
#ifndef GTLAB_CORE_STATISTICS_SAMPLE_MEAN_H
#define GTLAB_CORE_STATISTICS_SAMPLE_MEAN_H

/* *se is NaN for n < 2. */
void sample_mean_se(const double *x, int n, double *mean, double *se);

/* The two-sided 95% quantile of Student's t with `dof` degrees of freedom
 * (t_{0.975, dof}): what a mean of dof + 1 observations divided by its own
 * standard error must exceed. Tabulated to 3 decimals for dof <= 30
 * (Abramowitz and Stegun 1964, table 26.10), beyond by the Cornish-Fisher
 * expansion to second order, z + (z^3 + z) / (4 dof) + (5 z^5 + 16 z^3 +
 * 3 z) / (96 dof^2), z = 1.959964 (within 1e-4 there; A&S 26.7.5);
 * +infinity for dof < 1. */
double student_t_975(int dof);

#endif
