/* How many paired cases would decide a paired comparison: the power of the
 * paired t-test (two-sided, 95%), in the approximation that replaces the
 * noncentral t by Student's t quantiles (Guenther 1981, "Sample size
 * formulas for normal theory t tests", The American Statistician 35(4)):
 * with n cases, a true mean difference delta and a per-case spread sigma
 * (the standard deviation of one case's difference) are detected with
 * probability `power` when
 *     (t_{0.975, n-1} + t_{power, n-1}) sigma / sqrt(n) <= |delta|.
 * The smallest such n is what a "not significant" row needs; for large n it
 * tends to the normal closed form n = ((z_0.975 + z_power) sigma / delta)^2.
 * Student's quantiles are GSL's (gsl_cdf_tdist_Pinv). */
#ifndef GTLAB_CORE_STATISTICS_PAIRED_POWER_H
#define GTLAB_CORE_STATISTICS_PAIRED_POWER_H

/* Student's t quantile: P(T_dof <= t) = p. */
double student_t_quantile(double p, int dof);

/* The smallest n >= 2 for which the paired t-test detects a mean
 * difference `effect` with per-case spread `spread` with probability
 * `power` (0.5 <= power < 1); -1 if no n <= max_cases does, or if effect
 * is 0 or either argument is not a finite number. */
int paired_cases_needed(double effect, double spread, double power, int max_cases);

#endif
