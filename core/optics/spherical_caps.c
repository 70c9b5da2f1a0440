#include "core/optics/spherical_caps.h"

#include "core/optics/shared_math_c.h"

/* spherical_cap_solid_angle, acos_clamped and spherical_cap_intersection,
 * the text the shaders embed too. */
#include "core/optics/spherical_caps.inc"

/* ---- Mazonka's derivation, for the comparison ---- */

/* Mazonka 2012, "Solid Angle of Conical Surfaces, Polyhedral Cones, and
 * Intersecting Spherical Caps" (arXiv:1205.1396): the part of a cone of
 * half-angle t beyond a plane through its apex at angle f from its axis,
 *   2 [acos(sin f / sin t) - cos t acos(tan f / tan t)]   (|f| <= t <= pi/2),
 * and the intersection of caps a1, a2 (<= pi/2) with axes g apart as the sum
 * of two such parts, the plane through the apex and the two points where the
 * boundary circles cross. In the axes' plane the crossings' midpoint p has
 * p.e1 = cos a1 and p.e2 = cos a2, so the plane makes the angle
 *   psi = atan2((cos a2 - cos a1 cos g) / sin g, cos a1)
 * with e1 and g - psi with e2. */
static double cone_beyond_plane(double t, double f)
{
    /* tan f / tan t written as sin f cos t / (cos f sin t): defined at t = pi/2 */
    return 2.0 * (acos_clamped(sin(f) / sin(t)) - cos(t) * acos_clamped(sin(f) * cos(t) / (cos(f) * sin(t))));
}

static double mazonka_crossing(double a1, double a2, double g)
{
    double psi = atan2((cos(a2) - cos(a1) * cos(g)) / sin(g), cos(a1));
    return cone_beyond_plane(a1, psi) + cone_beyond_plane(a2, g - psi);
}

/* Caps beyond a hemisphere through their complements (radius pi - a about
 * the opposite axis): C1 n C2 = C1 - (C1 n C2'), and for two large caps
 * C1 n C2 = 4 pi - |C1'| - |C2'| + |C1' n C2'|. */
double spherical_cap_intersection_mazonka(double a1, double a2, double g)
{
    double cap1 = spherical_cap_solid_angle(cos(a1)), cap2 = spherical_cap_solid_angle(cos(a2));
    if (a1 <= 0.5 * M_PI && a2 <= 0.5 * M_PI)
        return mazonka_crossing(a1, a2, g);
    if (a1 > 0.5 * M_PI && a2 > 0.5 * M_PI)
        return cap1 + cap2 - 4.0 * M_PI + mazonka_crossing(M_PI - a1, M_PI - a2, g);
    if (a2 > 0.5 * M_PI)
        return cap1 - mazonka_crossing(a1, M_PI - a2, M_PI - g);
    return cap2 - mazonka_crossing(a2, M_PI - a1, M_PI - g);
}

double spherical_caps_compare_derivations(int n, long *compared)
{
    double worst = 0.0;
    *compared = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                double a1 = M_PI * (i + 0.37) / n, a2 = M_PI * (j + 0.61) / n, g = M_PI * (k + 0.23) / n;
                double lo = fabs(a1 - a2), hi = fmin(a1 + a2, 2.0 * M_PI - a1 - a2), margin = 1e-4;
                if (!(g > lo + margin && g < hi - margin) || fmax(a1, a2) > M_PI - 0.05)
                    continue;
                worst = fmax(worst, fabs(spherical_cap_intersection(a1, a2, g) -
                                         spherical_cap_intersection_mazonka(a1, a2, g)));
                ++*compared;
            }
    return worst;
}
