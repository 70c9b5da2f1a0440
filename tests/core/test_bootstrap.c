/* The bootstrap standard error against the bootstrap's own closed forms
 * (the B -> infinity limit of core/statistics/bootstrap.c's resampling):
 *   - the mean: se = sqrt(sum (x_i - mean)^2 / n) / sqrt(n) (the plug-in
 *     variance over n);
 *   - the nearest-rank quantile, the k-th smallest of a resample: it is at
 *     most x_(j) iff at least k of the n draws are, so
 *     P(X*_(k) <= x_(j)) = P(Binomial(n, j/n) >= k), whose distribution gives
 *     the exact bootstrap variance.
 * With B = 20000 resamples se_B scatters by about 1/sqrt(2B) = 0.5 % (a bit
 * more for the quantile's lumpy distribution): 4 % is several of its own
 * standard errors. */
#include <math.h>

#include "core/statistics/bootstrap.h"
#include "tests/check.h"

enum { N = 48, B = 20000 };

static double statistic_mean(double *values, int n, const void *context)
{
    (void)context;
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        sum += values[i];
    return sum / n;
}

/* P(Binomial(n, q) >= k). */
static double binomial_tail(int n, double q, int k)
{
    double sum = 0.0;
    for (int m = k; m <= n; ++m)
        sum += exp(lgamma(n + 1.0) - lgamma(m + 1.0) - lgamma(n - m + 1.0) + m * log(q) + (n - m) * log1p(-q));
    return q >= 1.0 ? 1.0 : sum;
}

/* The exact bootstrap standard error of the k-th smallest of sorted x. */
static double exact_order_statistic_se(const double *sorted, int n, int k)
{
    double mean = 0.0, square = 0.0, below = 0.0;
    for (int j = 1; j <= n; ++j) {
        double at_most = binomial_tail(n, (double)j / n, k), p = at_most - below;
        mean += p * sorted[j - 1], square += p * sorted[j - 1] * sorted[j - 1], below = at_most;
    }
    return sqrt(square - mean * mean);
}

int main(void)
{
    double x[N], plug_in = 0.0, mean = 0.0;
    for (int i = 0; i < N; ++i)
        x[i] = exp(0.1 * i) - 1.0; /* skewed, like errors */
    for (int i = 0; i < N; ++i)
        mean += x[i] / N;
    for (int i = 0; i < N; ++i)
        plug_in += (x[i] - mean) * (x[i] - mean) / N;
    double se_mean = bootstrap_standard_error(x, N, statistic_mean, NULL, B, 7);
    CHECK(fabs(se_mean / sqrt(plug_in / N) - 1.0) < 0.04);

    double p = 0.95;
    double se_q = bootstrap_standard_error(x, N, bootstrap_quantile, &p, B, 11);
    double exact = exact_order_statistic_se(x, N, 46); /* ceil(0.95 x 48) */
    CHECK(fabs(se_q / exact - 1.0) < 0.04);
    CHECK(se_q == bootstrap_standard_error(x, N, bootstrap_quantile, &p, B, 11)); /* the seed fixes it */

    double y[5] = {5, 1, 3, 2, 4};
    CHECK(quantile_nearest_rank(y, 5, 0.95) == 5.0 && quantile_nearest_rank(y, 5, 0.5) == 3.0);
    CHECK(quantile_nearest_rank(y, 5, 0.2) == 1.0);
    CHECK(isnan(bootstrap_standard_error(x, 1, statistic_mean, NULL, B, 7)));
    return check_report("core_bootstrap");
}
