/* The exact irradiance map (environment/irradiance_map.h):
 *  - an environment linear in w stored as exact texel means, L = a + b.w
 *    (a >= |b|): E(n) = pi a + 2 pi/3 b.n, but for the piecewise-constant
 *    texels' O(h^2) error and the horizon's ring of texels (h = pi / 128:
 *    1e-3 relative);
 *  - the map's entries equal an independent brute-force quadrature (texel
 *    centre radiance x max(0, n.w_t) x Omega_t over every texel) of an
 *    environment with a small bright sun, and blocks of 8 x 8 texels agree
 *    with single texels;
 *  - the lookup returns the entry at a texel centre, and interpolates
 *    between them to a small error (printed);
 *  - the bits do not depend on the thread count. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "environment/irradiance_map.h"
#include "core/vec3.h" /* M_PI */
#include "tests/check.h"

enum { W = 256, H = 128 };

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static const double B[3] = {0.3, -0.5, 0.2};
static const double SUN[3] = {0.48, 0.6, 0.64};

static float *make_env(int sun)
{
    float *rgb = malloc(sizeof(float) * W * H * 3);
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            double m[EQUIRECT_MONOMIALS], w[3];
            equirect_texel_moments(W, H, i, j, m);
            equirect_texel_direction(W, H, i, j, w);
            double mean = 1.0 + (B[0] * m[MONO_X] + B[1] * m[MONO_Y] + B[2] * m[MONO_Z]) / m[MONO_1];
            double value = sun ? 0.2 + 0.3 * fmax(0.0, w[1]) + (dot3(w, SUN) > cos(0.05) ? 500.0 : 0.0) : mean;
            for (int c = 0; c < 3; ++c)
                rgb[((size_t)j * W + i) * 3 + c] = (float)(value * (1.0 + 0.5 * c));
        }
    return rgb;
}

static void brute_force(const float *rgb, const double n[3], double e[3])
{
    e[0] = e[1] = e[2] = 0.0;
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            double w[3];
            equirect_texel_direction(W, H, i, j, w);
            double k = fmax(0.0, dot3(n, w)) * equirect_texel_solid_angle(W, H, j);
            for (int c = 0; c < 3; ++c)
                e[c] += rgb[((size_t)j * W + i) * 3 + c] * k;
        }
}

static void test_linear(void)
{
    float *rgb = make_env(0);
    environment_equirect env = {W, H, rgb};
    irradiance_map m;
    CHECK(irradiance_map_build(&m, &env, 32, 0, 2) == 0);
    double worst = 0.0;
    for (int j = 0; j < m.height; ++j)
        for (int i = 0; i < m.width; ++i) {
            double n[3];
            equirect_texel_direction(m.width, m.height, i, j, n);
            double exact = M_PI + 2.0 * M_PI / 3.0 * dot3(B, n);
            for (int c = 0; c < 3; ++c)
                worst = fmax(worst, fabs(m.rgb[((size_t)j * m.width + i) * 3 + c] / (1.0 + 0.5 * c) - exact));
        }
    printf("linear environment: largest |E - closed form| %.2e (of ~pi)\n", worst);
    CHECK(worst < 1e-3 * M_PI);
    irradiance_map_free(&m);
    free(rgb);
}

static void test_sun_against_brute_force(void)
{
    float *rgb = make_env(1);
    environment_equirect env = {W, H, rgb};
    irradiance_map fine, coarse, coarse1;
    CHECK(irradiance_map_build(&fine, &env, 16, 0, 2) == 0);
    CHECK(irradiance_map_build(&coarse, &env, 16, 3, 2) == 0);
    CHECK(irradiance_map_build(&coarse1, &env, 16, 3, 1) == 0);
    CHECK(coarse.reduction == 3);
    CHECK(memcmp(coarse.rgb, coarse1.rgb, sizeof(float) * 16 * 8 * 3) == 0);
    double worst = 0.0, worst_blocks = 0.0;
    for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 16; ++i) {
            double n[3], e[3];
            equirect_texel_direction(16, 8, i, j, n);
            brute_force(rgb, n, e);
            for (int c = 0; c < 3; ++c) {
                size_t k = ((size_t)j * 16 + i) * 3 + c;
                worst = fmax(worst, fabs(fine.rgb[k] - e[c]) / e[c]);
                worst_blocks = fmax(worst_blocks, fabs(coarse.rgb[k] - fine.rgb[k]) / fine.rgb[k]);
            }
        }
    printf("sun environment: map vs brute force %.2e, 8x8 blocks vs texels %.2e (relative)\n", worst, worst_blocks);
    CHECK(worst < 2e-3);
    CHECK(worst_blocks < 5e-3);
    /* the lookup: exact at texel centres; between them, against the quadrature */
    double n[3], e[3];
    float f[3];
    equirect_texel_direction(16, 8, 5, 3, n);
    irradiance_map_lookup(&fine, n, f);
    CHECK(f[0] == fine.rgb[(3 * 16 + 5) * 3] && f[2] == fine.rgb[(3 * 16 + 5) * 3 + 2]);
    equirect_direction(0.41, 0.47, n);
    irradiance_map_lookup(&fine, n, f);
    irradiance_map_quadrature(&env, 0, n, e);
    printf("bilinear lookup of a 16x8 map between texels: relative error %.3f\n", fabs(f[0] - e[0]) / e[0]);
    CHECK(fabs(f[0] - e[0]) < 0.1 * e[0]);
    irradiance_map_free(&fine), irradiance_map_free(&coarse), irradiance_map_free(&coarse1);
    free(rgb);
}

int main(void)
{
    test_linear();
    test_sun_against_brute_force();
    return check_report("test_irradiance_map");
}
