/* Gamma-vs-linear precision and HDR lower bounds (hdr_precision.h). */
#include "hdr_precision/hdr_precision.h"

#include <math.h>

#include "core/optics/srgb.h" /* linear_to_srgb: the one sRGB encode */

double gamma_equal_precision_point(double gamma)
{
    return pow(gamma, -gamma / (gamma - 1.0));
}

double srgb_encode(double x)
{
    return linear_to_srgb(x);
}

double srgb_equal_precision_point(void)
{
    return pow(1.055 / 2.4, 2.4 / 1.4);
}

double tonemap_exponential(double c, double l)
{
    return 1.0 - exp(-c / l);
}

double tonemap_filmic_display(double c, double l)
{
    double x = fmax(0.0, c / l - 0.004);
    return x * (6.2 * x + 0.5) / (x * (6.2 * x + 1.7) + 0.06);
}

double tonemap_filmic_transcribed_display(double c, double l)
{
    double x = fmax(0.0, c / l - 0.004);
    return x * (6.2 * x + 0.5) / (x * (6.2 * (x + 1.7)) + 0.06);
}

double exponential_c_min(double l, double y)
{
    return -l * log1p(-y);
}

double filmic_c_min(double l, double y)
{
    double d = pow(y, 1.0 / 2.2), a = 6.2 * (1.0 - d), b = 0.5 - 1.7 * d, c = -0.06 * d;
    double x = (-b + sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
    return l * (x + 0.004);
}

double tonemap_c_min_bisection(double (*t)(double c, double l), int linear, double l, double y)
{
    double lo = 0.0, hi = 16.0 * l;
    for (int i = 0; i < 60; ++i) {
        double mid = 0.5 * (lo + hi), v = t(mid, l);
        if (linear)
            v = pow(v, 2.2);
        if (v < y)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}
