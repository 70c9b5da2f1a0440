/* Errors measured against a Monte Carlo reference, with the reference's own
 * noise taken out.
 *
 * A reference pixel is r_i = t_i + n_i, the truth plus zero-mean noise of
 * variance s_i^2 (its standard error squared), independent of the image a
 * compared with it. Then E[(a_i - r_i)^2] = (a_i - t_i)^2 + s_i^2, so over
 * the mask
 *     E[RMSE(a, r)^2] = RMSE(a, t)^2 + mean_i s_i^2,
 * and RMSE(a, t) ~ sqrt(max(RMSE(a, r)^2 - mean_i s_i^2, 0)). Two noisy
 * references compared with each other add both mean variances. */
#ifndef GTLAB_METRICS_NOISE_CORRECTED_H
#define GTLAB_METRICS_NOISE_CORRECTED_H

#include <stddef.h>

/* Mean of stderr_i^2 over the pixels inside the mask (metrics_in_mask; NULL:
 * every pixel): the reference's noise in RMSE^2 units. 0 when stderr is NULL
 * (a reference without a standard error) or no pixel is inside the mask. */
double noise_mean_variance(const float *stderr_plane, const float *mask, size_t count);

/* sqrt(max(rmse^2 - mean_variance, 0)): the RMSE against the truth estimated
 * from the RMSE against a noisy reference; 0 when the measured error is
 * within the noise. */
double noise_corrected_rmse(double rmse, double mean_variance);

/* The noise budget of an RMSE figure (docs/claims-protocol.md, "Noise
 * budgets"): by the identity above, a reference whose noise RMSE is n shows
 * an error of true RMSE f as sqrt(f^2 + n^2), inflated by
 * sqrt(f^2 + n^2) - f. The largest n that inflates f by at most a quarter of
 * the visible margin m is
 *     n_max = sqrt((f + m/4)^2 - f^2) = sqrt(f m / 2 + m^2 / 16),
 * the most noise a reference may have for a figure f to be read to within
 * m/4. (A paired difference of squared errors against one reference is not
 * biased at all: both sides gain the same mean variance.) 0 for m <= 0. */
double noise_budget_for_rmse(double figure, double margin);

/* The budget of a figure measured against the noisy reference itself: its
 * true RMSE estimated first (noise_corrected_rmse with noise_rmse^2), then
 * noise_budget_for_rmse of that. */
double noise_budget_for_measured_rmse(double measured, double noise_rmse, double margin);

/* How much a reference of noise RMSE n inflates a figure of true RMSE f:
 * sqrt(f^2 + n^2) - f. */
double noise_inflation_of_rmse(double figure, double noise_rmse);

#endif
