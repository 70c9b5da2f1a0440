/* Noise-corrected RMSE; see noise_corrected.h. */
#include "metrics/noise_corrected.h"

#include <math.h>

#include "metrics/image_error.h"

double noise_mean_variance(const float *stderr_plane, const float *mask, size_t count)
{
    double sum = 0;
    size_t inside = 0;
    for (size_t i = 0; stderr_plane && i < count; ++i)
        if (metrics_in_mask(mask, i)) {
            sum += (double)stderr_plane[i] * stderr_plane[i];
            ++inside;
        }
    return inside ? sum / inside : 0.0;
}

double noise_corrected_rmse(double rmse, double mean_variance)
{
    return sqrt(fmax(rmse * rmse - mean_variance, 0.0));
}

double noise_budget_for_rmse(double figure, double margin)
{
    if (!(margin > 0.0))
        return 0.0;
    double f = fmax(figure, 0.0), quarter = 0.25 * margin;
    return sqrt((f + quarter) * (f + quarter) - f * f);
}

double noise_budget_for_measured_rmse(double measured, double noise_rmse, double margin)
{
    return noise_budget_for_rmse(noise_corrected_rmse(measured, noise_rmse * noise_rmse), margin);
}

double noise_inflation_of_rmse(double figure, double noise_rmse)
{
    double f = fmax(figure, 0.0);
    return sqrt(f * f + noise_rmse * noise_rmse) - f;
}
