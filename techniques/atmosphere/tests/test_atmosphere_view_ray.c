/* The view-ray radiance of the combination images (atmosphere/atmosphere_scattering.h,
 * atmosphere_view_radiance) and the vector Gauss-Kronrod under it
 * (core/sampling/quadrature.h), against mathematics:
 *  - the vector rule: integrals of several closed forms at once, each within
 *    its own tolerance, and equal to the scalar rule's;
 *  - closed forms in a homogeneous shell (H -> infinity), the sun at the
 *    zenith: a segment of length d looking up from the ground (nu = 1) has
 *    S_i = E beta_s^i d exp(-beta_t L) (view and sun paths sum to L = R_t -
 *    R_b at every point); looking down from h0 (nu = -1), S_i = E beta_s^i
 *    exp(-beta_t (L - h0)) (1 - exp(-2 beta_t d)) / (2 beta_t);
 *  - two implementations agreeing: at nu = mu mu_s over the whole ray, S_i
 *    and M equal atmosphere_single_scattering and
 *    atmosphere_multiple_scattering (their per-component quadratures);
 *  - the difference of two rays: with the sun at its true azimuth, the
 *    segment [0, d] plus T(0, d) times the whole ray from x_d equals the
 *    whole ray from x (single and multiple scattering alike: the
 *    integrands are functions of the point and the fixed sun direction);
 *  - L = p_R(nu) S_R + p_M(nu) S_M + M. */
#include <math.h>
#include <string.h>

#include "core/optics/phase_function.h"
#include "core/sampling/quadrature.h"
#include "atmosphere/atmosphere_model.h"
#include "atmosphere/atmosphere_scattering.h"
#include "tests/check.h"
#include "atmosphere_test_models.h"

static void three_forms(double x, void *ctx, double *v)
{
    (void)ctx;
    v[0] = exp(-x), v[1] = x * x, v[2] = 1.0 / (1.0 + x * x);
}

static double arctan_form(double x, void *ctx)
{
    (void)ctx;
    return 1.0 / (1.0 + x * x);
}

static void test_vector_rule(void)
{
    double points[3] = {0.0, 1.0, 5.0}, tol[3] = {1e-12, 1e-12, 1e-12}, v[3], err[3];
    quadrature_gk15_vector_split(three_forms, NULL, 3, points, 3, tol, v, err);
    CHECK_NEAR(v[0], 1.0 - exp(-5.0), 1e-12);
    CHECK_NEAR(v[1], 125.0 / 3.0, 1e-10);
    CHECK_NEAR(v[2], atan(5.0), 1e-12);
    CHECK(fabs(v[2] - atan(5.0)) <= err[2] + 1e-14); /* the estimate bounds the error */
    CHECK_NEAR(v[2], quadrature_gk15_split(arctan_form, NULL, points, 3, 1e-12, NULL), 1e-12);
}

static void test_homogeneous_segments(const atmosphere_solution *s)
{
    const atmosphere_model *m = &s->model;
    double L = m->top_radius - m->bottom_radius, h0 = 5000.0, d = 3000.0;
    atmosphere_coefficients k = atmosphere_coefficients_at(m, s->t, 0.0);
    atmosphere_view_ray up = {m->bottom_radius, 1.0, 1.0, 1.0, d}, down = {m->bottom_radius + h0, -1.0, 1.0, -1.0, d};
    double L_up[3], L_down[3], S_up[2][3], S_down[2][3];
    CHECK(atmosphere_view_radiance(s, ATMOSPHERE_REFERENCE, &up, 1e-9, L_up, S_up, NULL) < 1e-6);
    atmosphere_view_radiance(s, ATMOSPHERE_REFERENCE, &down, 1e-9, L_down, S_down, NULL);
    for (int i = 0; i < ATMOSPHERE_SPECIES; ++i)
        for (int c = 0; c < 3; ++c) {
            double e = m->solar_irradiance[c] * k.scattering[i][c], bt = k.extinction[c];
            double want_up = e * d * exp(-bt * L);
            double want_down = e * exp(-bt * (L - h0)) * -expm1(-2.0 * bt * d) / (2.0 * bt);
            CHECK_NEAR(S_up[i][c], want_up, 1e-7 * want_up);
            CHECK_NEAR(S_down[i][c], want_down, 1e-7 * want_down);
        }
}

/* The whole ray at nu = mu mu_s against the azimuth-averaged functions. */
static void test_agrees_with_scattering(const atmosphere_solution *s)
{
    const atmosphere_model *m = &s->model;
    const double mus[3] = {0.9, 0.2, -0.05}, mu[4] = {0.95, 0.1, 0.0, -0.3};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) {
            double r = m->bottom_radius + 700.0;
            atmosphere_view_ray ray = {r, mu[j], mus[i], mu[j] * mus[i], atmosphere_distance_to_boundary(m, r, mu[j])};
            double L[3], S[2][3], M[3], S_ref[2][3], M_ref[3];
            atmosphere_view_radiance(s, ATMOSPHERE_ADAPTIVE, &ray, 1e-8, L, S, M);
            atmosphere_single_scattering(s, ATMOSPHERE_ADAPTIVE, r, mu[j], mus[i], 1e-8, S_ref);
            atmosphere_multiple_scattering(s, ATMOSPHERE_ADAPTIVE, r, mu[j], mus[i], 1e-8, M_ref);
            double pr = rayleigh_phase(ray.nu), pm = cornette_shanks_phase(ray.nu, m->mie_g);
            for (int c = 0; c < 3; ++c) {
                double scale = s->model.solar_irradiance[c] * 1e-5 * 8000.0; /* ~ E beta_R H_R */
                for (int k = 0; k < ATMOSPHERE_SPECIES; ++k)
                    CHECK_NEAR(S[k][c], S_ref[k][c], 1e-6 * scale);
                CHECK_NEAR(M[c], M_ref[c], 1e-6 * scale);
                CHECK_NEAR(L[c], pr * S[0][c] + pm * S[1][c] + M[c], 1e-12 * scale);
            }
        }
}

/* Segment [0, d] + T(0, d) x the whole ray from x_d = the whole ray from x. */
static void test_difference_of_two_rays(const atmosphere_solution *s)
{
    const atmosphere_model *m = &s->model;
    const double mu[3] = {-0.2, 0.02, 0.5}, d = 4000.0, mu_s = 0.15, phi = 2.0;
    for (int j = 0; j < 3; ++j) {
        double r = m->bottom_radius + 1500.0;
        double nu = mu[j] * mu_s + sqrt((1.0 - mu[j] * mu[j]) * (1.0 - mu_s * mu_s)) * cos(phi);
        double r_d = atmosphere_radius_at(r, mu[j], d), mu_d = (r * mu[j] + d) / r_d;
        double mu_s_d = (r * mu_s + d * nu) / r_d;
        atmosphere_view_ray whole = {r, mu[j], mu_s, nu, atmosphere_distance_to_boundary(m, r, mu[j])};
        atmosphere_view_ray near = whole, far = {r_d, mu_d, mu_s_d, nu, atmosphere_distance_to_boundary(m, r_d, mu_d)};
        near.length = d;
        double a[3], b[3], c3[3], T[3];
        atmosphere_view_radiance(s, ATMOSPHERE_REFERENCE, &whole, 1e-8, a, NULL, NULL);
        atmosphere_view_radiance(s, ATMOSPHERE_REFERENCE, &near, 1e-8, b, NULL, NULL);
        atmosphere_view_radiance(s, ATMOSPHERE_REFERENCE, &far, 1e-8, c3, NULL, NULL);
        atmosphere_transmittance(s, ATMOSPHERE_REFERENCE, r, mu[j], d, T);
        for (int c = 0; c < 3; ++c)
            CHECK_NEAR(b[c] + T[c] * c3[c], a[c], 1e-5 * a[c]);
        CHECK(b[1] > 0.0 && b[1] < a[1]);
    }
}

int main(void)
{
    test_vector_rule();
    atmosphere_model hm = atmosphere_model_homogeneous(), dm = atmosphere_model_default();
    atmosphere_solution h, s;
    CHECK(atmosphere_solve(&hm, 0.3, 2, &h) == 0);
    test_homogeneous_segments(&h);
    atmosphere_solution_free(&h);
    CHECK(atmosphere_solve(&dm, 0.5, 2, &s) == 0);
    test_agrees_with_scattering(&s);
    test_difference_of_two_rays(&s);
    atmosphere_solution_free(&s);
    return check_report("test_atmosphere_view_ray");
}
