/* The atmosphere model and its precomputation (atmosphere/atmosphere_model.h,
 * atmosphere/atmosphere_scattering.h) against mathematics:
 *  - transmittance: a homogeneous shell (H -> infinity: tau = beta_t x the
 *    chord, vertical and horizontal) and an exponential atmosphere along
 *    vertical rays (tau = beta H (1 - exp(-dh / H)) up and down), by the
 *    grid and by quadrature; the same for the reversed segment;
 *  - single scattering in a homogeneous shell, sun at the zenith: looking up,
 *    S_i = E beta_s^i L exp(-beta_t L) (the sun's and the view's paths sum to
 *    L = R_t - R_b at every point); looking down from h0, S_i = E beta_s^i
 *    exp(-beta_t (L - h0)) (1 - exp(-2 beta_t h0)) / (2 beta_t); by every
 *    method;
 *  - the phases' azimuthal means: normalised (2 pi \int Pbar dmu' = 1),
 *    Rayleigh's closed form against quadrature;
 *  - an optically thin atmosphere (coefficients / 1000): multiple
 *    scattering is below 1e-3 of single scattering (it is O(tau));
 *  - energy: with albedo < 1 and a black ground every order carries less
 *    light than the one before (the grid mean of L^k falls by > 1.6x per
 *    order at t = 0.7);
 *  - bad parameters refused with a message; 1 and 2 threads give the same bits. */
#include <math.h>
#include <string.h>

#include "core/sampling/quadrature.h"
#include "core/optics/phase_function.h"
#include "core/vec3.h"
#include "atmosphere/atmosphere_model.h"
#include "atmosphere/atmosphere_scattering.h"
#include "tests/check.h"
#include "atmosphere_test_models.h"

static void test_homogeneous_transmittance(const atmosphere_solution *s)
{
    const atmosphere_model *m = &s->model;
    double L = m->top_radius - m->bottom_radius, chord = sqrt(m->top_radius * m->top_radius - m->bottom_radius * m->bottom_radius);
    atmosphere_coefficients k = atmosphere_coefficients_at(m, s->t, 0.0);
    for (int how = ATMOSPHERE_FAST; how <= ATMOSPHERE_REFERENCE; how += 2) {
        double up[3], flat[3];
        atmosphere_transmittance(s, how, m->bottom_radius, 1.0, L, up);
        atmosphere_transmittance(s, how, m->bottom_radius, 0.0, chord, flat);
        for (int c = 0; c < 3; ++c) {
            CHECK_NEAR(-log(up[c]), k.extinction[c] * L, 1e-6 * k.extinction[c] * L);
            CHECK_NEAR(-log(flat[c]), k.extinction[c] * chord, 1e-5 * k.extinction[c] * chord);
        }
    }
}

/* beta H (1 - exp(-dh / H)) exp(-h0 / H) summed over the species of blend t. */
static double vertical_tau(const atmosphere_model *m, double t, double h0, double dh, int c)
{
    double sum = 0.0, weight[2] = {1.0 - t, t};
    for (int w = 0; w < ATMOSPHERE_WEATHERS; ++w) {
        const atmosphere_weather *x = &m->weathers[w];
        double hr = x->rayleigh_scale_height, hm = x->mie_scale_height;
        sum += weight[w] * (x->rayleigh_scattering[c] * hr * exp(-h0 / hr) * (1.0 - exp(-dh / hr)) +
                            x->mie_extinction[c] * hm * exp(-h0 / hm) * (1.0 - exp(-dh / hm)));
    }
    return sum;
}

static void test_exponential_transmittance(const atmosphere_solution *s)
{
    const atmosphere_model *m = &s->model;
    double h0 = 3000.0, r = m->bottom_radius + h0, top = m->top_radius - r;
    for (int how = ATMOSPHERE_FAST; how <= ATMOSPHERE_REFERENCE; how += 2) {
        double tol = how == ATMOSPHERE_FAST ? 1e-3 : 1e-8;
        double up[3], down[3], back[3];
        atmosphere_transmittance(s, how, r, 1.0, top, up);
        atmosphere_transmittance(s, how, r, -1.0, h0, down);
        atmosphere_transmittance(s, how, m->bottom_radius, 1.0, h0, back);
        for (int c = 0; c < 3; ++c) {
            double tau_up = vertical_tau(m, s->t, h0, top, c), tau_down = vertical_tau(m, s->t, 0.0, h0, c);
            CHECK_NEAR(-log(up[c]), tau_up, tol * tau_up);
            CHECK_NEAR(-log(down[c]), tau_down, tol * tau_down);
            CHECK_NEAR(back[c], down[c], tol * tau_down);
        }
    }
}

/* T(r, mu, d) = T(r_d, -mu_d, d): the same segment walked backwards. */
static void test_reversed_segment(const atmosphere_solution *s)
{
    const atmosphere_model *m = &s->model;
    double cases[3][3] = {{m->bottom_radius + 500.0, 0.05, 80e3}, {m->bottom_radius + 9000.0, -0.2, 30e3},
                          {m->bottom_radius + 20.0, 0.5, 5e3}};
    for (int i = 0; i < 3; ++i) {
        double r = cases[i][0], mu = cases[i][1], d = cases[i][2];
        double r_d = atmosphere_radius_at(r, mu, d), mu_d = (r * mu + d) / r_d, a[3], b[3];
        for (int how = ATMOSPHERE_FAST; how <= ATMOSPHERE_REFERENCE; how += 2) {
            atmosphere_transmittance(s, how, r, mu, d, a);
            atmosphere_transmittance(s, how, r_d, -mu_d, d, b);
            for (int c = 0; c < 3; ++c)
                CHECK_NEAR(a[c], b[c], how == ATMOSPHERE_FAST ? 2e-3 : 1e-9);
        }
    }
}

static void test_homogeneous_single_scattering(const atmosphere_solution *s)
{
    const atmosphere_model *m = &s->model;
    double L = m->top_radius - m->bottom_radius, h0 = 5000.0;
    atmosphere_coefficients k = atmosphere_coefficients_at(m, s->t, 0.0);
    for (int how = ATMOSPHERE_FAST; how <= ATMOSPHERE_REFERENCE; ++how) {
        /* the grid's tau is bilinear in rho, h = rho^2 / 2 R_b: off by up to
         * beta_t (H / 63)^2 / (8 R_b) ~ beta_t 4 m, 3e-4 of this 5 km segment */
        double up[2][3], down[2][3], tol = how != ATMOSPHERE_REFERENCE ? 1e-3 : 1e-7;
        atmosphere_single_scattering(s, how, m->bottom_radius, 1.0, 1.0, 1e-9, up);
        atmosphere_single_scattering(s, how, m->bottom_radius + h0, -1.0, 1.0, 1e-9, down);
        for (int i = 0; i < ATMOSPHERE_SPECIES; ++i)
            for (int c = 0; c < 3; ++c) {
                double e = m->solar_irradiance[c] * k.scattering[i][c], bt = k.extinction[c];
                double want_up = e * L * exp(-bt * L);
                double want_down = e * exp(-bt * (L - h0)) * (1.0 - exp(-2.0 * bt * h0)) / (2.0 * bt);
                CHECK_NEAR(up[i][c], want_up, tol * want_up);
                CHECK_NEAR(down[i][c], want_down, tol * want_down);
            }
    }
}

typedef struct {
    int species;
    double g, mu_a;
} phase_ctx;

static double pbar(double mu, void *ctx)
{
    const phase_ctx *q = ctx;
    return 2.0 * M_PI * atmosphere_azimuthal_phase(q->species, q->g, q->mu_a, mu);
}

static double rayleigh_at(double phi, void *ctx)
{
    const double *ab = ctx;
    return rayleigh_phase(ab[0] * ab[1] + sqrt((1 - ab[0] * ab[0]) * (1 - ab[1] * ab[1])) * cos(phi)) / M_PI;
}

static void test_azimuthal_phases(void)
{
    for (double mu_a = -0.95; mu_a < 1.0; mu_a += 0.4) {
        for (int i = 0; i < ATMOSPHERE_SPECIES; ++i) {
            phase_ctx q = {i, 0.8, mu_a};
            double points[3] = {-1.0, mu_a, 1.0};
            CHECK_NEAR(quadrature_gk15_split(pbar, &q, points, 3, 1e-10, NULL), 1.0, 1e-7);
        }
        double ab[2] = {mu_a, 0.3};
        CHECK_NEAR(atmosphere_azimuthal_phase(ATMOSPHERE_RAYLEIGH, 0.8, mu_a, 0.3),
                   quadrature_gk15(rayleigh_at, ab, 0.0, M_PI, 1e-12, NULL), 1e-10);
    }
}

static void test_thin_atmosphere(int threads)
{
    atmosphere_model m = atmosphere_model_default();
    for (int w = 0; w < ATMOSPHERE_WEATHERS; ++w)
        for (int c = 0; c < 3; ++c) {
            m.weathers[w].rayleigh_scattering[c] *= 1e-3;
            m.weathers[w].mie_scattering[c] *= 1e-3, m.weathers[w].mie_extinction[c] *= 1e-3;
        }
    atmosphere_solution s;
    CHECK(atmosphere_solve(&m, 0.5, threads, &s) == 0);
    double mus[3] = {1.0, 0.3, 0.05}, mu[3] = {1.0, 0.2, -0.3}, worst = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double S[2][3], M[3];
            atmosphere_single_scattering(&s, ATMOSPHERE_ADAPTIVE, m.bottom_radius + 100.0, mu[j], mus[i], 1e-8, S);
            atmosphere_multiple_scattering(&s, ATMOSPHERE_ADAPTIVE, m.bottom_radius + 100.0, mu[j], mus[i], 1e-8, M);
            for (int c = 0; c < 3; ++c)
                worst = fmax(worst, M[c] / (S[0][c] + S[1][c]));
        }
    CHECK_MSG(worst < 1e-3, "thin atmosphere: multiple / single scattering up to %.3g", worst);
    atmosphere_solution_free(&s);
}

static void test_orders_fall(const atmosphere_solution *s)
{
    for (int k = 2; k <= ATMOSPHERE_ORDERS; ++k)
        CHECK_MSG(s->order_mean[k] > 0.0 && s->order_mean[k] < 0.6 * s->order_mean[k - 1],
                  "order %d: mean %.4g after %.4g", k, s->order_mean[k], s->order_mean[k - 1]);
}

static void test_bad_input(void)
{
    char msg[200];
    atmosphere_model m = atmosphere_model_default();
    CHECK(atmosphere_model_check(&m, msg, sizeof msg) == 0);
    m.weathers[1].mie_scattering[0] = -1e-6;
    CHECK(atmosphere_model_check(&m, msg, sizeof msg) != 0 && strstr(msg, "coefficients"));
    m = atmosphere_model_default(), m.weathers[0].rayleigh_scale_height = 0.0;
    CHECK(atmosphere_model_check(&m, msg, sizeof msg) != 0 && strstr(msg, "scale height"));
    m = atmosphere_model_default(), m.mie_g = NAN;
    CHECK(atmosphere_model_check(&m, msg, sizeof msg) != 0);
    m = atmosphere_model_default(), m.weathers[0].mie_extinction[2] = 1e-6;
    CHECK(atmosphere_model_check(&m, msg, sizeof msg) != 0);
}

int main(void)
{
    atmosphere_model hm = atmosphere_model_homogeneous(), dm = atmosphere_model_default();
    atmosphere_solution h, one, two;
    CHECK(atmosphere_solve(&hm, 0.3, 2, &h) == 0);
    test_homogeneous_transmittance(&h);
    test_homogeneous_single_scattering(&h);
    atmosphere_solution_free(&h);
    CHECK(atmosphere_solve(&dm, 0.7, 1, &one) == 0 && atmosphere_solve(&dm, 0.7, 2, &two) == 0);
    size_t ms = sizeof(double) * ATMOSPHERE_MS_R * ATMOSPHERE_MS_MU * ATMOSPHERE_MS_MU_S * 3;
    CHECK(memcmp(one.density, two.density, ms) == 0);
    CHECK(memcmp(one.tau_top, two.tau_top, sizeof(double) * ATMOSPHERE_T_R * ATMOSPHERE_T_MU * 3) == 0);
    test_exponential_transmittance(&one);
    test_reversed_segment(&one);
    test_orders_fall(&one);
    atmosphere_solution_free(&one), atmosphere_solution_free(&two);
    test_azimuthal_phases();
    test_thin_atmosphere(2);
    test_bad_input();
    return check_report("test_atmosphere_model");
}
