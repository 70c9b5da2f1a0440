/* The GTSO cone/lobe LUT (specular_occlusion/specular_occlusion_lut.c):
 *  - entries of a 16^3 table at random indices against an independent
 *    quadrature: a nested 2-D adaptive Gauss-Kronrod integral in polar
 *    coordinates about the CONE's axis (the generator integrates a 1-D
 *    integral about the reflection vector with the arc length in closed
 *    form), numerator over the cone and normaliser over the whole sphere;
 *    the largest difference is printed and asserted below 2e-6;
 *  - the lobe against core/optics/ggx.h's f_r (GGX lobe = f_r(R, w) (R.w) at n = R);
 *  - monotone in a_v (a wider visibility cone never sees less);
 *  - the lookup returns the entries at grid points; the table is the same
 *    for 1 and 2 threads.
 * (The axis parametrisations' interpolation errors are measured by `gtlab
 * lut` and the `gtlab all` stage, not here: a measurement, not a test.) */
#include <math.h>
#include <string.h>

#include "core/optics/ggx.h"
#include "core/sampling/quadrature.h"
#include "core/vec3.h"
#include "specular_occlusion/specular_occlusion_lut.h"
#include "tests/check.h"

static const double MAX_ENTRY_ERROR = 2e-6;

typedef struct {
    so_lobe lobe;
    double r, beta, psi, alpha;
} cone_point;

/* The lobe at the direction (psi, chi) about the cone's axis B, which lies
 * beta from R = +z: w.R = cos psi cos beta - sin psi cos chi sin beta. */
static double inner(double chi, void *ctx)
{
    const cone_point *q = ctx;
    double c = cos(q->psi) * cos(q->beta) - sin(q->psi) * cos(chi) * sin(q->beta);
    return so_lobe_value(q->lobe, c, q->r);
}

/* Break points of [0, 2 pi] clustered about chi = pi, where R lies. */
static int chi_points(double *points)
{
    int n = 0;
    points[n++] = 0.0;
    for (double s = 1.0; s > 1e-5; s *= 0.25)
        points[n++] = M_PI - s;
    points[n++] = M_PI;
    for (double s = 1e-5 * 4.0; s < 2.0; s *= 4.0)
        points[n++] = M_PI + s;
    /* sort the tail produced above (ascending by construction except the first run) */
    for (int i = 1; i < n; ++i)
        for (int j = i; j > 0 && points[j - 1] > points[j]; --j) {
            double t = points[j];
            points[j] = points[j - 1], points[j - 1] = t;
        }
    points[n++] = 2.0 * M_PI;
    return n;
}

static double outer(double psi, void *ctx)
{
    cone_point q = *(const cone_point *)ctx;
    q.psi = psi;
    double points[40];
    int n = chi_points(points);
    return sin(psi) * quadrature_gk15_split(inner, &q, points, n, 1e-10, NULL);
}

/* \int over the cap of half-angle cap_angle about B. */
static double cap_integral(so_lobe lobe, double r, double beta, double cap_angle)
{
    cone_point q = {lobe, r, beta, 0.0, fmax(r * r, 1e-3)};
    double points[64];
    int n = 0;
    points[n++] = 0.0;
    for (double s = 0.25 * q.alpha; s < M_PI; s *= 2.0) {
        if (beta - s > 0.0 && beta - s < cap_angle)
            points[n++] = beta - s;
        if (beta + s < cap_angle)
            points[n++] = beta + s;
    }
    if (beta < cap_angle)
        points[n++] = beta;
    points[n++] = cap_angle;
    for (int i = 1; i < n; ++i)
        for (int j = i; j > 0 && points[j - 1] > points[j]; --j) {
            double t = points[j];
            points[j] = points[j - 1], points[j - 1] = t;
        }
    return quadrature_gk15_split(outer, &q, points, n, 1e-9, NULL);
}

static unsigned long long rng = 99;
static int random_index(int n)
{
    rng = rng * 6364136223846793005ull + 1442695040888963407ull;
    return (int)((rng >> 33) % (unsigned long long)n);
}

static void test_entries(void)
{
    so_lut lut;
    CHECK(so_lut_build(&lut, 16, SO_LOBE_GGX, SO_AXES_ANGLES, 2) == 0);
    CHECK_MSG(lut.max_error_estimate < 1e-7, "quadrature error estimate %.2e", lut.max_error_estimate);
    double worst = 0.0;
    for (int s = 0; s < 10; ++s) {
        int i = random_index(16), j = random_index(16), k = 1 + random_index(15);
        double t[3] = {i / 15.0, j / 15.0, k / 15.0}, av, beta, r;
        so_lut_point(SO_AXES_ANGLES, t, &av, &beta, &r);
        double independent = cap_integral(SO_LOBE_GGX, r, beta, av) / cap_integral(SO_LOBE_GGX, r, beta, M_PI);
        double entry = lut.data[(k * 16 + j) * 16 + i];
        worst = fmax(worst, fabs(entry - independent));
        CHECK_MSG(fabs(entry - independent) <= MAX_ENTRY_ERROR, "(%d,%d,%d): table %.9f, 2-D quadrature %.9f", i, j, k,
                  entry, independent);
    }
    printf("LUT entries vs independent 2-D quadrature: max difference %.2e (asserted <= %.0e)\n", worst,
           MAX_ENTRY_ERROR);
    so_lut_free(&lut);
}

static void test_lobe_is_ggx(void)
{
    for (double r = 0.3; r <= 1.0; r += 0.35)
        for (double theta = 0.05; theta < 1.5; theta += 0.2) {
            vec3 n = v3(0, 0, 1), l = v3((float)sin(theta), 0.0f, (float)cos(theta));
            double expected = ggx_brdf(n, l, r * r) * l.z;
            CHECK_NEAR(so_lobe_value(SO_LOBE_GGX, l.z, r), expected, 1e-5 * expected);
        }
}

static void test_monotone_and_lookup(void)
{
    for (int axes = 0; axes < SO_AXES_COUNT; ++axes) {
        so_lut one, two;
        CHECK(so_lut_build(&one, 12, SO_LOBE_GGX, (so_lut_axes)axes, 1) == 0);
        CHECK(so_lut_build(&two, 12, SO_LOBE_GGX, (so_lut_axes)axes, 2) == 0);
        CHECK(memcmp(one.data, two.data, sizeof(float) * 12 * 12 * 12) == 0);
        int violations = 0;
        for (int k = 0; k < 12; ++k)
            for (int j = 0; j < 12; ++j)
                for (int i = 0; i + 1 < 12; ++i) {
                    double step = one.data[(k * 12 + j) * 12 + i + 1] - one.data[(k * 12 + j) * 12 + i];
                    /* angles: i grows with a_v; cosines: t = cos a_v, a_v shrinks */
                    violations += (axes == SO_AXES_ANGLES ? step : -step) < -1e-7;
                }
        CHECK_MSG(violations == 0, "axes %s: %d decreases in a_v", so_lut_axes_name((so_lut_axes)axes), violations);
        double t[3] = {3.0 / 11.0, 7.0 / 11.0, 5.0 / 11.0}, av, beta, r;
        so_lut_point((so_lut_axes)axes, t, &av, &beta, &r);
        CHECK_NEAR(so_lut_lookup(&one, av, beta, r), one.data[(5 * 12 + 7) * 12 + 3], 1e-6);
        so_lut_free(&one);
        so_lut_free(&two);
    }
}

/* The interpolation error does not depend on the thread count, bit for bit
 * (the RMS is summed in the points' order, not a reduction's). */
static void test_interpolation_error_thread_independent(void)
{
    so_lut lut;
    CHECK(so_lut_build(&lut, 8, SO_LOBE_GGX, SO_AXES_ANGLES, 2) == 0);
    double max1, rms1, max2, rms2;
    so_lut_interpolation_error(&lut, 512, 1u, 1, &max1, &rms1);
    so_lut_interpolation_error(&lut, 512, 1u, 2, &max2, &rms2);
    CHECK(max1 == max2 && rms1 == rms2);
    CHECK(rms1 > 0.0 && rms1 <= max1);
    so_lut_free(&lut);
}

int main(void)
{
    test_interpolation_error_thread_independent();
    test_lobe_is_ggx();
    test_monotone_and_lookup();
    test_entries();
    return check_report("test_specular_occlusion_lut");
}
