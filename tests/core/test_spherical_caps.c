/* Spherical caps and the adaptive quadrature:
 *  - the exact cap-cap intersection against brute-force Monte Carlo on the
 *    sphere (uniform directions, counted inside both caps) over many random
 *    configurations, each within 4.5 standard errors of its binomial count,
 *    and the aggregate z over all configurations within 4;
 *  - its limiting cases (nested, disjoint, complementary) and symmetry;
 *  - the GTSO talk's "derived differently, mathematically equivalent"
 *    (issue 26, item 6): gtlab's formula (Tovchigrechko and Vakser 2001's
 *    Gauss-Bonnet form) against Mazonka 2012's independent derivation (the
 *    lens split by the plane through the apex and the circles' two
 *    crossings, each half a cone cut by a plane through its apex), agreeing
 *    to 1e-12 on a dense grid of crossing configurations, caps of more than
 *    a hemisphere reduced to their complements;
 *  - Gauss-Kronrod: exact on polynomials of degree 22, and known integrals. */
#include <math.h>

#include "core/quadrature.h"
#include "core/spherical_caps.h"
#include "core/vec3.h"
#include "tests/check.h"

static unsigned long long rng_state = 12345;
static double uniform01(void)
{
    unsigned long long z = (rng_state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return (double)((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}

/* Monte Carlo: caps about z and about (sin g, 0, cos g). */
static void test_against_monte_carlo(void)
{
    enum { CONFIGS = 200, SAMPLES = 40000 };
    double sum_error = 0.0, sum_var = 0.0, worst_z = 0.0;
    for (int c = 0; c < CONFIGS; ++c) {
        double a1 = M_PI * uniform01(), a2 = M_PI * uniform01(), g = M_PI * uniform01();
        double c1 = cos(a1), c2 = cos(a2), sg = sin(g), cg = cos(g);
        int inside = 0;
        for (int s = 0; s < SAMPLES; ++s) {
            double z = 2.0 * uniform01() - 1.0, phi = 2.0 * M_PI * uniform01(), r = sqrt(1.0 - z * z);
            double x = r * cos(phi);
            inside += z >= c1 && x * sg + z * cg >= c2;
        }
        double p = (double)inside / SAMPLES, estimate = 4.0 * M_PI * p;
        double se = 4.0 * M_PI * sqrt(fmax(p * (1.0 - p), 1.0 / SAMPLES) / SAMPLES);
        double exact = spherical_cap_intersection(a1, a2, g);
        double z = (estimate - exact) / se;
        worst_z = fmax(worst_z, fabs(z));
        CHECK_MSG(fabs(z) < 4.5, "a1 %.4f a2 %.4f g %.4f: exact %.6f, MC %.6f +- %.6f", a1, a2, g, exact, estimate, se);
        sum_error += estimate - exact;
        sum_var += se * se;
    }
    double aggregate = fabs(sum_error) / sqrt(sum_var);
    CHECK_MSG(aggregate < 4.0, "aggregate z %.2f", aggregate);
    printf("cap intersection vs Monte Carlo: %d configurations, worst |z| %.2f, aggregate z %.2f\n", CONFIGS, worst_z,
           aggregate);
}

static void test_limits(void)
{
    double cap = spherical_cap_solid_angle(cos(0.3));
    CHECK_NEAR(spherical_cap_intersection(0.3, 1.0, 0.5), cap, 1e-15);  /* nested */
    CHECK_NEAR(spherical_cap_intersection(0.3, 1.0, 1.31), 0.0, 0.0);   /* disjoint */
    CHECK_NEAR(spherical_cap_intersection(M_PI, 0.7, 2.0), spherical_cap_solid_angle(cos(0.7)), 1e-12);
    CHECK_NEAR(spherical_cap_solid_angle(-1.0), 4.0 * M_PI, 1e-15);
    /* two hemispheres g apart: a lune of angle pi - g, area 2 (pi - g) */
    for (double g = 0.1; g < 3.1; g += 0.3)
        CHECK_NEAR(spherical_cap_intersection(0.5 * M_PI, 0.5 * M_PI, g), 2.0 * (M_PI - g), 1e-12);
    /* continuity at the tangent configurations and symmetry in the caps */
    CHECK_NEAR(spherical_cap_intersection(0.4, 0.9, 0.5 + 1e-9), spherical_cap_solid_angle(cos(0.4)), 1e-6);
    CHECK_NEAR(spherical_cap_intersection(0.4, 0.9, 1.3 - 1e-9), 0.0, 1e-6);
    CHECK_NEAR(spherical_cap_intersection(0.4, 0.9, 0.8), spherical_cap_intersection(0.9, 0.4, 0.8), 1e-14);
}

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
static double acos_clamped(double x) { return acos(fmax(-1.0, fmin(1.0, x))); }

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
static double mazonka_intersection(double a1, double a2, double g)
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

/* Every crossing configuration of a 97^3 grid (offset so no point is
 * tangent or nested to rounding: 1e-4 away from every case boundary, where
 * acos near +-1 turns rounding of 1e-16 into 1e-8), caps up to pi - 0.05.
 * Closer to pi the Gauss-Bonnet form divides by sin a -> 0 and the two part
 * by rounding: 2.3e-12 at a = 3.12 (of a solid angle near 4 pi). */
static void test_two_derivations_agree(void)
{
    enum { N = 97 };
    double worst = 0.0;
    long compared = 0;
    for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j)
            for (int k = 0; k < N; ++k) {
                double a1 = M_PI * (i + 0.37) / N, a2 = M_PI * (j + 0.61) / N, g = M_PI * (k + 0.23) / N;
                double lo = fabs(a1 - a2), hi = fmin(a1 + a2, 2.0 * M_PI - a1 - a2), margin = 1e-4;
                if (!(g > lo + margin && g < hi - margin) || fmax(a1, a2) > M_PI - 0.05)
                    continue;
                worst = fmax(worst, fabs(spherical_cap_intersection(a1, a2, g) - mazonka_intersection(a1, a2, g)));
                compared++;
            }
    CHECK_MSG(compared > 190000 && worst < 1e-12, "%ld configurations, largest difference %.3g", compared, worst);
}

static double poly22(double x, void *ctx)
{
    (void)ctx;
    return 23.0 * pow(x, 22) + 1.0;
}
static double peak(double x, void *ctx)
{
    double a = *(double *)ctx;
    return a / (M_PI * (x * x + a * a)); /* integrates to atan(x/a)/pi */
}
static double kink(double x, void *ctx)
{
    (void)ctx;
    return sqrt(fabs(x - 0.3));
}

static void test_quadrature(void)
{
    double err;
    CHECK_NEAR(quadrature_gk15(poly22, NULL, 0.0, 1.0, 1.0, &err), 2.0, 1e-13); /* one rule, exact */
    double a = 1e-3, points[4] = {-1.0, 0.0, 0.01, 1.0};
    CHECK_NEAR(quadrature_gk15_split(peak, &a, points, 4, 1e-10, &err), 2.0 * atan(1.0 / a) / M_PI, 1e-9);
    double expected = (2.0 / 3.0) * (pow(0.3, 1.5) + pow(0.7, 1.5));
    CHECK_NEAR(quadrature_gk15(kink, NULL, 0.0, 1.0, 1e-10, &err), expected, 1e-9);
}

int main(void)
{
    test_limits();
    test_two_derivations_agree();
    test_quadrature();
    test_against_monte_carlo();
    return check_report("test_spherical_caps");
}
