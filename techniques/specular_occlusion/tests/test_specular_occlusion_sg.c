/* Spherical-Gaussian specular occlusion (specular_occlusion/specular_occlusion_sg.h):
 *  - the SG inner product's closed form against a product quadrature over
 *    the sphere (an independent integration);
 *  - full visibility (a cone of half-angle pi/2 about the normal): V_s = 1
 *    up to the SG approximation's own error, the mismatch of the cone's SG
 *    (lambda_v = 1) and the hemisphere's (lambda_u = 0.8); for a sharp lobe
 *    V_s -> exp(-0.2 (1 - n.v)) (alpha -> 0: checked at r = 0.05 within
 *    0.005); measured over n.v, r in [0.05, 1]: 1 - V_s at most 0.18
 *    (grazing), at most 0.12 for n.v >= 0.5;
 *  - monotone (non-decreasing) in the cone's half-angle;
 *  - against the exact cone-lobe ratio (specular_occlusion/cone_visibility_view.h, the
 *    GGX BRDF with Smith masking integrated over the cone at the actual
 *    view, 48 x 48 strata: error ~1e-3) on a grid of views, roughnesses,
 *    cones and bent normals: the measured error is printed and bounded
 *    (mean |error| < 0.12, max < 0.45; README.md), beside GTSO's
 *    cone/cone (exact caps, cos a_s = 2^(-3.32193 alpha^2)) on the same grid. */
#include <math.h>

#include "core/vec3.h"
#include "specular_occlusion/cone_visibility_view.h"
#include "specular_occlusion/specular_occlusion.h"
#include "specular_occlusion/specular_occlusion_sg.h"
#include "tests/check.h"

/* <G_1, G_2> by a Gauss-free midpoint rule in (cos theta, phi) about the
 * first axis, fine enough for sharpnesses up to ~50. */
static double quadrature_inner_product(double l1, double l2, double cos_angle)
{
    enum { NT = 4000, NP = 256 };
    double sin_angle = sqrt(fmax(0.0, 1.0 - cos_angle * cos_angle)), sum = 0.0;
    for (int i = 0; i < NT; ++i) {
        double t = -1.0 + (i + 0.5) * 2.0 / NT, s = sqrt(fmax(0.0, 1.0 - t * t));
        for (int j = 0; j < NP; ++j) {
            double phi = (j + 0.5) * 2.0 * M_PI / NP;
            double dot2 = t * cos_angle + s * cos(phi) * sin_angle; /* v . p_2, p_2 in the xz-plane */
            sum += exp(l1 * (t - 1.0)) * exp(l2 * (dot2 - 1.0));
        }
    }
    return sum * (2.0 / NT) * (2.0 * M_PI / NP);
}

static void test_inner_product(void)
{
    printf("SG inner product\n");
    const double cases[][3] = {{1.0, 0.8, 1.0}, {5.0, 2.0, 0.3}, {20.0, 1.0, -0.5}, {3.0, 40.0, 0.9}};
    for (int k = 0; k < 4; ++k) {
        double closed = so_sg_inner_product(cases[k][0], cases[k][1], cases[k][2]);
        double numeric = quadrature_inner_product(cases[k][0], cases[k][1], cases[k][2]);
        printf("  lambda %g, %g, cos %g: %.8f (quadrature %.8f)\n", cases[k][0], cases[k][1], cases[k][2], closed,
               numeric);
        CHECK_NEAR(closed, numeric, 1e-4 * numeric);
    }
}

static void test_full_visibility(void)
{
    printf("full visibility\n");
    double worst = 0.0, worst_half = 0.0, worst_sharp = 0.0;
    for (int i = 1; i <= 20; ++i)
        for (int j = 1; j <= 20; ++j) {
            double nv = i / 20.0, r = j / 20.0;
            double v = so_sg_occlusion(0.0, nv, nv, r * r); /* b = n: cos beta = R.n = n.v */
            double deficit = 1.0 - v, sharp_limit = 1.0 - exp(-0.2 * (1.0 - nv));
            worst = fmax(worst, deficit);
            if (nv >= 0.5)
                worst_half = fmax(worst_half, deficit);
            if (j == 1)
                worst_sharp = fmax(worst_sharp, fabs(deficit - sharp_limit));
            CHECK(v >= 0.0 && v <= 1.0);
        }
    printf("  1 - V_s at most %.4f (n.v >= 0.5: %.4f); at r = 0.05 within %.4f of 1 - exp(-0.2 (1 - n.v))\n",
           worst, worst_half, worst_sharp);
    CHECK(worst <= 0.18);
    CHECK(worst_half <= 0.12);
    CHECK(worst_sharp <= 0.005);
}

static void test_monotone_in_cone(void)
{
    printf("monotone in the cone angle\n");
    int violations = 0, cases = 0;
    for (int i = 1; i <= 10; ++i)
        for (int j = 1; j <= 10; ++j)
            for (int b = 0; b <= 7; ++b) {
                double nv = i / 10.0, r = j / 10.0, cos_beta = cos(b * 0.4), previous = -1.0;
                for (int k = 0; k <= 90; ++k) {
                    double v = so_sg_occlusion(cos(k * M_PI / 180.0), cos_beta, nv, r * r);
                    violations += v < previous;
                    previous = v;
                    ++cases;
                }
            }
    printf("  %d decreases in %d steps\n", violations, cases);
    CHECK(violations == 0);
}

static vec3 unit(double theta, double phi)
{
    return v3((float)(sin(theta) * cos(phi)), (float)(sin(theta) * sin(phi)), (float)cos(theta));
}

static void test_against_exact(void)
{
    printf("against the exact cone-lobe ratio\n");
    const double nvs[] = {0.25, 0.5, 0.75, 1.0}, roughness[] = {0.25, 0.5, 0.8}, cone[] = {0.5, 0.9, 1.2, 1.5};
    const double tilt[] = {0.0, 0.35, -0.35, 0.7};
    double sum = 0.0, worst = 0.0, cone_sum = 0.0, cone_worst = 0.0;
    int count = 0;
    uint32_t seed = 1;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 4; ++k)
                for (int t = 0; t < 4; ++t) {
                    vec3 v = unit(acos(nvs[i]), 0.0), b = unit(fabs(tilt[t]), tilt[t] < 0.0 ? M_PI : 0.0);
                    vec3 r = v3(-v.x, -v.y, v.z); /* reflect(-v, n), n = +z */
                    double alpha = roughness[j] * roughness[j];
                    double exact = so_cone_visibility_view(v, b, cos(cone[k]), alpha, 48, seed++);
                    double sg = so_sg_occlusion(cos(cone[k]), v3_dot(b, r), nvs[i], alpha);
                    double err = fabs(sg - exact);
                    double cone_cone = so_cone_cone(cos(cone[k]), exp2(-3.32193 * alpha * alpha),
                                                    acos(fmax(-1.0, fmin(1.0, v3_dot(b, r)))), 1);
                    sum += err, ++count;
                    worst = fmax(worst, err);
                    cone_sum += fabs(cone_cone - exact), cone_worst = fmax(cone_worst, fabs(cone_cone - exact));
                }
    printf("  %d cases: mean |SG - exact| %.4f, max %.4f (cone/cone: %.4f, %.4f)\n", count, sum / count, worst,
           cone_sum / count, cone_worst);
    CHECK(sum / count < 0.12);
    CHECK(worst < 0.45);
}

int main(void)
{
    test_inner_product();
    test_full_visibility();
    test_monotone_in_cone();
    test_against_exact();
    return check_report("test_specular_occlusion_sg");
}
