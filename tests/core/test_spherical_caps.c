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

#include "core/sampling/quadrature.h"
#include "core/optics/spherical_caps.h"
#include "core/sampling/splitmix64.h"
#include "core/vec3.h"
#include "tests/check.h"

static unsigned long long rng_state = 12345;
static double uniform01(void)
{
    return splitmix64_uniform01(&rng_state);
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

/* The two derivations on every crossing configuration of a 97^3 grid
 * (spherical_caps_compare_derivations). */
static void test_two_derivations_agree(void)
{
    long compared = 0;
    double worst = spherical_caps_compare_derivations(97, &compared);
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
