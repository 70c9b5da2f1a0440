/* GGX (core/optics/ggx.c) against its mathematics:
 *   - D is normalised: the integral of D(m) (n.m) over the hemisphere is 1;
 *   - the visible normals are normalised (Heitz 2014's weak white furnace):
 *     the integral of G1(v) max(0, v.m) D(m) dm is n.v, i.e. D_v integrates
 *     to 1;
 *   - the sampler draws from the density the pdf function states: Monte
 *     Carlo means over sampled normals equal quadratures weighted by D_v;
 *   - the reflection pdf's Jacobian: its integral over the upper hemisphere
 *     equals the share of sampled reflections that land there;
 *   - f_r is reciprocal, and its cosine-weighted integral by quadrature
 *     equals the importance-sampled estimate (two implementations) and is
 *     at most 1 (energy conservation);
 *   - the closed-form sample weights (f_r cos / pdf and D cos / pdf) equal
 *     the quotients of the functions they simplify, and their importance-
 *     sampled means equal quadratures of f_r cos and D(h) cos.
 * Quadratures: Simpson in cos theta, the trapezoid rule in phi (spectrally
 * accurate for periodic integrands). Monte Carlo: Owen-scrambled Sobol',
 * fixed seeds, asserted within 4 standard errors. */
#include <math.h>

#include "core/optics/ggx.h"
#include "core/sampling/sobol.h"
#include "tests/check.h"

typedef double (*spherical_fn)(vec3 w, const void *ctx);

/* The integral of f over the upper hemisphere, dw = d(cos theta) d phi. */
static double hemisphere_integral(spherical_fn f, const void *ctx, int n_mu, int n_phi)
{
    double total = 0.0;
    for (int i = 0; i <= n_mu; ++i) {
        double mu = (double)i / n_mu, weight = (i == 0 || i == n_mu) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        double sin_theta = sqrt(fmax(0.0, 1.0 - mu * mu)), ring = 0.0;
        for (int j = 0; j < n_phi; ++j) {
            double phi = 2.0 * M_PI * (j + 0.5) / n_phi;
            ring += f(v3((float)(sin_theta * cos(phi)), (float)(sin_theta * sin(phi)), (float)mu), ctx);
        }
        total += weight * ring * (2.0 * M_PI / n_phi);
    }
    return total / (3.0 * n_mu);
}

static vec3 direction_at(double theta) { return v3((float)sin(theta), 0.0f, (float)cos(theta)); }

/* The integral of D(m) (n.m) in closed form is 1; here by Simpson in x =
 * (n.m)^2, where it reads pi * integral of D(sqrt x) dx over [0, 1]. */
static void test_ndf_normalised(void)
{
    const double alphas[] = {0.02, 0.1, 0.3, 0.7, 1.0};
    for (int a = 0; a < 5; ++a) {
        const int n = 400000;
        double sum = 0.0;
        for (int i = 0; i <= n; ++i) {
            double x = (double)i / n, weight = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
            sum += weight * ggx_ndf(sqrt(x), alphas[a]);
        }
        CHECK_NEAR(M_PI * sum / (3.0 * n), 1.0, 1e-6);
    }
}

typedef struct {
    vec3 v;
    double alpha;
} view;

static double visible_density(vec3 m, const void *ctx)
{
    const view *c = ctx;
    return ggx_visible_normal_pdf(c->v, m, c->alpha);
}

static void test_visible_normals_normalised(void)
{
    const double alphas[] = {0.2, 0.5, 1.0}, thetas[] = {0.0, 0.8, 1.4};
    for (int a = 0; a < 3; ++a)
        for (int t = 0; t < 3; ++t) {
            view c = {direction_at(thetas[t]), alphas[a]};
            CHECK_MSG(fabs(hemisphere_integral(visible_density, &c, 4000, 256) - 1.0) < 1e-4,
                      "alpha %g, theta_v %g", alphas[a], thetas[t]);
        }
}

/* A test function of the microfacet normal with some phi dependence. */
static double probe(vec3 m) { return m.x + 2.0 * m.z * m.z + 0.5 * m.y * m.y; }

static double probe_times_density(vec3 m, const void *ctx) { return probe(m) * visible_density(m, ctx); }

static double reflection_density(vec3 l, const void *ctx)
{
    const view *c = ctx;
    return ggx_reflection_pdf(c->v, l, c->alpha);
}

static void test_sampler_matches_pdf(void)
{
    const double alphas[] = {0.3, 0.8}, thetas[] = {0.3, 1.2};
    const uint32_t n = 1u << 16;
    for (int a = 0; a < 2; ++a)
        for (int t = 0; t < 2; ++t) {
            view c = {direction_at(thetas[t]), alphas[a]};
            sobol_pair_seeds seeds = sobol_owen_pair_seeds(hash_combine(17u, (uint32_t)(3 * a + t)), 0);
            double sum = 0.0, sum_sq = 0.0, upper = 0.0;
            for (uint32_t i = 0; i < n; ++i) {
                float u[2];
                sobol_owen_point(&seeds, i, u);
                vec3 m = ggx_sample_visible_normal(c.v, c.alpha, u);
                double g = probe(m);
                sum += g, sum_sq += g * g;
                upper += ggx_reflect(c.v, m).z > 0.0f;
            }
            double mean = sum / n, se = sqrt(fmax(sum_sq / n - mean * mean, 0.0) / (n - 1));
            double expected = hemisphere_integral(probe_times_density, &c, 4000, 256);
            CHECK_MSG(fabs(mean - expected) < 4.0 * se + 1e-5, "alpha %g theta %g: sampled %.6f, density %.6f (se %.2g)",
                      c.alpha, thetas[t], mean, expected, se);

            /* The share of reflections above the surface, both ways. */
            double share = upper / n, share_se = sqrt(share * (1.0 - share) / n);
            double integral = hemisphere_integral(reflection_density, &c, 4000, 256);
            CHECK_MSG(fabs(share - integral) < 4.0 * share_se + 1e-4, "alpha %g theta %g: share %.6f, pdf integral %.6f",
                      c.alpha, thetas[t], share, integral);
        }
}

/* f_r(v, l) (n.l) as a function of l. */
static double cosine_weighted_brdf(vec3 l, const void *ctx)
{
    const view *c = ctx;
    return ggx_brdf(c->v, l, c->alpha) * l.z;
}

/* Reciprocity, and the directional albedo by quadrature against the
 * importance-sampled estimator, whose weight f_r cos / pdf is G2 / G1(v). */
static void test_brdf_reciprocity_and_albedo(void)
{
    const double alphas[] = {0.3, 0.6, 1.0}, thetas[] = {0.2, 0.9, 1.3};
    for (int a = 0; a < 3; ++a)
        for (int t = 0; t < 3; ++t) {
            view c = {direction_at(thetas[t]), alphas[a]};
            vec3 l = v3_normalize(v3(-0.3f, 0.4f + 0.1f * (float)t, 0.7f));
            CHECK_NEAR(ggx_brdf(c.v, l, c.alpha), ggx_brdf(l, c.v, c.alpha), 1e-14 * ggx_brdf(c.v, l, c.alpha));

            const uint32_t n = 1u << 15;
            sobol_pair_seeds seeds = sobol_owen_pair_seeds(hash_combine(29u, (uint32_t)(3 * a + t)), 0);
            double sum = 0.0, sum_sq = 0.0;
            for (uint32_t i = 0; i < n; ++i) {
                float u[2];
                sobol_owen_point(&seeds, i, u);
                vec3 dir = ggx_reflect(c.v, ggx_sample_visible_normal(c.v, c.alpha, u));
                double pdf = ggx_reflection_pdf(c.v, dir, c.alpha);
                double w = dir.z > 0.0f && pdf > 0.0 ? ggx_brdf(c.v, dir, c.alpha) * dir.z / pdf : 0.0;
                sum += w, sum_sq += w * w;
            }
            double mean = sum / n, se = sqrt(fmax(sum_sq / n - mean * mean, 0.0) / (n - 1));
            double quadrature = hemisphere_integral(cosine_weighted_brdf, &c, 4000, 256);
            CHECK_MSG(fabs(mean - quadrature) < 4.0 * se + 1e-4, "alpha %g theta %g: sampled %.6f, quadrature %.6f",
                      c.alpha, thetas[t], mean, quadrature);
            CHECK(quadrature <= 1.0 + 1e-4);
        }
}

/* D(h) (n.l) as a function of l, h = normalize(v + l). */
static double cosine_weighted_ndf(vec3 l, const void *ctx)
{
    const view *c = ctx;
    vec3 h = v3_normalize(v3_add(c->v, l));
    return ggx_ndf(h.z, c->alpha) * l.z;
}

static void test_reflection_weights(void)
{
    const double alphas[] = {0.2, 0.5, 0.9}, thetas[] = {0.3, 1.0, 1.35};
    for (int a = 0; a < 3; ++a)
        for (int t = 0; t < 3; ++t) {
            view c = {direction_at(thetas[t]), alphas[a]};
            const uint32_t n = 1u << 15;
            sobol_pair_seeds seeds = sobol_owen_pair_seeds(hash_combine(41u, (uint32_t)(3 * a + t)), 0);
            double sum[2] = {0, 0}, sum_sq[2] = {0, 0};
            for (uint32_t i = 0; i < n; ++i) {
                float u[2];
                sobol_owen_point(&seeds, i, u);
                vec3 l = ggx_reflect(c.v, ggx_sample_visible_normal(c.v, c.alpha, u));
                double w[2] = {ggx_reflection_weight_brdf(c.v, l, c.alpha), ggx_reflection_weight_ndf(c.v, l, c.alpha)};
                double pdf = ggx_reflection_pdf(c.v, l, c.alpha);
                if (l.z > 0.0f && pdf > 0.0) {
                    vec3 h = v3_normalize(v3_add(c.v, l));
                    double direct[2] = {ggx_brdf(c.v, l, c.alpha) * l.z / pdf, ggx_ndf(h.z, c.alpha) * l.z / pdf};
                    for (int k = 0; k < 2; ++k)
                        CHECK_MSG(fabs(w[k] - direct[k]) <= 1e-4 * fmax(1.0, direct[k]),
                                  "weight %d: closed form %.9g, quotient %.9g", k, w[k], direct[k]);
                }
                for (int k = 0; k < 2; ++k)
                    sum[k] += w[k], sum_sq[k] += w[k] * w[k];
            }
            const spherical_fn integrands[2] = {cosine_weighted_brdf, cosine_weighted_ndf};
            for (int k = 0; k < 2; ++k) {
                double mean = sum[k] / n, se = sqrt(fmax(sum_sq[k] / n - mean * mean, 0.0) / (n - 1));
                double quadrature = hemisphere_integral(integrands[k], &c, 4000, 256);
                CHECK_MSG(fabs(mean - quadrature) < 4.0 * se + 1e-4 * quadrature,
                          "weight %d, alpha %g theta %g: sampled %.6f +- %.2g, quadrature %.6f", k, c.alpha, thetas[t],
                          mean, se, quadrature);
            }
        }
}

int main(void)
{
    test_ndf_normalised();
    test_visible_normals_normalised();
    test_sampler_matches_pdf();
    test_brdf_reciprocity_and_albedo();
    test_reflection_weights();
    return check_report("test_ggx");
}
