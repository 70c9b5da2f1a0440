/* CIEDE2000 of sRGB colours through Little CMS against what it must give:
 * 0 for equal colours; 100 between white and black (a pure lightness
 * difference of 100 at mean L* 50, where S_L = 1); symmetric; and, for two
 * greys, the lightness difference divided by S_L (Sharma, Wu and Dalal 2005,
 * eq. 17-18: no chroma or hue term), with L* from the CIE formula of the
 * sRGB luminance. */
#include <math.h>

#include "metrics/color_difference.h"
#include "tests/check.h"

static double srgb_to_linear(double v)
{
    return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
}

static double lightness(double y)
{
    return y > 216.0 / 24389.0 ? 116.0 * cbrt(y) - 16.0 : y * 24389.0 / 27.0;
}

int main(void)
{
    gt_error e;
    color_difference *cd = color_difference_create(&e);
    CHECK(cd != NULL);
    double a[6] = {1, 1, 1, 0.2, 0.5, 0.7}, b[6] = {0, 0, 0, 0.2, 0.5, 0.7}, d[2], r[2];
    color_difference_ciede2000(cd, a, b, 2, d);
    color_difference_ciede2000(cd, b, a, 2, r);
    CHECK_NEAR(d[0], 100.0, 0.05);
    CHECK(d[1] == 0.0 && r[0] == d[0]);
    double g1 = 0.3, g2 = 0.6, x[3] = {g1, g1, g1}, y[3] = {g2, g2, g2}, dg;
    color_difference_ciede2000(cd, x, y, 1, &dg);
    double l1 = lightness(srgb_to_linear(g1)), l2 = lightness(srgb_to_linear(g2)), lm = 0.5 * (l1 + l2);
    double sl = 1.0 + 0.015 * (lm - 50) * (lm - 50) / sqrt(20.0 + (lm - 50) * (lm - 50));
    CHECK_NEAR(dg, (l2 - l1) / sl, 0.05);
    color_difference_free(cd);
    return check_report("metrics_color_difference");
}
