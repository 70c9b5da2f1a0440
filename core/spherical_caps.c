#include "core/spherical_caps.h"

#include <math.h>

#include "core/vec3.h" /* M_PI */

double spherical_cap_solid_angle(double cos_a) { return 2.0 * M_PI * (1.0 - cos_a); }

/* acos with its argument clamped to [-1, 1]: rounding pushes the ratios of
 * the formula slightly outside near the tangent configurations. */
static double acos_clamped(double x) { return acos(fmax(-1.0, fmin(1.0, x))); }

double spherical_cap_intersection(double a1, double a2, double gamma)
{
    double small = fmin(a1, a2), large = fmax(a1, a2);
    if (gamma >= a1 + a2)
        return 0.0;
    if (gamma <= large - small)
        return spherical_cap_solid_angle(cos(small));
    if (gamma >= 2.0 * M_PI - a1 - a2) /* the complements are disjoint: the union is the sphere */
        return spherical_cap_solid_angle(cos(a1)) + spherical_cap_solid_angle(cos(a2)) - 4.0 * M_PI;
    double c1 = cos(a1), c2 = cos(a2), cg = cos(gamma), s1 = sin(a1), s2 = sin(a2), sg = sin(gamma);
    double vertex = acos_clamped((cg - c1 * c2) / (s1 * s2));
    double arc1 = acos_clamped((c2 - cg * c1) / (sg * s1));
    double arc2 = acos_clamped((c1 - cg * c2) / (sg * s2));
    return 2.0 * (M_PI - vertex - c1 * arc1 - c2 * arc2);
}
