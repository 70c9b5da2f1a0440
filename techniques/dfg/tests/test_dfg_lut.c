/* The split-sum DFG LUT (luts/dfg_lut.c; its interpolation study,
 * dfg/dfg_interpolation.c) against mathematics:
 *  - Monte Carlo: an independent estimator (GGX VNDF sampling, core/optics/ggx.h,
 *    Owen-scrambled Sobol' points, fixed seed) agrees with the quadrature
 *    within 5 of its own standard errors, and the quadrature's error
 *    estimate is below 2e-6;
 *  - the coordinates: ds/dtheta_h = 2 pi D cos sin (the header's Jacobian)
 *    against core/optics/ggx.h's D;
 *  - n.v = 1: an independent 1-D quadrature in theta_h with D from core/optics/ggx.h
 *    (l at 2 theta_h, the lobe symmetric about n);
 *  - limits: r = 0 gives E = 1 and B = (1 - n.v)^5 exactly (the
 *    Fresnel-weighted mirror), r = 0.02 within 1e-4; A, B >= 0, E <= 1; E
 *    does not grow with roughness for n.v >= 0.3. (Below, it does not fall
 *    monotonically: with height-correlated Smith G2, E -> 1 as n.v -> 0 at
 *    every roughness, since G2/G1(v) -> 1 and no reflected direction falls
 *    below the horizon; E(r) dips where alpha ~ n.v and recovers, which the
 *    Monte Carlo points at n.v = 0.05 confirm independently.)
 *  - the furnace: Fdez-Aguera's F_avg = F0 + (1 - F0)/21 is the cosine
 *    average of Schlick's F; Kulla-Conty's E_avg from the table equals E_avg
 *    from the quadrature within the interpolation error, so their f_ms lobe
 *    built on the table restores a white furnace to 1 within it;
 *  - the lookup: exact at texel centres, within the study's error elsewhere;
 *    interpolation error falling with N between texel centres, and ~1/N^2
 *    where E is smooth (n.v, r in [0.3, 0.9]; near n.v = 0 it has a
 *    boundary layer of width ~alpha that bilinear interpolation does not
 *    resolve at these sizes);
 *  - sizes outside 32..256 refused; 1 and 2 threads give the same bits.
 * Not checked: that 1 + F0 (1/E - 1) is right for F0 < 1 (an approximation;
 * it needs a multiple-scattering random-walk reference, Heitz et al. 2016). */
#include <math.h>
#include <string.h>

#include "core/optics/ggx.h"
#include "core/sampling/quadrature.h"
#include "core/sampling/sobol.h"
#include "core/vec3.h"
#include "dfg/dfg_interpolation.h"
#include "luts/dfg_lut.h"
#include "tests/check.h"

static const double MAX_QUADRATURE_ERROR = 2e-6;

/* A, B by VNDF importance sampling: weight G2/G1 (ggx_reflection_weight_brdf). */
static void monte_carlo(double mu, double r, int count, double mean[2], double stderr_[2])
{
    double alpha = ggx_alpha(r), sum[2] = {0}, sum_sq[2] = {0};
    vec3 v = v3((float)sqrt(1.0 - mu * mu), 0.0f, (float)mu);
    sobol_pair_seeds seeds = sobol_owen_pair_seeds(hash_combine(2024, (uint32_t)(mu * 1e4 + r * 1e8)), 0);
    for (int k = 0; k < count; ++k) {
        float u[2];
        sobol_owen_point(&seeds, (uint32_t)k, u);
        vec3 m = ggx_sample_visible_normal(v, alpha, u), l = ggx_reflect(v, m);
        double w = ggx_reflection_weight_brdf(v, l, alpha), fc = pow(1.0 - v3_dot(v, m), 5.0);
        double x[2] = {w * (1.0 - fc), w * fc};
        for (int c = 0; c < 2; ++c)
            sum[c] += x[c], sum_sq[c] += x[c] * x[c];
    }
    for (int c = 0; c < 2; ++c) {
        mean[c] = sum[c] / count;
        stderr_[c] = sqrt(fmax(0.0, sum_sq[c] / count - mean[c] * mean[c]) / (count - 1));
    }
}

static void test_monte_carlo(void)
{
    const double points[][2] = {{0.05, 0.3}, {0.2, 0.8}, {0.5, 0.5}, {0.9, 0.1}, {0.3, 1.0}, {0.7, 0.15}};
    for (int p = 0; p < 6; ++p) {
        double q[3], mc[2], se[2], err = dfg_integrate(points[p][0], points[p][1], q);
        monte_carlo(points[p][0], points[p][1], 1 << 15, mc, se);
        for (int c = 0; c < 2; ++c)
            CHECK_MSG(fabs(q[c] - mc[c]) <= 5.0 * se[c] + 1e-7, "(%g, %g) channel %d: quadrature %.7f, MC %.7f +- %.1e",
                      points[p][0], points[p][1], c, q[c], mc[c], se[c]);
        CHECK_MSG(err < MAX_QUADRATURE_ERROR, "(%g, %g): error estimate %.2e", points[p][0], points[p][1], err);
        printf("n.v %.2f r %.2f: A %.7f (MC %.7f +- %.1e)  B %.7f (MC %.7f +- %.1e)  est. error %.1e\n", points[p][0],
               points[p][1], q[0], mc[0], se[0], q[1], mc[1], se[1], err);
    }
}

/* The header's s(theta) = tan^2 / (alpha^2 + tan^2): its derivative is 2 pi D cos sin. */
static void test_coordinates_are_ggx(void)
{
    for (double alpha = 0.01; alpha < 1.0; alpha *= 3.0)
        for (double theta = 0.003; theta < 1.5; theta *= 2.5) {
            double h = 1e-6 * theta, s[2];
            for (int k = 0; k < 2; ++k) {
                double t = tan(theta + (2 * k - 1) * h);
                s[k] = t * t / (alpha * alpha + t * t);
            }
            double expected = 2.0 * M_PI * ggx_ndf(cos(theta), alpha) * cos(theta) * sin(theta);
            CHECK_NEAR((s[1] - s[0]) / (2.0 * h), expected, 1e-5 * expected);
        }
}

typedef struct {
    double alpha;
    int bias;
} normal_incidence;

/* f_r (n.l) dl at v = n over theta_h: D G2(1, cos 2 theta_h) cos theta_h 2 pi sin theta_h. */
static double normal_incidence_integrand(double theta, void *ctx)
{
    const normal_incidence *q = ctx;
    double ch = cos(theta), fc = pow(1.0 - ch, 5.0), w = q->bias ? fc : 1.0 - fc;
    return ggx_ndf(ch, q->alpha) * ggx_smith_g2(1.0, cos(2.0 * theta), q->alpha) * ch * 2.0 * M_PI * sin(theta) * w;
}

static void test_normal_incidence(void)
{
    for (double r = 0.1; r <= 1.0; r += 0.3) {
        double q[3], points[40];
        int n = 0;
        points[n++] = 0.0;
        for (double t = 0.25 * r * r; t < 0.25 * M_PI; t *= 2.0)
            points[n++] = t;
        points[n++] = 0.25 * M_PI;
        dfg_integrate(1.0, r, q);
        for (int c = 0; c < 2; ++c) {
            normal_incidence ctx = {ggx_alpha(r), c};
            double expected = quadrature_gk15_split(normal_incidence_integrand, &ctx, points, n, 1e-10, NULL);
            CHECK_NEAR(q[c], expected, 1e-6);
        }
    }
}

static void test_smooth_limit(void)
{
    for (double mu = 0.1; mu <= 1.0; mu += 0.15) {
        double q[3], fc = pow(1.0 - mu, 5.0);
        dfg_integrate(mu, 0.0, q);
        CHECK_NEAR(q[DFG_ALBEDO], 1.0, 1e-12);
        CHECK_NEAR(q[DFG_BIAS], fc, 1e-12);
        dfg_integrate(mu, 0.02, q);
        CHECK_NEAR(q[DFG_ALBEDO], 1.0, 1e-4);
        CHECK_NEAR(q[DFG_BIAS], fc, 1e-4);
    }
}

static void test_table_bounds(const dfg_lut *lut)
{
    int n = lut->size, negative = 0, above_one = 0, grows = 0;
    for (int t = 0; t < n * n; ++t) {
        const float *d = lut->data + 3 * t;
        negative += d[0] < 0.0f || d[1] < 0.0f;
        above_one += d[2] > 1.0f + (float)lut->error_estimate[t];
    }
    for (int i = (int)(0.3 * n); i < n; ++i) /* n.v >= 0.3: see the top comment */
        for (int j = 0; j + 1 < n; ++j)
            grows += lut->data[((j + 1) * n + i) * 3 + 2] > lut->data[(j * n + i) * 3 + 2] + 1e-6f;
    CHECK_MSG(negative == 0, "%d texels with A or B < 0", negative);
    CHECK_MSG(above_one == 0, "%d texels with E > 1", above_one);
    CHECK_MSG(grows == 0, "%d places where E grows with roughness at n.v >= 0.3", grows);
    CHECK_MSG(lut->max_error_estimate < MAX_QUADRATURE_ERROR, "table error estimate %.2e", lut->max_error_estimate);
}

/* Fdez-Aguera 2019's F_avg = 2 \int F(mu) mu dmu = F0 + (1 - F0) / 21 for Schlick's F. */
static double schlick_cosine(double mu, void *ctx) { return 2.0 * mu * (*(double *)ctx + (1.0 - *(double *)ctx) * pow(1.0 - mu, 5.0)); }

static void test_fresnel_average(void)
{
    for (double f0 = 0.0; f0 <= 1.0; f0 += 0.25) {
        double favg = quadrature_gk15(schlick_cosine, &f0, 0.0, 1.0, 1e-12, NULL);
        CHECK_NEAR(favg, f0 + (1.0 - f0) / 21.0, 1e-10);
    }
    CHECK_NEAR(dfg_energy_compensation(0.8, 1.0) * 0.8, 1.0, 1e-12);
    CHECK_NEAR(dfg_energy_compensation(0.8, 0.0), 1.0, 1e-12);
}

typedef struct {
    const dfg_lut *lut;
    double r;
} e_avg_ctx;

static double e_cos_exact(double mu, void *ctx)
{
    double q[3];
    dfg_integrate(mu, ((e_avg_ctx *)ctx)->r, q);
    return 2.0 * mu * q[DFG_ALBEDO];
}

static double e_cos_table(double mu, void *ctx)
{
    const e_avg_ctx *c = ctx;
    float v[3];
    dfg_lut_sample(c->lut, (float)mu, (float)c->r, v);
    return 2.0 * mu * v[DFG_ALBEDO];
}

/* Kulla-Conty 2017: f_ms = (1 - E(mu_o))(1 - E(mu_i)) / (pi (1 - E_avg)) adds
 * albedo (1 - E(mu_o)) (1 - E_avg') / (1 - E_avg), E_avg' from the lookups a
 * shader makes, E_avg from the quadrature: the white furnace is 1 to within
 * the table's interpolation error over its 1 - E_avg. */
static void test_kulla_conty_furnace(const dfg_lut *lut, double table_error)
{
    for (double r = 0.3; r <= 1.0; r += 0.35) {
        e_avg_ctx ctx = {lut, r};
        double points[4] = {0.0, 0.05, 0.3, 1.0};
        double exact = quadrature_gk15_split(e_cos_exact, &ctx, points, 4, 1e-7, NULL);
        double table = quadrature_gk15_split(e_cos_table, &ctx, points, 4, 1e-7, NULL);
        float e_o[3];
        dfg_lut_sample(lut, 0.4f, (float)r, e_o);
        double furnace = e_o[2] + (1.0 - e_o[2]) * (1.0 - table) / (1.0 - exact);
        CHECK_MSG(fabs(furnace - 1.0) <= table_error / (1.0 - exact), "r %.2f: E_avg %.6f (table %.6f), furnace %.6f",
                  r, exact, table, furnace);
        printf("r %.2f: Kulla-Conty E_avg %.6f (from the table %.6f), white furnace %.6f\n", r, exact, table, furnace);
    }
}

static void test_lookup_at_centres(const dfg_lut *lut)
{
    int n = lut->size, mismatches = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            float v[3];
            dfg_lut_sample(lut, (i + 0.5f) / n, (j + 0.5f) / n, v);
            mismatches += memcmp(v, lut->data + ((size_t)j * n + i) * 3, sizeof v) != 0;
        }
    CHECK_MSG(mismatches == 0, "%d texel centres where the lookup is not the texel", mismatches);
    float corner[3];
    dfg_lut_sample(lut, -1.0f, 2.0f, corner); /* clamp-to-edge */
    CHECK(memcmp(corner, lut->data + (size_t)(n - 1) * n * 3, sizeof corner) == 0);
}

static void test_interpolation_study(const dfg_lut *lut32, double *table_error)
{
    const int sizes[3] = {8, 16, 32};
    dfg_interpolation_result res[3];
    CHECK(dfg_interpolation_study(sizes, 3, 400, 11, 2, res) == 0);
    for (int k = 0; k < 3; ++k)
        printf("N %2d: E max %.2e rms %.2e; between texel centres max %.2e rms %.2e (%d points)\n", res[k].size,
               res[k].max_error[2], res[k].rms_error[2], res[k].interior_max_error[2], res[k].interior_rms_error[2],
               res[k].interior_points);
    for (int c = 0; c < DFG_CHANNELS; ++c)
        for (int k = 0; k + 1 < 3; ++k)
            CHECK_MSG(res[k].interior_rms_error[c] > res[k + 1].interior_rms_error[c],
                      "channel %d: interior RMS %.2e at N %d, %.2e at N %d", c, res[k].interior_rms_error[c],
                      res[k].size, res[k + 1].interior_rms_error[c], res[k + 1].size);
    *table_error = res[2].max_error[2];
    /* The same table as lut32, so its errors at other points are of the same size. */
    double q[3];
    float v[3];
    dfg_integrate(0.437, 0.611, q);
    dfg_lut_sample(lut32, 0.437f, 0.611f, v);
    CHECK_NEAR(v[2], q[2], res[2].max_error[2]);
}

/* RMS error of E at fixed points in the smooth region [0.3, 0.9]^2. */
static double smooth_rms(const dfg_lut *lut, const double (*exact)[3], int count)
{
    double sum = 0.0;
    for (int k = 0; k < count; ++k) {
        float v[3], nv = 0.3f + 0.6f * (k % 7) / 6.0f + 0.013f, r = 0.3f + 0.6f * (k / 7) / 6.0f + 0.007f;
        dfg_lut_sample(lut, nv, r, v);
        sum += (v[2] - exact[k][2]) * (v[2] - exact[k][2]);
    }
    return sqrt(sum / count);
}

static void test_second_order(const dfg_lut *lut32)
{
    double exact[49][3];
    for (int k = 0; k < 49; ++k)
        dfg_integrate(0.3f + 0.6f * (k % 7) / 6.0f + 0.013f, 0.3f + 0.6f * (k / 7) / 6.0f + 0.007f, exact[k]);
    dfg_lut lut16;
    CHECK(dfg_lut_build_any_size(&lut16, 16, 2) == 0);
    double e16 = smooth_rms(&lut16, exact, 49), e32 = smooth_rms(lut32, exact, 49);
    printf("smooth region: E RMS %.2e at N 16, %.2e at N 32 (ratio %.2f; 4 for O(1/N^2))\n", e16, e32, e16 / e32);
    CHECK_MSG(e16 > 3.0 * e32, "not second order: %.2e at N 16, %.2e at N 32", e16, e32);
    dfg_lut_free(&lut16);
}

static void test_sizes_and_threads(const dfg_lut *two_threads)
{
    dfg_lut bad, one;
    CHECK(dfg_lut_build(&bad, 31, 1) == -1 && bad.data == NULL);
    CHECK(dfg_lut_build(&bad, 257, 1) == -1 && bad.data == NULL);
    CHECK(dfg_lut_size_valid(32) && dfg_lut_size_valid(256) && !dfg_lut_size_valid(0));
    CHECK(dfg_lut_build(&one, 32, 1) == 0);
    CHECK(memcmp(one.data, two_threads->data, sizeof(float) * 32 * 32 * 3) == 0);
    dfg_lut_free(&one);
}

int main(void)
{
    test_coordinates_are_ggx();
    test_fresnel_average();
    test_smooth_limit();
    test_normal_incidence();
    test_monte_carlo();
    dfg_lut lut;
    double table_error = 0.0;
    CHECK(dfg_lut_build(&lut, 32, 2) == 0);
    test_table_bounds(&lut);
    test_lookup_at_centres(&lut);
    test_interpolation_study(&lut, &table_error);
    test_second_order(&lut);
    test_kulla_conty_furnace(&lut, table_error);
    test_sizes_and_threads(&lut);
    dfg_lut_free(&lut);
    return check_report("dfg_lut");
}
