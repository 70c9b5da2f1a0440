/* The spherical-Gaussian NDF fit: one lobe fitted to an SG-shaped target
 * recovers it; the fitted sums' projected-area integrals (exact per lobe)
 * match the NDF's normalisation 1 within the bound the fit's own L2 error
 * gives (Cauchy-Schwarz: |int (S - D) cos| <= ||S - D||_2 ||cos||_2,
 * ||cos||_2^2 = 2 pi / 3 on the hemisphere); the error does not grow with k;
 * one and two Ceres threads give the same bits; a lobe too many is caught;
 * bad options are errors. */
#include <math.h>
#include <string.h>

#include "core/optics/anisotropic_ndf.h"
#include "sg_ndf/sg_ndf_fit.h"
#include "tests/check.h"

static double sg_fn(const double m[3], const void *g) { return sg_evaluate(g, m); }
static double ndf_fn(const double m[3], const void *n) { return anisotropic_ndf_evaluate(n, m); }

static sg_fit_options small_grid(void)
{
    sg_fit_options o = sg_fit_default_options();
    o.theta_count = 32;
    o.phi_count = 64;
    return o;
}

static void test_recovers_one_lobe(void)
{
    spherical_gaussian truth = {{0, 0, 1}, 40.0, 3.0};
    const double a = 0.15, b = -0.1;
    sg_axis_from_gnomonic(a, b, truth.axis, NULL);
    double alpha = sqrt(2.0 / 60.0); /* the first lobe starts wider, at the normal, with the wrong mu */
    sg_target t = {sg_fn, &truth, alpha, alpha};
    sg_fit_options o = small_grid();
    sg_fit f;
    gt_error e = {{0}};
    CHECK(sg_fit_lobes(&t, 1, NULL, &o, &f, &e) == 0);
    CHECK_MSG(f.status == SG_FIT_OK, "%s: %s", sg_fit_status_name(f.status), f.note);
    CHECK_NEAR(f.params[0], a, 1e-6);
    CHECK_NEAR(f.params[1], b, 1e-6);
    CHECK_NEAR(f.params[2], 40.0, 1e-6 * 40.0);
    CHECK_NEAR(f.params[3], 3.0, 1e-6 * 3.0);
    CHECK(f.l2_error < 1e-8);
}

/* Greedy k = 1..4 on anisotropic Ward and GGX: the integral bound and the
 * monotone error. */
static void test_series(ndf_kind kind)
{
    anisotropic_ndf ndf = {kind, 0.3, 0.12};
    sg_target t = {ndf_fn, &ndf, ndf.alpha_x, ndf.alpha_y};
    sg_fit_options o = small_grid();
    sg_fit f[4];
    gt_error e = {{0}};
    CHECK(sg_fit_series(&t, 4, &o, f, &e) == 0);
    for (int k = 0; k < 4; ++k) {
        CHECK_MSG(f[k].status == SG_FIT_OK, "%s k=%d: %s %s", ndf_kind_name(kind), k + 1,
                  sg_fit_status_name(f[k].status), f[k].note);
        double bound = f[k].l2_error * f[k].target_norm * sqrt(2.0 * M_PI / 3.0) * 1.05 +
                       fabs(f[k].grid_normalisation - 1.0);
        CHECK_MSG(fabs(f[k].projected_area - 1.0) <= bound, "%s k=%d: int S cos = %.6f, bound %.3g",
                  ndf_kind_name(kind), k + 1, f[k].projected_area, bound);
        if (k > 0)
            CHECK(f[k].l2_error <= f[k - 1].l2_error);
    }
    CHECK(f[3].l2_error < 0.5 * f[0].l2_error);
}

static void test_threads_bits(void)
{
    anisotropic_ndf ndf = {NDF_WARD, 0.25, 0.1};
    sg_target t = {ndf_fn, &ndf, ndf.alpha_x, ndf.alpha_y};
    sg_fit_options o1 = small_grid(), o2 = small_grid();
    o2.threads = 2;
    sg_fit a[3], b[3];
    gt_error e = {{0}};
    CHECK(sg_fit_series(&t, 3, &o1, a, &e) == 0 && sg_fit_series(&t, 3, &o2, b, &e) == 0);
    for (int k = 0; k < 3; ++k) {
        CHECK(memcmp(a[k].params, b[k].params, sizeof a[k].params) == 0);
        CHECK(memcmp(&a[k].l2_error, &b[k].l2_error, sizeof(double)) == 0);
    }
}

/* Two lobes for one SG: the second is dead, collapsed, or the fit stalls;
 * never an OK two-lobe number. The series then stops. */
static void test_lobe_too_many(void)
{
    spherical_gaussian truth = {{0, 0, 1}, 80.0, 2.0};
    double alpha = sqrt(2.0 / 80.0);
    sg_target t = {sg_fn, &truth, alpha, alpha};
    sg_fit_options o = small_grid();
    sg_fit f[3];
    gt_error e = {{0}};
    CHECK(sg_fit_series(&t, 3, &o, f, &e) == 0);
    CHECK(f[0].status == SG_FIT_OK);
    CHECK_MSG(f[1].status != SG_FIT_OK && f[1].note[0], "k=2: %s", sg_fit_status_name(f[1].status));
    CHECK(f[2].status == SG_FIT_NOT_RUN);
}

static void test_bad_options(void)
{
    anisotropic_ndf ndf = {NDF_GGX, 0.3, 0.0};
    sg_target t = {ndf_fn, &ndf, ndf.alpha_x, ndf.alpha_y};
    sg_fit f;
    gt_error e = {{0}};
    CHECK(sg_fit_lobes(&t, 1, NULL, NULL, &f, &e) == -1 && strstr(e.message, "roughness"));
    t.alpha_y = 0.2;
    CHECK(sg_fit_lobes(&t, 0, NULL, NULL, &f, &e) == -1 && strstr(e.message, "lobe count"));
    sg_fit_options o = small_grid();
    o.threads = 0;
    CHECK(sg_fit_lobes(&t, 1, NULL, &o, &f, &e) == -1 && strstr(e.message, "threads"));
}

int main(void)
{
    test_recovers_one_lobe();
    test_series(NDF_WARD);
    test_series(NDF_GGX);
    test_threads_bits();
    test_lobe_too_many();
    test_bad_options();
    return check_report("test_sg_ndf_fit");
}
