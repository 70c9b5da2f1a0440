#include "core/sample_mean.h"

#include <math.h>

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
