/* The height-field control variate's mathematics (techniques/ao/slice_horizons.h):
 *  - each half-slice's integrals of g (kinks split in closed form, then
 *    6-point Gauss-Legendre) against an independent adaptive Gauss-Kronrod
 *    double integral of max(n.w, 0) sin(theta) over theta <= h, split where
 *    n.w changes sign (core/sampling/quadrature.h), for random normals and horizons;
 *  - with every half-slice open, G_d = G_u = 1 (the hemisphere) to 1e-12,
 *    and so 1.0f exactly;
 *  - the mean of g over cosine- (uniform-) distributed directions equals
 *    G_d (G_u) within 4 standard errors: g's binning and the integrals
 *    describe the same function. */
#include <math.h>
#include <stdint.h>

#include "core/sampling/hemisphere_sampling.h"
#include "core/sampling/quadrature.h"
#include "ao/slice_horizons.h"
#include "tests/check.h"

static uint32_t rng_state = 12345u;
static double rnd(void)
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return (rng_state >> 8) / 16777216.0;
}

static vec3 random_unit(void)
{
    double z = 2.0 * rnd() - 1.0, phi = 2.0 * M_PI * rnd(), r = sqrt(1.0 - z * z);
    return v3((float)(r * cos(phi)), (float)(r * sin(phi)), (float)z);
}

typedef struct {
    vec3 n;
    frame f;
    double h, psi;
    int uniform;
} integrand_ctx;

static double inner_integrand(double theta, void *p)
{
    const integrand_ctx *c = p;
    /* n.w in double from the frame's components. */
    double a = v3_dot(c->n, c->f.n), b = v3_dot(c->n, c->f.t) * cos(c->psi) + v3_dot(c->n, c->f.b) * sin(c->psi);
    double nw = a * cos(theta) + b * sin(theta);
    if (nw <= 0.0)
        return 0.0;
    return c->uniform ? sin(theta) : nw * sin(theta);
}

/* The inner integral at psi, up to the horizon or n.w = 0, whichever comes first. */
static double outer_integrand(double psi, void *p)
{
    integrand_ctx *c = p;
    c->psi = psi;
    double a = v3_dot(c->n, c->f.n), b = v3_dot(c->n, c->f.t) * cos(psi) + v3_dot(c->n, c->f.b) * sin(psi);
    double edge = 0.5 * M_PI + atan(b / a), top = fmin(c->h, edge);
    return top > 0.0 ? quadrature_gk15(inner_integrand, c, 0.0, top, 1e-13, NULL) : 0.0;
}

static void test_side_integrals(void)
{
    double worst = 0.0;
    for (int trial = 0; trial < 40; ++trial) {
        vec3 v = random_unit(), n = random_unit();
        if (v3_dot(n, v) < 0.05f)
            n = v3_normalize(v3_add(n, v3_scale(v, 1.1f - v3_dot(n, v))));
        integrand_ctx c = {n, frame_from_normal(v), 0.3 + 2.6 * rnd(), 0.0, 0};
        int k = (int)(rnd() * SLICE_HORIZON_SIDES);
        double cosine, uniform, lo = 2.0 * M_PI * k / SLICE_HORIZON_SIDES;
        double hi = 2.0 * M_PI * (k + 1) / SLICE_HORIZON_SIDES;
        slice_horizons_side_integrals(n, &c.f, c.h, k, &cosine, &uniform);
        /* The reference splits psi finely: its inner integrand has kinks in psi. */
        double ref_cos = 0.0, ref_uni = 0.0;
        for (int j = 0; j < 64; ++j) {
            double a = lo + (hi - lo) * j / 64, b = lo + (hi - lo) * (j + 1) / 64;
            c.uniform = 0;
            ref_cos += quadrature_gk15(outer_integrand, &c, a, b, 1e-12, NULL);
            c.uniform = 1;
            ref_uni += quadrature_gk15(outer_integrand, &c, a, b, 1e-12, NULL);
        }
        worst = fmax(worst, fmax(fabs(cosine - ref_cos), fabs(uniform - ref_uni)));
    }
    CHECK_MSG(worst < 1e-7, "side integrals differ from the reference by %.3g", worst);
}

static void test_open_hemisphere(void)
{
    float open[SLICE_HORIZON_SIDES];
    for (int k = 0; k < SLICE_HORIZON_SIDES; ++k)
        open[k] = (float)M_PI;
    int not_one = 0;
    double worst = 0.0;
    for (int trial = 0; trial < 200; ++trial) {
        vec3 v = random_unit(), n = random_unit();
        if (v3_dot(n, v) < 0.01f)
            continue;
        frame f = frame_from_normal(v);
        double total_cos = 0.0, total_uni = 0.0;
        for (int k = 0; k < SLICE_HORIZON_SIDES; ++k) {
            double c, u;
            slice_horizons_side_integrals(n, &f, M_PI, k, &c, &u);
            total_cos += c;
            total_uni += u;
        }
        worst = fmax(worst, fmax(fabs(total_cos / M_PI - 1.0), fabs(total_uni / (2.0 * M_PI) - 1.0)));
        slice_horizons h;
        slice_horizons_init(&h, v, n, open);
        not_one += h.integral[0] != 1.0f || h.integral[1] != 1.0f;
    }
    CHECK_MSG(worst < 1e-12, "open hemisphere integrates to 1 within %.3g", worst);
    CHECK_MSG(not_one == 0, "%d pixels whose open hemisphere is not exactly 1.0f", not_one);
}

/* Monte Carlo mean of g against G, for both measures. */
static void test_monte_carlo(void)
{
    for (int trial = 0; trial < 6; ++trial) {
        vec3 v = random_unit(), n = random_unit();
        if (v3_dot(n, v) < 0.2f)
            n = v3_normalize(v3_add(n, v3_scale(v, 1.2f - v3_dot(n, v))));
        float theta[SLICE_HORIZON_SIDES];
        for (int k = 0; k < SLICE_HORIZON_SIDES; ++k)
            theta[k] = (float)(0.2 + 2.9 * rnd());
        slice_horizons h;
        slice_horizons_init(&h, v, n, theta);
        frame f = slice_horizons_frame(&h), shading = frame_from_normal(n);
        for (int q = 0; q < 2; ++q) {
            const int count = 400000;
            double sum = 0.0;
            for (int i = 0; i < count; ++i) {
                float u[2] = {(float)rnd(), (float)rnd()};
                vec3 local = q == 0 ? sample_cosine_hemisphere(u) : sample_uniform_hemisphere(u);
                sum += slice_horizons_visible(&h, &f, frame_to_world(&shading, local));
            }
            double mean = sum / count, se = sqrt(fmax(mean * (1.0 - mean), 1e-12) / count);
            CHECK_MSG(fabs(mean - h.integral[q]) <= 4.0 * se, "trial %d %s: mean g %.5f, G %.5f, se %.2g", trial,
                      q ? "uniform" : "cosine", mean, h.integral[q], se);
        }
    }
}

int main(void)
{
    test_side_integrals();
    test_open_hemisphere();
    test_monte_carlo();
    return check_report("test_slice_horizons");
}
