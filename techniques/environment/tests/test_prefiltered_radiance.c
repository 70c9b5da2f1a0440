/* GGX pre-filtered radiance and the split sum (environment/prefiltered_radiance.h):
 *  - a constant environment L: every texel of every level is L (the weights
 *    are normalised), and the split sum is L (F0 A + B) of the DFG LUT's
 *    lookup, which is dfg_integrate's value at a texel centre;
 *  - an environment linear in w, L = a + b.w: P(R, r) = a + kappa(r) b.R,
 *    kappa = \int (R.l)^2 D / \int (R.l) D over l's hemisphere, an
 *    independent 1-D quadrature over theta_h (R.l = cos 2 theta_h, h
 *    distributed as D cos theta_h); the filter agrees but for the pyramid's
 *    smoothing (Colbert-Krivanek's lod bias of +1 reads levels blurrier than
 *    the sample spacing): at 512 samples 2.9e-3 (r = 0: bilinear lookup of a
 *    64 x 32 level) rising to 1.2e-2 at r = 1, for |b| = 0.62 (without the
 *    bias 3e-3; at 4096 samples 1.8e-3), so the tolerance is 0.02;
 *  - the lookup at a level's roughness and a texel centre is its entry;
 *  - the bits do not depend on the thread count. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/optics/ggx.h"
#include "core/sampling/quadrature.h"
#include "environment/prefiltered_radiance.h"
#include "core/vec3.h" /* M_PI */
#include "tests/check.h"

enum { W = 256, H = 128, LEVELS = 6, SAMPLES = 512 };

static float *constant_env(float value)
{
    float *rgb = malloc(sizeof(float) * W * H * 3);
    for (size_t k = 0; k < (size_t)W * H * 3; ++k)
        rgb[k] = value * (float)(1 + k % 3);
    return rgb;
}

static void test_constant(void)
{
    float *rgb = constant_env(0.75f);
    environment_equirect env = {W, H, rgb};
    prefiltered_radiance p, p1;
    CHECK(prefiltered_radiance_build(&p, &env, 64, LEVELS, SAMPLES, 2) == 0);
    CHECK(prefiltered_radiance_build(&p1, &env, 64, LEVELS, SAMPLES, 1) == 0);
    double worst = 0.0;
    for (int k = 0; k < LEVELS; ++k) {
        CHECK(memcmp(p.rgb[k], p1.rgb[k], sizeof(float) * p.width[k] * p.height[k] * 3) == 0);
        for (size_t t = 0; t < (size_t)p.width[k] * p.height[k] * 3; ++t)
            worst = fmax(worst, fabs(p.rgb[k][t] / (0.75 * (1 + t % 3)) - 1.0));
    }
    CHECK(worst < 1e-6);
    dfg_lut dfg;
    CHECK(dfg_lut_build(&dfg, 32, 2) == 0);
    double R[3] = {0.0, 0.6, 0.8}, f0[3] = {0.04, 0.5, 1.0}, out[3];
    double nv = 16.5 / 32.0, r = 9.5 / 32.0, abe[3];
    split_sum_specular(&p, &dfg, R, nv, r, f0, out);
    dfg_integrate(nv, r, abe);
    for (int c = 0; c < 3; ++c)
        CHECK_NEAR(out[c], 0.75 * (c + 1) * (f0[c] * abe[0] + abe[1]), 1e-6);
    dfg_lut_free(&dfg);
    prefiltered_radiance_free(&p), prefiltered_radiance_free(&p1);
    free(rgb);
}

typedef struct {
    double alpha;
    int power;
} kappa_ctx;

/* (R.l)^power D(h) cos sin at theta_h (the 2 pi and the Jacobian cancel in the ratio). */
static double kappa_integrand(double theta, void *ctx)
{
    const kappa_ctx *k = ctx;
    double rl = cos(2.0 * theta);
    return pow(rl, k->power) * ggx_ndf(cos(theta), k->alpha) * cos(theta) * sin(theta);
}

static double kappa(double roughness)
{
    kappa_ctx two = {ggx_alpha(roughness), 2}, one = {ggx_alpha(roughness), 1};
    double pts[4] = {0.0, 0.5 * ggx_alpha(roughness), 2.0 * ggx_alpha(roughness), M_PI / 4.0};
    int n = pts[2] < pts[3] ? 4 : 2;
    if (n == 2)
        pts[1] = M_PI / 4.0;
    return quadrature_gk15_split(kappa_integrand, &two, pts, n, 1e-12, NULL) /
           quadrature_gk15_split(kappa_integrand, &one, pts, n, 1e-12, NULL);
}

static void test_linear(void)
{
    const double b[3] = {0.3, -0.5, 0.2};
    float *rgb = malloc(sizeof(float) * W * H * 3);
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            double m[EQUIRECT_MONOMIALS];
            equirect_texel_moments(W, H, i, j, m);
            double v = 1.0 + (b[0] * m[MONO_X] + b[1] * m[MONO_Y] + b[2] * m[MONO_Z]) / m[MONO_1];
            for (int c = 0; c < 3; ++c)
                rgb[((size_t)j * W + i) * 3 + c] = (float)v;
        }
    environment_equirect env = {W, H, rgb};
    equirect_pyramid src;
    CHECK(equirect_pyramid_build(&src, &env) == 0);
    for (int k = 0; k < LEVELS; ++k) {
        double r = prefiltered_level_roughness(k, LEVELS), kap = r > 0.0 ? kappa(r) : 1.0, worst = 0.0;
        for (int t = 0; t < 12; ++t) {
            double R[3];
            equirect_direction((t * 0.37 + 0.05) - floor(t * 0.37 + 0.05), (t + 0.5) / 12.0, R);
            float out[3];
            prefiltered_radiance_filter(&src, R, r, SAMPLES, 4.0 * M_PI / (64.0 * 32.0), out);
            double exact = 1.0 + kap * (b[0] * R[0] + b[1] * R[1] + b[2] * R[2]);
            worst = fmax(worst, fabs(out[0] - exact));
        }
        printf("r = %.1f: kappa %.4f, largest |P - (a + kappa b.R)| %.2e (|b| = %.2f)\n", r, kap, worst, 0.62);
        CHECK(worst < 0.02);
    }
    equirect_pyramid_free(&src);
    prefiltered_radiance p;
    CHECK(prefiltered_radiance_build(&p, &env, 64, LEVELS, SAMPLES, 2) == 0);
    double R[3];
    float out[3];
    equirect_texel_direction(p.width[2], p.height[2], 7, 5, R);
    prefiltered_radiance_lookup(&p, R, prefiltered_level_roughness(2, LEVELS), out);
    CHECK(out[0] == p.rgb[2][(5 * p.width[2] + 7) * 3]);
    prefiltered_radiance_free(&p);
    free(rgb);
}

int main(void)
{
    test_constant();
    test_linear();
    return check_report("test_prefiltered_radiance");
}
