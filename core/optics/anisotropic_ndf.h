/* Anisotropic normal distribution functions, normalised as microfacet NDFs:
 *
 *   int_{H^2} D(m) (m.n) dm = 1                         (Walter et al. 2007, eq. 4)
 *
 * with n = +z, the tangent along x (roughness alpha_x) and the bitangent
 * along y (alpha_y). For m = (x, y, z), z > 0, tan^2 theta = (x^2 + y^2) / z^2:
 *
 *   Ward (Ward 1992, "Measuring and Modeling Anisotropic Reflection", eq. 5a's
 *   distribution; Walter 2005, "Notes on the Ward BRDF", eq. 4):
 *     D(m) = exp(-(x^2/alpha_x^2 + y^2/alpha_y^2) / z^2) / (pi alpha_x alpha_y z^4)
 *
 *   GGX / Trowbridge-Reitz (Heitz 2014, "Understanding the Masking-Shadowing
 *   Function", eq. 85):
 *     D(m) = 1 / (pi alpha_x alpha_y (x^2/alpha_x^2 + y^2/alpha_y^2 + z^2)^2)
 *
 * Both normalisations are exact: with t = tan theta the projected-area
 * integral becomes int_0^2pi int_0^inf f(t^2 a(phi)) t dt dphi / (pi alpha_x
 * alpha_y), a(phi) = cos^2 phi/alpha_x^2 + sin^2 phi/alpha_y^2, and
 * int_0^2pi dphi / a(phi) = 2 pi alpha_x alpha_y. With alpha_x = alpha_y = alpha
 * the GGX form is core/optics/ggx.h's ggx_ndf. D = 0 for z <= 0. */
#ifndef GTLAB_CORE_OPTICS_ANISOTROPIC_NDF_H
#define GTLAB_CORE_OPTICS_ANISOTROPIC_NDF_H

#include <math.h>

/* Strict C11 <math.h> does not define it. */
#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

typedef enum { NDF_WARD = 0, NDF_GGX } ndf_kind;

typedef struct {
    ndf_kind kind;
    double alpha_x, alpha_y; /* > 0 */
} anisotropic_ndf;

/* D(m) for a unit microfacet normal m. */
double anisotropic_ndf_evaluate(const anisotropic_ndf *ndf, const double m[3]);

/* A microfacet normal m with density D(m) (m.n) per unit solid angle, from
 * u in [0, 1)^2. Both NDFs share the azimuth's marginal density
 * 1 / (2 pi alpha_x alpha_y a(phi)), inverted by phi = atan2(alpha_y sin 2 pi u1,
 * alpha_x cos 2 pi u1); given phi, x = a(phi) tan^2 theta has the CDF
 * 1 - exp(-x) (Ward: x = -log(1 - u0); Walter 2005, eq. 6) or
 * 1 - 1/(1 + x) (GGX: x = u0 / (1 - u0)). */
void anisotropic_ndf_sample(const anisotropic_ndf *ndf, const double u[2], double m[3]);

/* "ward" or "ggx". */
const char *ndf_kind_name(ndf_kind kind);

#endif
