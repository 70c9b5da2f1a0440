#include "core/statistics/paired_power.h"

#include <gsl/gsl_cdf.h>
#include <math.h>

double student_t_quantile(double p, int dof) { return gsl_cdf_tdist_Pinv(p, (double)dof); }

/* Guenther's condition at n cases. */
static int detects(double effect, double spread, double power, int n)
{
    double t = student_t_quantile(0.975, n - 1) + student_t_quantile(power, n - 1);
    return t * spread / sqrt((double)n) <= fabs(effect);
}

int paired_cases_needed(double effect, double spread, double power, int max_cases)
{
    if (!isfinite(effect) || !isfinite(spread) || effect == 0.0 || !(power >= 0.5 && power < 1.0))
        return -1;
    if (spread <= 0.0)
        return 2;
    /* the condition's left side falls with n: bisect on [2, max_cases] */
    if (max_cases < 2 || !detects(effect, spread, power, max_cases))
        return -1;
    int lo = 1, hi = max_cases; /* detects(hi); lo fails (or is below 2) */
    while (hi - lo > 1) {
        int mid = lo + (hi - lo) / 2;
        if (mid >= 2 && detects(effect, spread, power, mid))
            hi = mid;
        else
            lo = mid;
    }
    return hi;
}
