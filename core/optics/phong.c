#include "core/optics/phong.h"

#include <math.h>

#include "core/vec3.h" /* M_PI */

double phong_exponent(double alpha)
{
    alpha = fmax(alpha, 1e-4);
    return 2.0 / (alpha * alpha) - 2.0;
}

double phong_ndf(double cos_m, double p) { return cos_m > 0.0 ? (p + 2.0) / (2.0 * M_PI) * pow(cos_m, p) : 0.0; }
