/* Anisotropic Ward and GGX normal distributions (see the header). */
#include "core/optics/anisotropic_ndf.h"

#include <math.h>

/* x^2/alpha_x^2 + y^2/alpha_y^2: the slope-space radius squared times z^2. */
static double stretched_slope2(const anisotropic_ndf *ndf, const double m[3])
{
    double sx = m[0] / ndf->alpha_x, sy = m[1] / ndf->alpha_y;
    return sx * sx + sy * sy;
}

static double ward_ndf(const anisotropic_ndf *ndf, const double m[3])
{
    double z2 = m[2] * m[2];
    return exp(-stretched_slope2(ndf, m) / z2) / (M_PI * ndf->alpha_x * ndf->alpha_y * z2 * z2);
}

static double ggx_aniso_ndf(const anisotropic_ndf *ndf, const double m[3])
{
    double q = stretched_slope2(ndf, m) + m[2] * m[2];
    return 1.0 / (M_PI * ndf->alpha_x * ndf->alpha_y * q * q);
}

double anisotropic_ndf_evaluate(const anisotropic_ndf *ndf, const double m[3])
{
    if (m[2] <= 0.0)
        return 0.0;
    return ndf->kind == NDF_WARD ? ward_ndf(ndf, m) : ggx_aniso_ndf(ndf, m);
}

void anisotropic_ndf_sample(const anisotropic_ndf *ndf, const double u[2], double m[3])
{
    double psi = 2.0 * M_PI * u[1];
    double phi = atan2(ndf->alpha_y * sin(psi), ndf->alpha_x * cos(psi));
    double c = cos(phi), s = sin(phi);
    double a = c * c / (ndf->alpha_x * ndf->alpha_x) + s * s / (ndf->alpha_y * ndf->alpha_y);
    double x = ndf->kind == NDF_WARD ? -log1p(-u[0]) : u[0] / (1.0 - u[0]);
    double tan2 = x / a, cos_theta = 1.0 / sqrt(1.0 + tan2), sin_theta = sqrt(tan2) * cos_theta;
    m[0] = sin_theta * c;
    m[1] = sin_theta * s;
    m[2] = cos_theta;
}

const char *ndf_kind_name(ndf_kind kind) { return kind == NDF_WARD ? "ward" : "ggx"; }
