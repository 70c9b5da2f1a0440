/* Gamma-vs-linear precision and the HDR lower bounds against independent
 * computations:
 * - at x*, the code step of gamma space equals linear's: the derivative of
 *   the encode, by central differences, is 1 (power curve and sRGB), and it
 *   is above 1 below x* (gamma finer) and below 1 above; no exponent of
 *   the power curve gives the talk's 5/11 (x* < 1/e for every gamma > 1);
 * - the closed-form c_min of both tone mappers equals bisection on T, and
 *   T(c_min) is the threshold 1/510;
 * - the exponential bound is l ln(510/509), the positive magnitude of the
 *   slide's "-l ln(510/509)". */
#include <math.h>

#include "hdr_precision/hdr_precision.h"
#include "tests/check.h"

static double power_encode(double x) { return pow(x, 1.0 / 2.2); }

static double derivative(double (*f)(double), double x)
{
    double h = 1e-6 * x;
    return (f(x + h) - f(x - h)) / (2.0 * h);
}

/* No exponent of the power curve puts the equal-precision point at the
 * talk's 5/11 in linear (the talk names no exponent there): for every
 * gamma in (1, 10] the point, checked as the place where the encode's
 * derivative x^(1/g - 1) / g is 1, lies below its limit 1/e as gamma -> 1,
 * and falls as gamma grows. */
static void test_no_exponent_gives_five_elevenths(void)
{
    double previous = 1.0;
    for (double g = 1.01; g <= 10.0; g += 0.01) {
        double x = gamma_equal_precision_point(g);
        CHECK_NEAR(pow(x, 1.0 / g - 1.0) / g, 1.0, 1e-9);
        CHECK(x < exp(-1.0) && x < previous);
        previous = x;
    }
    CHECK(exp(-1.0) < 5.0 / 11.0 - 0.08);
}

static double filmic_linear(double c, double l) { return pow(tonemap_filmic_display(c, l), 2.2); }

int main(void)
{
    test_no_exponent_gives_five_elevenths();
    double x22 = gamma_equal_precision_point(2.2), xs = srgb_equal_precision_point();
    CHECK_NEAR(derivative(power_encode, x22), 1.0, 1e-7);
    CHECK_NEAR(derivative(srgb_encode, xs), 1.0, 1e-7);
    CHECK(derivative(power_encode, 0.8 * x22) > 1.0 && derivative(power_encode, 1.25 * x22) < 1.0);
    CHECK(derivative(srgb_encode, 0.8 * xs) > 1.0 && derivative(srgb_encode, 1.25 * xs) < 1.0);
    const double ls[] = {0.05, 0.18, 1.0, 7.5};
    for (int i = 0; i < 4; ++i) {
        double l = ls[i], y = HDR_DISPLAY_THRESHOLD;
        double ce = exponential_c_min(l, y), cf = filmic_c_min(l, y);
        CHECK_NEAR(ce, tonemap_c_min_bisection(tonemap_exponential, 0, l, y), 1e-12 * l);
        CHECK_NEAR(cf, tonemap_c_min_bisection(tonemap_filmic_display, 1, l, y), 1e-12 * l);
        CHECK_NEAR(tonemap_exponential(ce, l), y, 1e-15);
        CHECK_NEAR(filmic_linear(cf, l), y, 1e-13);
        CHECK_NEAR(ce, l * log(510.0 / 509.0), 1e-15 * l);
    }
    /* the slide's denominator is another curve: its bound differs */
    CHECK(fabs(tonemap_c_min_bisection(tonemap_filmic_transcribed_display, 1, 1.0, HDR_DISPLAY_THRESHOLD) -
               filmic_c_min(1.0, HDR_DISPLAY_THRESHOLD)) > 0.01);
    return check_report("test_hdr_precision");
}
