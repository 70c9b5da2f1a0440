/* The environment sampler (core/optics/environment_sampler.h): its density
 * integrates to 1 over the sphere (texel by texel, and by Monte Carlo over
 * uniform directions); a chi-square test of 400,000 samples' texel histogram
 * against the density, and of their positions within a texel against
 * uniform solid angle; the returned density equals the lookup's at the
 * sample, rotated or not; no sample lands where the luminance is 0; the
 * one-sample balance-heuristic weights sum to 1, and the mixture estimator
 * of the unoccluded Lambertian integral (1/pi) \int L max(0, n.w) dw agrees
 * with its texel-by-texel quadrature within 4 standard errors; a sun-only
 * environment (one bright texel) gets every sample, each with L / pdf = I;
 * the batched draws and lookups are the single ones' bits. */
#include <stdint.h>
#include <string.h>

#include "core/optics/environment_sampler.h"
#include "core/frame.h"
#include "core/optics/ggx.h"
#include "core/sampling/hemisphere_sampling.h"
#include "tests/check.h"

static uint64_t rng_state = 0x9E3779B97F4A7C15ull;

/* splitmix64 -> a float in [0, 1). */
static float uniform01(void)
{
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return (float)((z ^ (z >> 31)) >> 40) * 0x1p-24f;
}

/* A 16 x 8 map of random colours, a zero column band and a bright texel. */
static void make_test_map(environment_map *env, int width, int height)
{
    float *rgb = malloc(sizeof(float) * 3 * (size_t)width * (size_t)height);
    for (int i = 0; i < width * height; ++i)
        for (int c = 0; c < 3; ++c)
            rgb[3 * i + c] = (i % width == 3) ? 0.0f : uniform01() * (c + 1);
    rgb[3 * (2 * width + 9)] = 40.0f;
    gt_error e;
    CHECK_MSG(environment_map_from_pixels(env, "test", width, height, rgb, &e) == 0, "%s", e.message);
    free(rgb);
}

/* The Wilson-Hilferty upper quantile of chi-square with k degrees of
 * freedom at z standard deviations (z = 4.27: p ~ 1e-5). */
static double chi2_critical(int k, double z)
{
    double a = 2.0 / (9.0 * k);
    return k * pow(1.0 - a + z * sqrt(a), 3.0);
}

static void test_pdf_integrates_to_one(const environment_sampler *s)
{
    const environment_map *env = s->env;
    double sum = 0.0;
    for (int r = 0; r < env->height; ++r)
        for (int c = 0; c < env->width; ++c)
            sum += s->texel[r * env->width + c][3] * env->row_solid_angle[r];
    CHECK_NEAR(sum, 1.0, 1e-6);
    /* E[4 pi pdf(w)] over uniform w is \int pdf = 1. */
    double mean = 0.0, square = 0.0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        float z = 1.0f - 2.0f * uniform01(), phi = 6.2831853f * uniform01(), rr = sqrtf(fmaxf(0.0f, 1.0f - z * z));
        double x = 4.0 * M_PI * environment_sampler_pdf(s, v3(rr * cosf(phi), z, rr * sinf(phi)));
        mean += x / n, square += x * x / n;
    }
    double se = sqrt((square - mean * mean) / n);
    printf("  Monte Carlo integral of the pdf: %.5f +- %.5f\n", mean, se);
    CHECK_NEAR(mean, 1.0, 4.0 * se);
}

static void test_histogram(const environment_sampler *s)
{
    const environment_map *env = s->env;
    const int n = 400000, texels = env->width * env->height;
    long *count = calloc((size_t)texels, sizeof(long));
    long sub[4][4] = {{0}};
    int mismatched = 0;
    for (int i = 0; i < n; ++i) {
        float u[2] = {uniform01(), uniform01()}, pdf;
        vec3 w = environment_sampler_sample(s, u, &pdf);
        int t = environment_texel_of(env, environment_world_to_map(env, w));
        ++count[t];
        mismatched += pdf != environment_sampler_pdf(s, w);
        if (t == 2 * env->width + 9) { /* where within the bright texel: phi and cos theta quarters */
            float uu, vv;
            environment_direction_to_uv(environment_world_to_map(env, w), &uu, &vv);
            double cos_top = cos(M_PI * 2 / env->height), cos_bottom = cos(M_PI * 3 / env->height);
            int a = (int)((uu * env->width - 9) * 4), b = (int)((w.y - cos_top) / (cos_bottom - cos_top) * 4);
            ++sub[a < 0 ? 0 : (a > 3 ? 3 : a)][b < 0 ? 0 : (b > 3 ? 3 : b)];
        }
    }
    double chi2 = 0.0;
    int bins = 0;
    for (int t = 0; t < texels; ++t) {
        double expected = n * s->texel[t][3] * env->row_solid_angle[t / env->width];
        if (expected == 0.0) {
            CHECK_MSG(count[t] == 0, "texel %d of luminance 0 got %ld samples", t, count[t]);
            continue;
        }
        chi2 += (count[t] - expected) * (count[t] - expected) / expected;
        ++bins;
    }
    printf("  texel histogram: chi2 = %.1f over %d bins (critical %.1f); %d pdf mismatches\n", chi2, bins,
           chi2_critical(bins - 1, 4.27), mismatched);
    CHECK(chi2 < chi2_critical(bins - 1, 4.27));
    CHECK(mismatched <= n / 10000);
    long total = 0;
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
            total += sub[a][b];
    double sub_chi2 = 0.0;
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
            sub_chi2 += (sub[a][b] - total / 16.0) * (sub[a][b] - total / 16.0) / (total / 16.0);
    printf("  within the bright texel (%ld samples): chi2 = %.1f over 16 bins (critical %.1f)\n", total, sub_chi2,
           chi2_critical(15, 4.27));
    CHECK(total > 1000 && sub_chi2 < chi2_critical(15, 4.27));
    free(count);
}

/* The MIS weights of cosine and environment sampling sum to 1; the
 * one-sample mixture estimator of (1/pi) \int L_R max(0, n.w) dw agrees
 * with the sum over texels of L_R times the texel's cosine integral (by a
 * fine midpoint rule), for c = 0.5 and for each strategy alone. */
static void test_mis(const environment_sampler *s, double c)
{
    const environment_map *env = s->env;
    const vec3 n = v3_normalize(v3(0.3f, 0.8f, -0.5f));
    const frame f = frame_from_normal(n);
    double exact = 0.0;
    for (int r = 0; r < env->height; ++r)
        for (int col = 0; col < env->width; ++col)
            for (int j = 0; j < 16; ++j)
                for (int i = 0; i < 16; ++i) {
                    vec3 w = environment_uv_to_direction((col + (i + 0.5f) / 16) / env->width,
                                                         (float)(acos(cos(M_PI * r / env->height) +
                                                                      (cos(M_PI * (r + 1) / env->height) -
                                                                       cos(M_PI * r / env->height)) * (j + 0.5) / 16) /
                                                                 M_PI));
                    float rgb[3];
                    environment_map_radiance(env, w, rgb);
                    exact += rgb[0] * fmax(0.0, v3_dot(n, w)) * env->row_solid_angle[r] / 256.0 / M_PI;
                }
    const int count = 200000;
    double mean = 0.0, square = 0.0, worst_sum = 0.0;
    for (int k = 0; k < count; ++k) {
        float u[2] = {uniform01(), uniform01()}, pdf_e, rgb[3];
        int brdf = uniform01() < c;
        vec3 w = brdf ? frame_to_world(&f, sample_cosine_hemisphere(u)) : environment_sampler_sample(s, u, &pdf_e);
        double p_b = fmax(0.0, v3_dot(n, w)) / M_PI, p_e = environment_sampler_pdf(s, w);
        double sum = environment_mis_balance(c, p_b, 1.0 - c, p_e) + environment_mis_balance(1.0 - c, p_e, c, p_b);
        if (c * p_b + (1.0 - c) * p_e > 0.0)
            worst_sum = fmax(worst_sum, fabs(sum - 1.0));
        environment_map_radiance(env, w, rgb);
        double p_mix = c * p_b + (1.0 - c) * p_e;
        double x = p_mix > 0.0 ? rgb[0] * fmax(0.0, v3_dot(n, w)) / M_PI / p_mix : 0.0;
        mean += x / count, square += x * x / count;
    }
    double se = sqrt((square - mean * mean) / count);
    printf("  c = %.2f: mixture estimate %.5f +- %.5f, quadrature %.5f; |w_b + w_e - 1| <= %.2g\n", c, mean, se,
           exact, worst_sum);
    CHECK_NEAR(mean, exact, 4.0 * se + 1e-3 * exact);
    CHECK(worst_sum < 1e-12);
}

/* The same for GGX (alpha 0.36) against visible-normal sampling:
 * (1/pi is not there) \int L f_r max(0, n.w) dw, with f_r core/optics/ggx.h's. */
static void test_mis_ggx(const environment_sampler *s, double c)
{
    const environment_map *env = s->env;
    const double alpha = 0.36;
    const frame f = frame_from_normal(v3_normalize(v3(-0.2f, 0.9f, 0.3f)));
    const vec3 v = v3_normalize(v3(0.5f, 0.1f, 0.8f)); /* local */
    double exact = 0.0;
    for (int r = 0; r < env->height; ++r)
        for (int col = 0; col < env->width; ++col)
            for (int j = 0; j < 32; ++j)
                for (int i = 0; i < 32; ++i) {
                    double ct = cos(M_PI * r / env->height) +
                                (cos(M_PI * (r + 1) / env->height) - cos(M_PI * r / env->height)) * (j + 0.5) / 32;
                    vec3 w = environment_uv_to_direction((col + (i + 0.5f) / 32) / env->width, (float)(acos(ct) / M_PI));
                    vec3 l = frame_to_local(&f, w);
                    float rgb[3];
                    environment_map_radiance(env, w, rgb);
                    exact += rgb[0] * ggx_brdf(v, l, alpha) * fmax(0.0, l.z) * env->row_solid_angle[r] / 1024.0;
                }
    const int count = 200000;
    double mean = 0.0, square = 0.0, worst_sum = 0.0;
    for (int k = 0; k < count; ++k) {
        float u[2] = {uniform01(), uniform01()}, pdf_e, rgb[3];
        vec3 w = uniform01() < c ? frame_to_world(&f, ggx_reflect(v, ggx_sample_visible_normal(v, alpha, u)))
                                 : environment_sampler_sample(s, u, &pdf_e);
        vec3 l = frame_to_local(&f, w);
        double p_b = l.z > 0.0f ? ggx_reflection_pdf(v, l, alpha) : 0.0, p_e = environment_sampler_pdf(s, w);
        double sum = environment_mis_balance(c, p_b, 1.0 - c, p_e) + environment_mis_balance(1.0 - c, p_e, c, p_b);
        if (c * p_b + (1.0 - c) * p_e > 0.0)
            worst_sum = fmax(worst_sum, fabs(sum - 1.0));
        environment_map_radiance(env, w, rgb);
        double p_mix = c * p_b + (1.0 - c) * p_e;
        double x = p_mix > 0.0 ? rgb[0] * ggx_brdf(v, l, alpha) * fmax(0.0, l.z) / p_mix : 0.0;
        mean += x / count, square += x * x / count;
    }
    double se = sqrt((square - mean * mean) / count);
    printf("  GGX c = %.2f: mixture estimate %.5f +- %.5f, quadrature %.5f; |w_b + w_e - 1| <= %.2g\n", c, mean,
           se, exact, worst_sum);
    CHECK_NEAR(mean, exact, 4.0 * se + 2e-3 * exact);
    CHECK(worst_sum < 1e-12);
}

/* environment_sampler_sample_many and _lookup_many (the passes with
 * prefetches) against one at a time: the same bits, over more directions
 * than one pass takes, rotated, and for a constant environment. */
static void test_many_equals_one(const environment_sampler *s)
{
    enum { N = 150 };
    float u[N][2], rgb[N][3], pdf[N];
    vec3 w[N];
    for (int i = 0; i < N; ++i)
        u[i][0] = uniform01(), u[i][1] = uniform01();
    u[0][0] = u[0][1] = 0.0f, u[1][0] = u[1][1] = 0x1.fffffep-1f;
    environment_sampler_sample_many(s, N, (const float(*)[2])u, w);
    environment_sampler_lookup_many(s, N, w, rgb, pdf);
    int differ = 0;
    for (int i = 0; i < N; ++i) {
        float pdf_one, rgb_one[3], pdf_lookup;
        vec3 one = environment_sampler_sample(s, u[i], &pdf_one);
        environment_sampler_lookup(s, one, rgb_one, &pdf_lookup);
        differ += memcmp(&one, &w[i], sizeof one) != 0 || memcmp(rgb_one, rgb[i], sizeof rgb_one) != 0 ||
                  memcmp(&pdf_lookup, &pdf[i], sizeof pdf_lookup) != 0;
    }
    CHECK_MSG(differ == 0, "%d of %d batched directions differ from one at a time", differ, N);
}

static void test_rotation(environment_map *env)
{
    gt_error e;
    CHECK(environment_map_transform(env, 137.0f, 3.0f, &e) == 0);
    environment_sampler s;
    CHECK(environment_sampler_init(&s, env, &e) == 0);
    int mismatched = 0;
    for (int i = 0; i < 20000; ++i) {
        float u[2] = {uniform01(), uniform01()}, pdf;
        vec3 w = environment_sampler_sample(&s, u, &pdf);
        mismatched += pdf != environment_sampler_pdf(&s, w);
    }
    CHECK_MSG(mismatched <= 2, "%d of 20000 rotated samples disagree with the lookup's density", mismatched);
    test_pdf_integrates_to_one(&s);
    test_many_equals_one(&s);
    environment_sampler_free(&s);
    CHECK(environment_map_transform(env, 0.0f, 1.0f, &e) == 0);
}

/* One bright texel and nothing else: every sample lands in it, and
 * L / pdf = I = L Omega for each. */
static void test_sun_only(void)
{
    enum { W = 256, H = 128 };
    float *rgb = calloc(3 * W * H, sizeof(float));
    const int row = 40, column = 200;
    for (int c = 0; c < 3; ++c)
        rgb[3 * (row * W + column) + c] = 5000.0f;
    environment_map env;
    environment_sampler s;
    gt_error e;
    CHECK(environment_map_from_pixels(&env, "sun-only", W, H, rgb, &e) == 0);
    CHECK(environment_sampler_init(&s, &env, &e) == 0 && s.usable);
    int outside = 0;
    double worst = 0.0, integral = 5000.0 * env.row_solid_angle[row];
    for (int i = 0; i < 10000; ++i) {
        float u[2] = {uniform01(), uniform01()}, pdf, l[3];
        vec3 w = environment_sampler_sample(&s, u, &pdf);
        outside += environment_texel_of(&env, w) != row * W + column;
        environment_map_radiance(&env, w, l);
        worst = fmax(worst, fabs(l[1] / pdf / integral - 1.0));
    }
    CHECK(outside == 0);
    CHECK_MSG(worst < 1e-6, "L / pdf off by %g", worst);
    environment_sampler_free(&s);
    environment_map_free(&env);
    free(rgb);
}

int main(void)
{
    environment_map env;
    make_test_map(&env, 16, 8);
    environment_sampler s;
    gt_error e;
    CHECK(environment_sampler_init(&s, &env, &e) == 0 && s.usable);
    test_pdf_integrates_to_one(&s);
    test_histogram(&s);
    test_mis(&s, 0.5);
    test_mis(&s, 1.0);
    test_mis(&s, 0.0);
    test_mis_ggx(&s, 0.5);
    test_mis_ggx(&s, 1.0);
    test_many_equals_one(&s);
    environment_sampler_free(&s);
    test_rotation(&env);
    environment_map_free(&env);
    test_sun_only();
    float grey[3] = {0.25f, 0.5f, 1.0f};
    CHECK(environment_map_constant(&env, "grey", grey, &e) == 0);
    CHECK(environment_sampler_init(&s, &env, &e) == 0 && s.usable);
    test_many_equals_one(&s);
    environment_sampler_free(&s);
    environment_map_free(&env);
    float zero[3] = {0, 0, 0};
    CHECK(environment_map_constant(&env, "black", zero, &e) == 0);
    CHECK(environment_sampler_init(&s, &env, &e) == 0 && !s.usable);
    CHECK(environment_sampler_pdf(&s, v3(0, 1, 0)) == 0.0f);
    return check_report("test_environment_sampler");
}
