/* The parameter-space sphere-light reference (techniques/sphere_light/sphere_light_reference.c)
 * against closed forms and an independent quadrature: a Lambert plane under
 * a sphere fully above the horizon (E = pi sin^2(sigma) cos(theta)), the
 * horizon-crossing case against Frostbite's exact formula, the GGX
 * integral against a midpoint rule over the cap, and the small-light limit
 * (the point light). Every comparison is within 4 standard errors of the
 * run itself, fixed seeds. */
#include <math.h>
#include <stdio.h>

#include "core/optics/ggx.h"
#include "sphere_light/sphere_light_reference.h"
#include "realtime/sphere_illuminance.h"
#include "tests/check.h"

#define SAMPLES 4096u

static void test_lambert_above_horizon(void)
{
    const double sin_sigma[4] = {0.005, 0.1, 0.4, 0.8}, theta[4] = {0.1, 0.7, 1.0, 0.3};
    for (int i = 0; i < 4; ++i) {
        sphere_light_config c = sphere_light_config_make(0.6, theta[i], 1.0, sin_sigma[i], 0.5);
        sphere_light_estimate est;
        sphere_light_reference(&c, SAMPLES, 11u + i, &est);
        double closed = sphere_light_normal_illuminance(sin_sigma[i]) * cos(theta[i]);
        CHECK_MSG(fabs(M_PI * est.diff - closed) <= 4.0 * M_PI * est.diff_stderr + 1e-6 * closed,
                  "sin sigma %g: E = %.9g +- %.3g, closed form %.9g", sin_sigma[i], M_PI * est.diff,
                  M_PI * est.diff_stderr, closed);
        CHECK(est.diff_stderr > 0.0);
    }
}

static void test_lambert_across_horizon(void)
{
    const double sin_sigma[3] = {0.3, 0.6, 0.9}, theta[3] = {1.5, 1.2, 2.0};
    for (int i = 0; i < 3; ++i) {
        sphere_light_config c = sphere_light_config_make(0.6, theta[i], 0.0, sin_sigma[i], 0.5);
        sphere_light_estimate est;
        sphere_light_reference(&c, SAMPLES, 21u + i, &est);
        double exact = sphere_illuminance_frostbite((float)cos(theta[i]), (float)sin_sigma[i]);
        CHECK_MSG(fabs(M_PI * est.diff - exact) <= 4.0 * M_PI * est.diff_stderr + 1e-5,
                  "theta %g: E = %.7g +- %.3g, Frostbite %.7g", theta[i], M_PI * est.diff, M_PI * est.diff_stderr,
                  exact);
    }
}

/* Midpoint rule in (theta, phi) around lc: independent of both samplers. */
static double ggx_over_cap_quadrature(const sphere_light_config *c, int n)
{
    double sigma = asin(c->sin_sigma), sum = 0.0;
    /* A frame (t, b) around lc. */
    double lc[3] = {c->lc.x, c->lc.y, c->lc.z}, a[3] = {1, 0, 0};
    if (fabs(lc[0]) > 0.9)
        a[0] = 0, a[1] = 1;
    double t[3] = {a[1] * lc[2] - a[2] * lc[1], a[2] * lc[0] - a[0] * lc[2], a[0] * lc[1] - a[1] * lc[0]};
    double tl = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    for (int k = 0; k < 3; ++k)
        t[k] /= tl;
    double b[3] = {lc[1] * t[2] - lc[2] * t[1], lc[2] * t[0] - lc[0] * t[2], lc[0] * t[1] - lc[1] * t[0]};
    for (int i = 0; i < n; ++i) {
        double th = sigma * (i + 0.5) / n;
        for (int j = 0; j < n; ++j) {
            double ph = 2.0 * M_PI * (j + 0.5) / n;
            double d[3];
            for (int k = 0; k < 3; ++k)
                d[k] = cos(th) * lc[k] + sin(th) * (cos(ph) * t[k] + sin(ph) * b[k]);
            vec3 l = v3((float)d[0], (float)d[1], (float)d[2]);
            sum += ggx_brdf(c->v, l, c->alpha) * fmax(0.0, d[2]) * sin(th);
        }
    }
    return sum * (sigma / n) * (2.0 * M_PI / n);
}

static void test_ggx_against_quadrature(void)
{
    /* Glossy on a large light (BRDF sampling matters), rough on a small one,
     * a light crossing the horizon, and R inside the light. */
    const double nv[4] = {0.7, 0.4, 0.5, 0.3}, th[4] = {0.6, 0.9, 1.45, 1.2}, ph[4] = {3.14159, 2.5, 3.0, 3.14159},
                 ss[4] = {0.5, 0.08, 0.4, 0.3}, rough[4] = {0.3, 0.8, 0.5, 0.45};
    for (int i = 0; i < 4; ++i) {
        sphere_light_config c = sphere_light_config_make(nv[i], th[i], ph[i], ss[i], rough[i]);
        sphere_light_estimate est;
        sphere_light_reference(&c, SAMPLES, 31u + i, &est);
        double quad = ggx_over_cap_quadrature(&c, 800);
        printf("GGX over the cap, case %d: MC %.6g +- %.2g, quadrature %.6g\n", i, est.spec, est.spec_stderr, quad);
        CHECK_MSG(fabs(est.spec - quad) <= 4.0 * est.spec_stderr + 1e-4 * quad, "case %d", i);
    }
}

/* sigma -> 0: L_spec / (pi sin^2 sigma) -> f_r(v, lc) n.lc. */
static void test_small_light_limit(void)
{
    const double nv[3] = {0.8, 0.5, 0.3}, th[3] = {0.4, 0.8, 1.1}, rough[3] = {0.3, 0.5, 0.8};
    for (int i = 0; i < 3; ++i) {
        double prev = INFINITY;
        for (double ss = 0.064; ss > 1e-3; ss *= 0.25) {
            sphere_light_config c = sphere_light_config_make(nv[i], th[i], 2.0, ss, rough[i]);
            sphere_light_estimate est;
            sphere_light_reference(&c, SAMPLES, 41u + i, &est);
            double e = sphere_light_normal_illuminance(ss);
            double point = ggx_brdf(c.v, c.lc, c.alpha) * c.lc.z;
            double err = fabs(est.spec / e - point) / point;
            CHECK_MSG(err < prev || err <= 4.0 * est.spec_stderr / e / point, "case %d sin %g: %.3g", i, ss, err);
            prev = err;
        }
        CHECK_MSG(prev < 1e-3, "case %d: relative distance to the point light %.3g", i, prev);
    }
}

int main(void)
{
    test_lambert_above_horizon();
    test_lambert_across_horizon();
    test_ggx_against_quadrature();
    test_small_light_limit();
    return check_report("test_sphere_light_reference");
}
