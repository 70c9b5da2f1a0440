/* ao_decals/ao_decals_fit: the generalised Pareto falloff and the refit.
 *  - at the published parameters (xi = -1/2, L = 1/2, A = 1/9, w = 1) the
 *    family is the talk's three lines at radius 3 with a light's sign
 *    (ao_decals/ao_decals.c's ao_point_decal_published, an independent
 *    implementation), for a sphere and for a stretched (pill) volume;
 *  - xi = 0 is the exponential exp(-(d - 2) / L), and at xi = +-1e-5 the
 *    family differs from it by its first-order term xi u^2 / 2 (u = (d - 2) / L);
 *  - xi = 1/2, L = 1, A = 1/4, w = 0 is Quilez's sphere cos (r / d)^2;
 *  - noise-free data made by the model at known parameters (exponential,
 *    power-law and compact tails; two sets, one with two decals multiplying
 *    and a base visibility) are fitted back to 1e-4, inside the bounds,
 *    with finite standard errors; with k held at 2 on data made at k = 2 the
 *    fit recovers the rest and k's s.e. is 0. */
#include <math.h>

#include "ao_decals/ao_decals.h"
#include "ao_decals/ao_decals_fit.h"
#include "tests/check.h"

enum { N = 400 };

static void check_published(void)
{
    double params[AO_DECAL_PARAMS];
    ao_decal_published_params(params);
    const ao_decal_volume vols[2] = {{{0, 1.5f, 0}, {1, 1, 1}}, {{0.2f, 0.8f, -0.1f}, {1.6f, 0.5f, 0.5f}}};
    for (int v = 0; v < 2; ++v)
        for (int i = 0; i < 40; ++i) {
            vec3 p = v3(-3.0f + 0.15f * i, 0.0f, 0.4f - 0.05f * i), n = v3_normalize(v3(0.1f * (i % 3), 1, 0)), pos, norm;
            ao_decal_samples s = {&p, &n, NULL, NULL, 1, &vols[v], 1};
            ao_decal_unit_space(p, n, &vols[v], &pos, &norm);
            double talk = ao_point_decal_published(v3_neg(v3_scale(pos, 1.0f / 3.0f)), norm);
            CHECK_NEAR(1.0 - ao_decal_fit_visibility(&s, 0, params), talk, 2e-6);
        }
}

static void check_limits(void)
{
    for (double d = 0.5; d < 6.0; d += 0.37) {
        double u = (d - AO_DECAL_FIT_D0) / 0.8, e = exp(-u), first_order = 1e-5 * u * u / 2 * e;
        CHECK_NEAR(ao_decal_falloff(d, 0.0, 0.8), e, 1e-12);
        CHECK_NEAR(ao_decal_falloff(d, 1e-5, 0.8), e, 1.1 * first_order + 1e-12);
        CHECK_NEAR(ao_decal_falloff(d, -1e-5, 0.8), e, 1.1 * first_order + 1e-12);
        CHECK_NEAR(ao_decal_falloff(d, 0.5, 1.0), 4.0 / (d * d), 1e-12); /* (1 + (d - 2) / 2)^-2 = (2 / d)^2 */
    }
    vec3 p = v3(1.3f, 0, 0.4f), n = v3(0, 1, 0), c = v3(0, 1.5f, 0);
    const ao_decal_volume vol = {c, {1, 1, 1}};
    double params[AO_DECAL_PARAMS] = {0.5, 1.0, 0.0, 0.25};
    ao_decal_samples s = {&p, &n, NULL, NULL, 1, &vol, 1};
    CHECK_NEAR(1.0 - ao_decal_fit_visibility(&s, 0, params), ao_sphere_quilez(p, n, c, 1.0f), 1e-6);
}

/* Two sets: one decal over a floor; two decals and a base visibility. */
static vec3 ps[2][N], ns[2][N];
static float vis[2][N], base[N];
static const ao_decal_volume one[1] = {{{0, 1.2f, 0}, {1, 1, 1}}};
static const ao_decal_volume two[2] = {{{-0.6f, 0.9f, 0.3f}, {1.2f, 0.4f, 0.4f}}, {{0.9f, 0.5f, -0.4f}, {0.5f, 0.5f, 0.5f}}};

static void make_sets(const double *truth, ao_decal_samples sets[2])
{
    for (int i = 0; i < N; ++i)
        for (int k = 0; k < 2; ++k) {
            ps[k][i] = v3(-3.0f + 6.0f * (i % 20) / 19.0f, 0.0f, -3.0f + 6.0f * (i / 20) / 19.0f);
            ns[k][i] = v3_normalize(v3(0.05f * k, 1.0f, 0.0f)), base[i] = 0.9f - 0.1f * (i % 3);
        }
    sets[0] = (ao_decal_samples){ps[0], ns[0], vis[0], NULL, N, one, 1};
    sets[1] = (ao_decal_samples){ps[1], ns[1], vis[1], base, N, two, 2};
    for (int k = 0; k < 2; ++k)
        for (int i = 0; i < N; ++i)
            vis[k][i] = (float)ao_decal_fit_visibility(&sets[k], i, truth);
}

static void check_recovery(const double *truth, double held)
{
    ao_decal_samples sets[2];
    make_sets(truth, sets);
    ao_decal_fit_result r;
    gt_error e;
    CHECK_MSG(ao_decal_fit(sets, 2, held, &r, &e) == 0, "%s", e.message);
    for (int k = 0; k < AO_DECAL_PARAMS; ++k)
        CHECK_MSG(fabs(r.params[k] - truth[k]) < 1e-4, "held %g, param %d: %g, truth %g", held, k, r.params[k],
                  truth[k]);
    CHECK(r.at_bound == 0 && r.has_covariance && r.rmse < 1e-5);
    for (int k = 0; k < AO_DECAL_PARAMS; ++k)
        CHECK(isfinite(r.standard_errors[k]));
    if (held > 0.0)
        CHECK(r.exponent == held && r.exponent_se == 0.0);
    else
        CHECK(truth[0] < 0.0 ? fabs(r.exponent + 1.0 / truth[0]) < 1e-3 : truth[0] > 0.0 ? isnan(r.exponent) : 1);
}

int main(void)
{
    check_published();
    check_limits();
    const double exponential[AO_DECAL_PARAMS] = {0.0, 0.8, 0.3, 0.2}, power[AO_DECAL_PARAMS] = {0.45, 0.9, 0.0, 0.25},
                 compact[AO_DECAL_PARAMS] = {-0.3, 0.6, 0.7, 0.15}, k2[AO_DECAL_PARAMS] = {-0.5, 0.7, 0.5, 0.2};
    check_recovery(exponential, 0.0);
    check_recovery(power, 0.0);
    check_recovery(compact, 0.0);
    check_recovery(k2, 2.0);
    return check_report("test_ao_decals_fit");
}
