/* Spherical Gaussians and the anisotropic NDFs against independent
 * integrations: the closed-form integrals against nested adaptive
 * quadrature of the evaluated functions in (theta, phi) on the sphere, the
 * NDFs' projected-area normalisation likewise, the isotropic GGX limit
 * against core/optics/ggx.h, and the gnomonic axis' derivative by differences. */
#include <math.h>

#include "core/optics/anisotropic_ndf.h"
#include "core/optics/ggx.h"
#include "core/sampling/quadrature.h"
#include "core/sampling/sobol.h"
#include "core/optics/spherical_gaussian.h"
#include "tests/check.h"

/* f(theta, phi) sin theta integrated by GK15 in phi inside GK15 in theta. */
typedef double (*sphere_fn)(const double v[3], const void *ctx);
typedef struct {
    sphere_fn f;
    const void *ctx;
    double theta;
    double tol;
} nested_ctx;

static double phi_integrand(double phi, void *ctx_)
{
    nested_ctx *c = ctx_;
    double s = sin(c->theta), v[3] = {s * cos(phi), s * sin(phi), cos(c->theta)};
    return c->f(v, c->ctx) * s;
}

static double theta_integrand(double theta, void *ctx_)
{
    nested_ctx c = *(nested_ctx *)ctx_;
    c.theta = theta;
    double pts[9];
    for (int i = 0; i < 9; ++i)
        pts[i] = 2.0 * M_PI * i / 8.0;
    return quadrature_gk15_split(phi_integrand, &c, pts, 9, c.tol * 1e-2, NULL);
}

static double sphere_integral(sphere_fn f, const void *ctx, const double *theta_pts, int count, double tol)
{
    nested_ctx c = {f, ctx, 0.0, tol};
    return quadrature_gk15_split(theta_integrand, &c, theta_pts, count, tol, NULL);
}

static double sg_fn(const double v[3], const void *g) { return sg_evaluate(g, v); }
static double sg_cos_fn(const double v[3], const void *g) { return sg_evaluate(g, v) * fmax(0.0, v[2]); }
static double ndf_cos_fn(const double v[3], const void *n) { return anisotropic_ndf_evaluate(n, v) * v[2]; }

static spherical_gaussian tilted_sg(double a, double b, double sharpness, double amplitude)
{
    spherical_gaussian g = {{0, 0, 1}, sharpness, amplitude};
    sg_axis_from_gnomonic(a, b, g.axis, NULL);
    return g;
}

/* theta split points about the lobe: its elevation +- 1 and 3 widths. */
static int lobe_points(double theta0, double width, double upper, double *pts)
{
    double t[5] = {theta0 - 3 * width, theta0 - width, theta0, theta0 + width, theta0 + 3 * width};
    int n = 0;
    pts[n++] = 0.0;
    for (int i = 0; i < 5; ++i)
        if (t[i] > pts[n - 1] + 1e-9 && t[i] < upper - 1e-9)
            pts[n++] = t[i];
    pts[n++] = upper;
    return n;
}

static void test_sphere_integral(void)
{
    const double sharp[4] = {0.05, 1.0, 20.0, 400.0};
    for (int i = 0; i < 4; ++i) {
        spherical_gaussian g = tilted_sg(0.4, -0.3, sharp[i], 1.7);
        double pts[7];
        int n = lobe_points(acos(g.axis[2]), 1.0 / sqrt(sharp[i]), M_PI, pts);
        double q = sphere_integral(sg_fn, &g, pts, n, 1e-11);
        double closed = sg_sphere_integral(sharp[i], 1.7);
        CHECK_MSG(fabs(q - closed) <= 1e-8 * closed, "lambda %g: quadrature %.12g closed %.12g", sharp[i], q, closed);
    }
}

static void test_cosine_integrals(void)
{
    const double sharp[4] = {1e-5, 0.7, 30.0, 2000.0};
    for (int i = 0; i < 4; ++i) {
        spherical_gaussian axial = tilted_sg(0.0, 0.0, sharp[i], 0.9);
        double closed = sg_axial_cosine_integral(sharp[i], 0.9);
        CHECK_MSG(fabs(sg_projected_area_integral(&axial) - closed) <= 1e-9 * closed, "axial lambda %g", sharp[i]);
        spherical_gaussian g = tilted_sg(0.8, 0.5, sharp[i], 0.9); /* axis 43 degrees from n */
        double pts[7];
        int n = lobe_points(acos(g.axis[2]), 1.0 / sqrt(sharp[i]), M_PI / 2, pts);
        double q = sphere_integral(sg_cos_fn, &g, pts, n, 1e-11 * closed);
        double mine = sg_projected_area_integral(&g);
        CHECK_MSG(fabs(mine - q) <= 1e-7 * q, "tilted lambda %g: %.12g vs quadrature %.12g", sharp[i], mine, q);
    }
}

static void test_ndf_normalisation(void)
{
    const double ax[4] = {0.05, 0.2, 0.5, 0.3}, ay[4] = {0.05, 0.1, 0.15, 0.9};
    for (int k = 0; k < 2; ++k)
        for (int i = 0; i < 4; ++i) {
            anisotropic_ndf ndf = {(ndf_kind)k, ax[i], ay[i]};
            double w = fmin(ax[i], ay[i]), pts[9] = {0.0, atan(w), atan(3 * w), atan(10 * w), atan(30 * w),
                                                    atan(100 * w), atan(1000 * w), M_PI / 2};
            double q = sphere_integral(ndf_cos_fn, &ndf, pts, 8, 1e-10);
            CHECK_MSG(fabs(q - 1.0) <= (k == NDF_GGX && ax[i] > 0.5 ? 1e-6 : 1e-8), "%s (%g, %g): %.12g",
                      ndf_kind_name(ndf.kind), ax[i], ay[i], q);
        }
}

static void test_isotropic_ggx(void)
{
    anisotropic_ndf ndf = {NDF_GGX, 0.3, 0.3};
    for (int i = 1; i < 10; ++i) {
        double c = i / 10.0, s = sqrt(1 - c * c), m[3] = {s * 0.6, s * 0.8, c};
        double d = ggx_ndf(c, 0.3);
        CHECK_NEAR(anisotropic_ndf_evaluate(&ndf, m), d, 1e-12 * d);
    }
}

static void test_gnomonic_derivative(void)
{
    double a = 0.7, b = -0.4, axis[3], d[6], p[3], q[3], h = 1e-6;
    sg_axis_from_gnomonic(a, b, axis, d);
    CHECK_NEAR(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2], 1.0, 1e-15);
    for (int j = 0; j < 2; ++j) {
        sg_axis_from_gnomonic(a + (j == 0) * h, b + (j == 1) * h, p, NULL);
        sg_axis_from_gnomonic(a - (j == 0) * h, b - (j == 1) * h, q, NULL);
        for (int c = 0; c < 3; ++c)
            CHECK_NEAR(d[3 * j + c], (p[c] - q[c]) / (2 * h), 1e-8);
    }
}

/* Sampler against density: the mean of f(m) = m_x^2 + 2 m_y^2 + m_z over
 * 2^16 Sobol' points against the nested quadrature of f times the density,
 * within 5 standard errors (plus 1e-9). */
typedef struct {
    const anisotropic_ndf *ndf;
    const spherical_gaussian *sg;
} density_ctx;

static double moment_f(const double v[3]) { return v[0] * v[0] + 2.0 * v[1] * v[1] + v[2]; }

static double density_moment(const double v[3], const void *c_)
{
    const density_ctx *c = c_;
    if (c->ndf)
        return moment_f(v) * anisotropic_ndf_evaluate(c->ndf, v) * v[2];
    return moment_f(v) * sg_evaluate(c->sg, v) / sg_sphere_integral(c->sg->sharpness, c->sg->amplitude);
}

static void check_sampler(const density_ctx *c, const double *pts, int count, const char *what)
{
    double sum = 0.0, sum2 = 0.0, m[3];
    const int n = 1 << 16;
    for (int i = 0; i < n; ++i) {
        float uf[2];
        sobol_owen_2d(1234u, (uint32_t)i, 0, uf);
        double u[2] = {uf[0], uf[1]};
        if (c->ndf)
            anisotropic_ndf_sample(c->ndf, u, m);
        else
            sg_sample(c->sg, u, m);
        double f = moment_f(m);
        sum += f;
        sum2 += f * f;
    }
    double mean = sum / n, se = sqrt(fmax(0.0, sum2 / n - mean * mean) / n);
    double q = sphere_integral(density_moment, c, pts, count, 1e-10);
    CHECK_MSG(fabs(mean - q) <= 5.0 * se + 1e-9, "%s: sampled %.8f, quadrature %.8f, se %.2g", what, mean, q, se);
}

static void test_samplers(void)
{
    for (int k = 0; k < 2; ++k) {
        anisotropic_ndf ndf = {(ndf_kind)k, 0.35, 0.1};
        density_ctx c = {&ndf, NULL};
        double pts[8] = {0.0, atan(0.1), atan(0.3), atan(1.0), atan(3.0), atan(10.0), atan(100.0), M_PI / 2};
        check_sampler(&c, pts, 8, ndf_kind_name(ndf.kind));
    }
    spherical_gaussian g = tilted_sg(0.5, 0.2, 25.0, 2.0);
    density_ctx c = {NULL, &g};
    double pts[7];
    int n = lobe_points(acos(g.axis[2]), 0.2, M_PI, pts);
    check_sampler(&c, pts, n, "sg");
}

int main(void)
{
    test_samplers();
    test_sphere_integral();
    test_cosine_integrals();
    test_ndf_normalisation();
    test_isotropic_ggx();
    test_gnomonic_derivative();
    return check_report("test_spherical_gaussian");
}
