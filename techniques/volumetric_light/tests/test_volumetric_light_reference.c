/* techniques/volumetric_light/volumetric_light_integral.h against mathematics, one ray at a
 * time, unshadowed point light, isotropic phase:
 *  - the quadrature against the airlight integral of Sun, Ramamoorthi,
 *    Narasimhan & Nayar 2005 (eq. 12 with scattering sigma_s and extinction
 *    sigma_t kept apart): with s0 the closest approach, h its distance,
 *        L = sigma_s I e^{-sigma_t s0} / (2 pi h) [F(sigma_t h, xi_d) - F(sigma_t h, xi_0)],
 *        F(u, v) = \int_0^v exp(-u tan xi) dxi,  xi = theta / 2 + pi / 4,
 *    theta = atan((s - s0) / h) at s = 0 and s = d. F is integrated here in
 *    xi (another variable than the reference's theta) to 1e-14; the
 *    difference must lie within the quadrature's own error estimate;
 *  - with sigma_t -> 0 (sigma_s = sigma_t = 1e-9) the equiangular closed form
 *    L = sigma_s I (theta_d - theta_0) / (4 pi h);
 *  - the Monte Carlo estimator (equiangular) within 4 standard errors of the
 *    closed form, and its error falling as 1/sqrt(n);
 *  - a spot light: quadrature and Monte Carlo agree (the cone's analytic
 *    interval against sampling that ignores it). */
#include <math.h>
#include <stdint.h>

#include "core/sampling/quadrature.h"
#include "volumetric_light/volumetric_light_integral.h"
#include "tests/check.h"

typedef struct {
    double u;
} f_context;

static double f_integrand(double xi, void *ctx)
{
    return exp(-((f_context *)ctx)->u * tan(xi));
}

static double airlight_f(double u, double v)
{
    f_context c = {u};
    return quadrature_gk15(f_integrand, &c, 0.0, v, 1e-14, NULL);
}

static double closed_form(const volumetric_light *l, const volumetric_medium *m, vec3 o, vec3 w, double d)
{
    double p[3] = {(double)l->position.x - o.x, (double)l->position.y - o.y, (double)l->position.z - o.z};
    double s0 = p[0] * w.x + p[1] * w.y + p[2] * w.z;
    double q[3] = {p[0] - s0 * w.x, p[1] - s0 * w.y, p[2] - s0 * w.z};
    double h = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    double th0 = atan2(-s0, h), thd = atan2(d - s0, h);
    if (m->sigma_t < 1e-6) /* the equiangular closed form without extinction, to O(sigma_t (s + r)) */
        return m->sigma_s * l->intensity[0] * (thd - th0) / (4.0 * M_PI * h);
    double u = m->sigma_t * h;
    return m->sigma_s * l->intensity[0] * exp(-m->sigma_t * s0) / (2.0 * M_PI * h) *
           (airlight_f(u, 0.5 * thd + M_PI / 4.0) - airlight_f(u, 0.5 * th0 + M_PI / 4.0));
}

/* Mean and standard error of n equiangular samples (n a multiple of 64) with
 * uniforms from an LCG. */
static void mc_mean(const volumetric_lighting *l, vec3 o, vec3 w, double d, int n, uint64_t seed, double *mean,
                    double *se)
{
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; i += 64) {
        float u[64];
        double v[64];
        for (int k = 0; k < 64; ++k) {
            seed = seed * 6364136223846793005ull + 1442695040888963407ull;
            u[k] = (float)((double)(seed >> 40) / 16777216.0);
        }
        volumetric_light_mc_samples(l, o, w, d, u, 64, v);
        for (int k = 0; k < 64; ++k)
            sum += v[k], sum2 += v[k] * v[k];
    }
    *mean = sum / n;
    *se = sqrt(fmax(0.0, sum2 / n - *mean * *mean) / (n - 1));
}

static void check_ray(const volumetric_light *light, const volumetric_medium *m, vec3 o, vec3 w, double d)
{
    volumetric_lighting l = {light, m, NULL};
    volumetric_ray_estimate q;
    volumetric_light_quadrature(&l, o, w, d, 1e-6, &q);
    double exact = closed_form(light, m, o, w, d), far = d + v3_length(v3_sub(light->position, o)) + d;
    double limit = m->sigma_t < 1e-6 ? m->sigma_t * far * exact : 0.0; /* e^{-sigma_t (s + r)} = 1 to this */
    CHECK_MSG(fabs(q.radiance[0] - exact) <= q.error[0] + limit + 1e-12 * exact, "quadrature %.15g +- %.3g vs %.15g",
              q.radiance[0], q.error[0], exact);
    CHECK(q.error[0] < 1e-4 * exact && q.rays == 0);
    double mean, se;
    mc_mean(&l, o, w, d, 4096, 7, &mean, &se);
    mean *= light->intensity[0], se *= light->intensity[0];
    /* With sigma_t -> 0 the equiangular samples are all equal (se = 0). */
    CHECK_MSG(fabs(mean - exact) <= 4.0 * se + limit + 1e-6 * exact, "MC %.9g +- %.3g vs %.9g", mean, se, exact);
}

int main(void)
{
    const double intensity[3] = {10.0, 10.0, 10.0};
    volumetric_light point = volumetric_point_light(v3(0.5f, 2.0f, -1.0f), intensity);
    volumetric_medium media[3] = {{0.3, 0.3, 0.0}, {0.1, 0.6, 0.0}, {1e-9, 1e-9, 0.0}};
    vec3 origins[3] = {v3(-4.0f, 0.0f, 0.0f), v3(0.0f, 3.0f, 3.0f), v3(1.0f, 2.1f, -5.0f)};
    /* Unit in float exactly, so the closed form and the reference see the same line. */
    vec3 dirs[3] = {v3(1.0f, 0.0f, 0.0f), v3(0.0f, 0.0f, -1.0f), v3(0.0f, 0.0f, 1.0f)};
    double depths[3] = {9.0, 4.0, 12.0};
    for (int mi = 0; mi < 3; ++mi)
        for (int r = 0; r < 3; ++r)
            check_ray(&point, &media[mi], origins[r], dirs[r], depths[r]);

    /* A spot light: the analytic cone intervals against sampling that ignores them. */
    volumetric_light spot = volumetric_spot_light(v3(0.0f, 4.0f, 0.0f), v3(0.3f, 0.0f, 0.2f), 30.0, 15.0, intensity);
    volumetric_medium hg = {0.2, 0.3, 0.5};
    volumetric_lighting l = {&spot, &hg, NULL};
    int crossing = 0;
    for (int r = 0; r < 12; ++r) {
        vec3 o = v3(-5.0f + 0.3f * r, 0.2f * r, 4.0f), w = v3_normalize(v3(1.0f, 0.1f * (r % 4) - 0.1f, -0.6f));
        volumetric_ray_estimate q;
        volumetric_light_quadrature(&l, o, w, 12.0, 1e-6, &q);
        double mean, se;
        mc_mean(&l, o, w, 12.0, 8192, 11 + (uint64_t)r, &mean, &se);
        mean *= intensity[0], se *= intensity[0];
        crossing += q.radiance[0] > 0.0;
        CHECK_MSG(fabs(mean - q.radiance[0]) <= 4.0 * se + q.error[0] && (q.radiance[0] == 0.0) == (se == 0.0),
                  "spot ray %d: MC %.9g +- %.3g vs quadrature %.9g +- %.3g", r, mean, se, q.radiance[0], q.error[0]);
    }
    CHECK_MSG(crossing >= 6, "%d of 12 rays cross the cone", crossing);

    /* 1/sqrt(n): the standard error with 16x the samples is about 4x smaller. */
    volumetric_lighting lp = {&point, &media[0], NULL};
    double m1, se1, m2, se2;
    mc_mean(&lp, origins[0], dirs[0], depths[0], 1024, 3, &m1, &se1);
    mc_mean(&lp, origins[0], dirs[0], depths[0], 16384, 5, &m2, &se2);
    CHECK_MSG(se1 / se2 > 3.3 && se1 / se2 < 4.8, "stderr ratio %.3g", se1 / se2);
    return check_report("test_volumetric_light_reference");
}
