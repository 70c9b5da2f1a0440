/* The GGX LTC fit (ltc/ltc_fit.h) against mathematics:
 *  - an exact clamped-cosine target gives the identity M^-1 (a = c = 1,
 *    b = d = 0) from a distant start, error ~0;
 *  - every fitted distribution integrates to 1 over the sphere, by an
 *    independent midpoint quadrature in (cos theta, phi) (rough rows, where
 *    that grid resolves the lobe);
 *  - the magnitude equals the BRDF's directional albedo, estimated
 *    independently by GGX VNDF sampling (weight G2 / G1, Owen-scrambled
 *    Sobol', fixed seed) within 5 standard errors, for r >= 0.3 (below,
 *    the reflections lost under the horizon come from GGX's tail beyond
 *    45 degrees, mass ~alpha^2, which 2^14 points do not sample);
 *  - E times the LTC integral of a small polygon around the lobe's peak
 *    matches f_r (n.l) times its solid angle to the fit's accuracy;
 *  - the table is the same for 1 and 2 threads; bad sizes are refused. */
#include <math.h>
#include <string.h>

#include "core/optics/ggx.h"
#include "core/sampling/sobol.h"
#include "ltc/ltc_fit.h"
#include "ltc/ltc_sphere.h"
#include "tests/check.h"

static double cosine_target(void *user, const double l[3])
{
    (void)user;
    return l[2] > 0.0 ? l[2] / M_PI : 0.0;
}

static void check_cosine_identity(void)
{
    double m[4] = {2.0, 0.5, 1.5, -0.3};
    ltc_cell_fit f;
    gt_error e;
    CHECK(ltc_fit_cell_target(0.6, 0.5, cosine_target, NULL, 1.0, m, &f, &e) == 0);
    CHECK_NEAR(m[0], 1.0, 1e-4);
    CHECK_NEAR(m[1], 0.0, 1e-4);
    CHECK_NEAR(m[2], 1.0, 1e-4);
    CHECK_NEAR(m[3], 0.0, 1e-4);
    CHECK(f.error < 1e-4);
}

/* \int_S D by midpoint quadrature, n x 2n cells in (cos theta, phi). */
static double sphere_integral(const double m[4], int n)
{
    double sum = 0.0, dz = 2.0 / n, dphi = M_PI / n;
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < 2 * n; ++k) {
            double z = -1.0 + (i + 0.5) * dz, s = sqrt(1.0 - z * z), phi = (k + 0.5) * dphi;
            double w[3] = {s * cos(phi), s * sin(phi), z};
            sum += ltc_density(m, w) * dz * dphi;
        }
    return sum;
}

/* E by VNDF sampling: mean of G2 / G1 (core/optics/ggx.h). */
static void albedo_mc(double mu, double alpha, int count, double *mean, double *se)
{
    vec3 v = v3((float)sqrt(1.0 - mu * mu), 0.0f, (float)mu);
    sobol_pair_seeds seeds = sobol_owen_pair_seeds(hash_combine(77, (uint32_t)(mu * 1e6)), 0);
    double sum = 0.0, sum_sq = 0.0;
    for (int k = 0; k < count; ++k) {
        float u[2];
        sobol_owen_point(&seeds, (uint32_t)k, u);
        double w = ggx_reflection_weight_brdf(v, ggx_reflect(v, ggx_sample_visible_normal(v, alpha, u)), alpha);
        sum += w, sum_sq += w * w;
    }
    *mean = sum / count;
    *se = sqrt(fmax(0.0, sum_sq / count - *mean * *mean) / (count - 1));
}

static const float *texel(const ltc_table *t, int i, int j) { return t->data + ((size_t)j * t->size + i) * LTC_CHANNELS; }

static void check_table_invariants(const ltc_table *t)
{
    for (int j = 0; j < t->size; ++j)
        for (int i = 0; i < t->size; ++i) {
            const float *x = texel(t, i, j);
            double m[4] = {x[0], x[1], x[2], x[3]}, r = ltc_roughness_of_row(j, t->size);
            double mu = ltc_n_dot_v_of_column(i, t->size), mean, se;
            if (r >= 0.4) {
                double integral = sphere_integral(m, 400);
                CHECK_MSG(fabs(integral - 1.0) < 2e-3, "texel (%d, %d): \\int D = %.6g", i, j, integral);
            }
            if (r < 0.3) /* GGX's tail beyond 45 deg (mass ~alpha^2) would get < 100 of the points */
                continue;
            albedo_mc(mu, ggx_alpha(r), 1 << 14, &mean, &se);
            CHECK_MSG(fabs(x[LTC_MAGNITUDE] - mean) < 5.0 * se + 1e-6, "texel (%d, %d): E %.6g vs MC %.6g +- %.2g", i,
                      j, x[LTC_MAGNITUDE], mean, se);
            CHECK(t->error[(size_t)j * t->size + i] >= 0.0f && t->error[(size_t)j * t->size + i] < 1.0f);
        }
}

/* E times the LTC integral of a small square at the mirror direction
 * against f_r (n.l) Omega: the LTC approximates the lobe, so within 20%. */
static void check_small_polygon(const ltc_table *t)
{
    float mu = 0.7f, r = 0.5f, texel_v[LTC_CHANNELS];
    ltc_table_sample(t, mu, r, texel_v);
    vec3 v = v3(sqrtf(1.0f - mu * mu), 0.0f, mu), w = v3(-v.x, 0.0f, v.z), offsets[4], cos_offsets[4];
    vec3 a = v3(0.0f, 1.0f, 0.0f), b = v3_cross(w, a);
    const float h = 2e-3f;
    for (int k = 0; k < 4; ++k) {
        float sx = (k == 0 || k == 3) ? h : -h, sy = k < 2 ? h : -h;
        offsets[k] = v3_add(v3_scale(a, sx), v3_scale(b, sy));
        vec3 o = offsets[k];
        cos_offsets[k] = v3(texel_v[0] * o.x + texel_v[1] * o.z, texel_v[2] * o.y, texel_v[3] * o.x + o.z);
    }
    double omega = M_PI * ltc_polygon_form_factor(w, offsets, 4) / w.z;
    vec3 cw = v3(texel_v[0] * w.x + texel_v[1] * w.z, texel_v[2] * w.y, texel_v[3] * w.x + w.z);
    double got = texel_v[LTC_MAGNITUDE] * ltc_polygon_form_factor(cw, cos_offsets, 4);
    double want = ggx_brdf(v, w, ggx_alpha(r)) * w.z * omega;
    printf("small polygon at the mirror direction: LTC %.6g, BRDF x cos x solid angle %.6g (ratio %.4f)\n", got, want,
           got / want);
    CHECK_MSG(fabs(got / want - 1.0) < 0.2, "%.6g vs %.6g", got, want);
}

int main(void)
{
    check_cosine_identity();
    ltc_table one, two;
    gt_error e;
    CHECK(ltc_fit_table(&one, 8, 1, &e) == 0);
    CHECK(ltc_fit_table(&two, 8, 2, &e) == 0);
    CHECK(memcmp(one.data, two.data, sizeof *one.data * 8 * 8 * LTC_CHANNELS) == 0);
    printf("8x8 table: mean error %.4f, max %.4f\n", one.mean_error, one.max_error);
    for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i)
            printf("%6.3f%s", one.error[j * 8 + i], i == 7 ? "\n" : " ");
    check_table_invariants(&one);
    check_small_polygon(&one);
    ltc_table bad;
    CHECK(ltc_fit_table(&bad, 2, 1, &e) == -1 && bad.data == NULL);
    ltc_table_free(&one), ltc_table_free(&two);
    return check_report("ltc_fit");
}
