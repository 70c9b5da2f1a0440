/* Hemisphere and disc sampling (core/sampling/hemisphere_sampling.c) against their
 * densities' closed-form moments and distribution functions, with
 * Owen-scrambled Sobol' points; tolerances are 4 standard errors computed
 * from the run itself (generous for low-discrepancy points, which converge
 * faster than independent ones). */
#include <string.h>

#include "core/sampling/hemisphere_sampling.h"
#include "core/sampling/sobol.h"
#include "tests/check.h"

#define N_SAMPLES (1 << 16)

/* Running mean and standard error of the mean of one statistic. */
typedef struct {
    double sum, sum_sq;
    int n;
} moment;

static void moment_add(moment *m, double v)
{
    m->sum += v;
    m->sum_sq += v * v;
    m->n++;
}

static double moment_mean(const moment *m) { return m->sum / m->n; }

static double moment_stderr(const moment *m)
{
    double mean = moment_mean(m);
    double variance = (m->sum_sq - m->n * mean * mean) / (m->n - 1);
    return sqrt(fmax(variance, 0.0) / m->n);
}

/* |mean - expected| <= 4 standard errors (and a floor for statistics that
 * are nearly constant). */
#define CHECK_MOMENT(m, expected, what)                                                                     \
    do {                                                                                                    \
        double tol_ = fmax(4.0 * moment_stderr(&(m)), 1e-9);                                                \
        CHECK_MSG(fabs(moment_mean(&(m)) - (expected)) <= tol_, "%s: %.6f, expected %.6f (4 se = %.2g)", what, \
                  moment_mean(&(m)), (double)(expected), tol_);                                             \
    } while (0)

typedef vec3 (*direction_sampler)(const float u[2]);

/* For a density p(z) on the hemisphere (rotationally symmetric), checks unit
 * length, z >= 0, E[z], E[z^2], E[x] = E[y] = 0, E[x^2] = E[y^2] =
 * (1 - E[z^2]) / 2, and P(z < t) at a few t. */
static void check_hemisphere(const char *name, direction_sampler sample, double mean_z, double mean_z2,
                             double (*cdf_z)(double))
{
    moment z = {0}, z2 = {0}, x = {0}, y = {0}, x2 = {0}, y2 = {0};
    const double t[3] = {0.25, 0.5, 0.9};
    moment below[3] = {{0}};
    int bad_length = 0, below_horizon = 0;
    for (uint32_t i = 0; i < N_SAMPLES; ++i) {
        float u[2];
        sobol_owen_2d(0x5eed1234u, i, 0u, u);
        vec3 d = sample(u);
        bad_length += fabs(v3_length(d) - 1.0) > 1e-6;
        below_horizon += d.z < 0.0f;
        moment_add(&z, d.z);
        moment_add(&z2, (double)d.z * d.z);
        moment_add(&x, d.x);
        moment_add(&y, d.y);
        moment_add(&x2, (double)d.x * d.x);
        moment_add(&y2, (double)d.y * d.y);
        for (int k = 0; k < 3; ++k)
            moment_add(&below[k], d.z < t[k] ? 1.0 : 0.0);
    }
    printf("%s: E[z] = %.6f (%.6f), E[z^2] = %.6f (%.6f)\n", name, moment_mean(&z), mean_z, moment_mean(&z2),
           mean_z2);
    CHECK_MSG(bad_length == 0, "%s: %d directions not of unit length", name, bad_length);
    CHECK_MSG(below_horizon == 0, "%s: %d directions below the horizon", name, below_horizon);
    CHECK_MOMENT(z, mean_z, "E[z]");
    CHECK_MOMENT(z2, mean_z2, "E[z^2]");
    CHECK_MOMENT(x, 0.0, "E[x]");
    CHECK_MOMENT(y, 0.0, "E[y]");
    CHECK_MOMENT(x2, (1.0 - mean_z2) / 2.0, "E[x^2]");
    CHECK_MOMENT(y2, (1.0 - mean_z2) / 2.0, "E[y^2]");
    for (int k = 0; k < 3; ++k)
        CHECK_MOMENT(below[k], cdf_z(t[k]), "P(z < t)");
}

/* Cosine-weighted, pdf cos(theta) / pi: p(z) = 2z on [0, 1], so P(z < t) =
 * t^2, E[z] = 2/3, E[z^2] = 1/2. */
static double cosine_cdf(double t) { return t * t; }
/* Uniform, pdf 1 / (2 pi): z uniform on [0, 1], E[z] = 1/2, E[z^2] = 1/3. */
static double uniform_cdf(double t) { return t; }

static void test_concentric_disc(void)
{
    /* Shirley & Chiu 1997: the centre and the edge midpoints of the square go
     * to the centre and the axis points of the disc. */
    const float centre[2] = {0.5f, 0.5f}, right[2] = {1.0f, 0.5f}, top[2] = {0.5f, 1.0f}, left[2] = {0.0f, 0.5f};
    float px, py;
    sample_concentric_disc(centre, &px, &py);
    CHECK(px == 0.0f && py == 0.0f);
    sample_concentric_disc(right, &px, &py);
    CHECK_NEAR(px, 1.0, 1e-6);
    CHECK_NEAR(py, 0.0, 1e-6);
    sample_concentric_disc(top, &px, &py);
    CHECK_NEAR(px, 0.0, 1e-6);
    CHECK_NEAR(py, 1.0, 1e-6);
    sample_concentric_disc(left, &px, &py);
    CHECK_NEAR(px, -1.0, 1e-6);
    CHECK_NEAR(py, 0.0, 1e-6);

    /* Area preserving: uniform points on the square give uniform points on
     * the disc, so P(r < rho) = rho^2 and each quadrant holds 1/4. */
    const double rho[4] = {0.25, 0.5, 0.75, 0.95};
    moment inside[4] = {{0}}, quadrant[4] = {{0}};
    int outside = 0;
    for (uint32_t i = 0; i < N_SAMPLES; ++i) {
        float u[2], x, y;
        sobol_owen_2d(77u, i, 3u, u);
        sample_concentric_disc(u, &x, &y);
        double r = sqrt((double)x * x + (double)y * y);
        outside += r > 1.0 + 1e-6;
        for (int k = 0; k < 4; ++k)
            moment_add(&inside[k], r < rho[k] ? 1.0 : 0.0);
        int q = (x >= 0.0f ? 0 : 1) + (y >= 0.0f ? 0 : 2);
        for (int k = 0; k < 4; ++k)
            moment_add(&quadrant[k], q == k ? 1.0 : 0.0);
    }
    CHECK_MSG(outside == 0, "%d points outside the unit disc", outside);
    for (int k = 0; k < 4; ++k) {
        CHECK_MOMENT(inside[k], rho[k] * rho[k], "P(r < rho)");
        CHECK_MOMENT(quadrant[k], 0.25, "quadrant fraction");
    }
}

/* The extreme inputs a 24-bit sample can take: no direction may fall on the
 * horizon (z = 0), where it would graze the surface it leaves and a renderer
 * could not tell whether it is above or below it. */
static void test_never_on_horizon(void)
{
    const float edges[] = {0.0f, 0x1p-24f, 0.5f, 1.0f - 0x1p-24f};
    int bad = 0;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            const float u[2] = {edges[i], edges[j]};
            vec3 c = sample_cosine_hemisphere(u), w = sample_uniform_hemisphere(u);
            bad += !(c.z > 0.0f) + !(w.z > 0.0f);
            bad += fabsf(v3_length(c) - 1.0f) > 1e-6f || fabsf(v3_length(w) - 1.0f) > 1e-6f;
        }
    }
    /* And the whole rim of the concentric map, where rounding bites. */
    for (uint32_t k = 0; k < (1u << 16); ++k) {
        const float u[2] = {1.0f - 0x1p-24f, (float)k / 65536.0f};
        bad += !(sample_cosine_hemisphere(u).z > 0.0f);
    }
    CHECK_MSG(bad == 0, "%d edge inputs on the horizon or not unit length", bad);
}

/* The batch (vectorised where the CPU allows) gives exactly the scalar
 * functions' directions, so renders do not depend on the code path. */
static void test_batch_matches_scalar(void)
{
    enum { N = 4099 };
    static float u0[N], u1[N];
    static vec3 cosine[N], uniform[N];
    sobol_pair_seeds seeds = sobol_owen_pair_seeds(5, 0);
    for (int k = 0; k < N; ++k) {
        float u[2];
        sobol_owen_point(&seeds, (uint32_t)k, u);
        u0[k] = u[0];
        u1[k] = u[1];
    }
    u0[0] = 0.5f, u1[0] = 0.5f; /* the disc's centre */
    sample_hemisphere_batch(u0, u1, N, cosine, uniform);
    int differ = 0;
    for (int k = 0; k < N; ++k) {
        const float u[2] = {u0[k], u1[k]};
        vec3 c = sample_cosine_hemisphere(u), w = sample_uniform_hemisphere(u);
        differ += memcmp(&c, &cosine[k], sizeof c) != 0 || memcmp(&w, &uniform[k], sizeof w) != 0;
    }
    CHECK_MSG(differ == 0, "%d of %d batch directions differ from the scalar ones", differ, N);
}

int main(void)
{
    test_never_on_horizon();
    test_batch_matches_scalar();
    check_hemisphere("cosine", sample_cosine_hemisphere, 2.0 / 3.0, 0.5, cosine_cdf);
    check_hemisphere("uniform", sample_uniform_hemisphere, 0.5, 1.0 / 3.0, uniform_cdf);
    test_concentric_disc();
    return check_report("test_hemisphere_sampling");
}
