#include "core/statistics/sample_mean.h"

#include <math.h>

double student_t_975(int dof)
{
    static const double table[31] = {INFINITY, 12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                     2.201,    2.179,  2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080,
                                     2.074,    2.069,  2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
    const double z = 1.959963984540054;
    if (dof < 1)
        return INFINITY;
    double z3 = z * z * z, z5 = z3 * z * z, n = dof;
    return dof <= 30 ? table[dof] : z + (z3 + z) / (4.0 * n) + (5.0 * z5 + 16.0 * z3 + 3.0 * z) / (96.0 * n * n);
}

void sample_mean_se(const double *x, int n, double *mean, double *se)
{
    double sum = 0.0, sq = 0.0;
    for (int i = 0; i < n; ++i)
        sum += x[i];
    *mean = n > 0 ? sum / n : NAN;
    for (int i = 0; i < n; ++i)
        sq += (x[i] - *mean) * (x[i] - *mean);
    *se = n > 1 ? sqrt(sq / (n - 1) / n) : NAN;
}
