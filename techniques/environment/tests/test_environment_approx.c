/* The engines' ambient combinations (environment/environment_approx.h) under a
 * constant environment L, where every lighting approximation is exact:
 *  - E(n) = pi L from SH (exactly) and from the map (to its horizon ring's
 *    error, 1e-3 relative at 64 x 32), so unoccluded diffuse per unit albedo
 *    is L, ao-n and ao-bent are L AO (the white-dome AO shading: the case the
 *    talk says AO x probe is accurate for), the multi-bounce kinds
 *    L G(AO, rho) with the talk's G per channel;
 *  - the specular term is L (F0 A + B) V_s;
 *  - the bent normal is normalised, and falls back to n when zero;
 * and under a linear environment L = 2 + b.w the bent-normal kinds read E at
 * the bent normal (2 pi + 2 pi/3 b.bent), the others at n; the screen pass
 * (environment/environment_screen.h) gives each pixel's value (a zero bent
 * vector: n), 0 outside the mask, and reflects the view about n. */
#include <math.h>
#include <stdlib.h>

#include "core/vec3.h" /* M_PI */
#include "environment/environment_approx.h"
#include "environment/environment_screen.h"
#include "tests/check.h"

enum { W = 64, H = 32 };

static float *env_of(const double b[3])
{
    float *rgb = malloc(sizeof(float) * W * H * 3);
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            double m[EQUIRECT_MONOMIALS];
            equirect_texel_moments(W, H, i, j, m);
            double v = 2.0 + (b[0] * m[MONO_X] + b[1] * m[MONO_Y] + b[2] * m[MONO_Z]) / m[MONO_1];
            for (int c = 0; c < 3; ++c)
                rgb[((size_t)j * W + i) * 3 + c] = (float)v;
        }
    return rgb;
}

typedef struct {
    sh9_rgb sh;
    irradiance_map map;
    prefiltered_radiance pre;
    dfg_lut dfg;
    multibounce_model mb;
    environment_lighting l;
} lighting;

static void lighting_build(lighting *x, const float *rgb)
{
    environment_equirect env = {W, H, rgb};
    sh9_project_equirect(&env, &x->sh);
    CHECK(irradiance_map_build(&x->map, &env, 32, 0, 1) == 0);
    CHECK(prefiltered_radiance_build(&x->pre, &env, 32, 5, 64, 1) == 0);
    CHECK(dfg_lut_build(&x->dfg, 32, 2) == 0);
    x->mb = multibounce_model_jimenez2016();
    environment_lighting l = {&x->sh, &x->map, &x->pre, &x->dfg, &x->mb};
    x->l = l;
}

static void lighting_free(lighting *x)
{
    irradiance_map_free(&x->map);
    prefiltered_radiance_free(&x->pre);
    dfg_lut_free(&x->dfg);
}

static void test_constant(void)
{
    double zero[3] = {0, 0, 0};
    float *rgb = env_of(zero);
    lighting x;
    lighting_build(&x, rgb);
    double n[3] = {0.0, 0.6, 0.8}, bent[3] = {0.36, 0.48, 0.8}, ub[3], albedo[3] = {0.2, 0.5, 0.9}, ao = 0.63;
    environment_unit_bent(bent, n, ub);
    for (int s = 0; s < ENVIRONMENT_IRRADIANCE_SOURCES; ++s)
        for (int k = 0; k < ENVIRONMENT_DIFFUSE_KINDS; ++k) {
            double out[3];
            environment_diffuse(&x.l, (environment_irradiance_source)s, (environment_diffuse_kind)k, n, ub, ao, albedo, out);
            for (int c = 0; c < 3; ++c) {
                double occ = k == ENVIRONMENT_DIFFUSE_UNOCCLUDED ? 1.0
                             : k <= ENVIRONMENT_DIFFUSE_AO_BENT  ? ao
                                                         : gtao_multibounce(&x.mb, ao, albedo[c]);
                /* SH: exact; the map: its horizon ring at 64 x 32 texels (6.6e-4 relative) */
                CHECK_NEAR(out[c], 2.0 * occ, (s == ENVIRONMENT_IRRADIANCE_SH9 ? 1e-6 : 1e-3) * out[c]);
            }
        }
    double R[3] = {0.0, 0.6, 0.8}, f0[3] = {0.04, 0.04, 0.04}, spec[3];
    float ab[3];
    environment_specular(&x.l, R, 0.7, 0.4, f0, 0.5, spec);
    dfg_lut_sample(&x.dfg, 0.7f, 0.4f, ab);
    CHECK_NEAR(spec[0], 2.0 * (0.04 * ab[0] + ab[1]) * 0.5, 1e-6);
    double zero_bent[3] = {0, 0, 0};
    environment_unit_bent(zero_bent, n, ub);
    CHECK(ub[0] == n[0] && ub[1] == n[1] && ub[2] == n[2]);
    lighting_free(&x);
    free(rgb);
}

static void test_linear_bent(void)
{
    double b[3] = {0.3, -0.5, 0.2};
    float *rgb = env_of(b);
    lighting x;
    lighting_build(&x, rgb);
    double n[3] = {0.0, 1.0, 0.0}, bent[3] = {0.6, 0.8, 0.0}, albedo[3] = {1.0, 1.0, 1.0}, out[3];
    environment_diffuse(&x.l, ENVIRONMENT_IRRADIANCE_SH9, ENVIRONMENT_DIFFUSE_AO_BENT, n, bent, 0.5, albedo, out);
    double e = 2.0 * M_PI + 2.0 * M_PI / 3.0 * (b[0] * 0.6 + b[1] * 0.8);
    CHECK_NEAR(out[0], e / M_PI * 0.5, 2e-3); /* the 64 x 32 texels' O(h^2) */
    double on_n[3];
    environment_diffuse(&x.l, ENVIRONMENT_IRRADIANCE_SH9, ENVIRONMENT_DIFFUSE_AO_N, n, bent, 0.5, albedo, on_n);
    CHECK_NEAR(on_n[0], (2.0 * M_PI + 2.0 * M_PI / 3.0 * b[1]) / M_PI * 0.5, 2e-3);
    lighting_free(&x);
    free(rgb);
}

static void test_screen(void)
{
    double b[3] = {0.3, -0.5, 0.2};
    float *rgb = env_of(b);
    lighting x;
    lighting_build(&x, rgb);
    /* pixel 0: n = +Y seen from straight above; 1: a tilted normal, zero bent vector; 2: outside the mask */
    float nx[3] = {0, 0.6f, 0}, ny[3] = {1, 0.8f, 1}, nz[3] = {0, 0, 0}, zero[3] = {0, 0, 0};
    float bx[3] = {0.2f, 0, 0}, by[3] = {0.9f, 0, 0}, ao[3] = {0.7f, 0.4f, 0.5f}, mask[3] = {1, 1, 0};
    float rough[3] = {0.3f, 0.6f, 0.3f}, alb[3] = {0.5f, 0.5f, 0.5f};
    so_screen_buffers buf = {.width = 3, .height = 1, .normal = {nx, ny, nz}, .position = {zero, zero, zero},
                             .mask = mask, .roughness = rough, .ao_cosine = ao, .bent = {bx, by, zero}};
    const float *albedo[3] = {alb, alb, alb};
    float o[3][3], *out[3] = {o[0], o[1], o[2]};
    environment_screen_diffuse(&x.l, ENVIRONMENT_IRRADIANCE_MAP, ENVIRONMENT_DIFFUSE_MULTIBOUNCE_BENT, &buf, albedo, out);
    double n0[3] = {0, 1, 0}, bent0[3] = {0.2, 0.9, 0}, ub[3], rho[3] = {0.5, 0.5, 0.5}, e[3];
    environment_unit_bent(bent0, n0, ub);
    environment_diffuse(&x.l, ENVIRONMENT_IRRADIANCE_MAP, ENVIRONMENT_DIFFUSE_MULTIBOUNCE_BENT, n0, ub, 0.7, rho, e);
    CHECK(o[0][0] == (float)e[0] && o[2][0] == (float)e[2]);
    double n1[3] = {0.6f, 0.8f, 0};
    environment_diffuse(&x.l, ENVIRONMENT_IRRADIANCE_MAP, ENVIRONMENT_DIFFUSE_MULTIBOUNCE_BENT, n1, n1, 0.4, rho, e);
    CHECK(o[0][1] == (float)e[0]);
    CHECK(o[0][2] == 0.0f && o[1][2] == 0.0f);
    so_pixel_inputs in;
    vec3 eye = v3(0, 5, 0);
    CHECK(so_inputs_compute(&buf, eye, -1.0, &in) == 0);
    environment_screen_specular(&x.l, &buf, &in, eye, 0.04, NULL, out);
    double spec[3], f0[3] = {0.04, 0.04, 0.04};
    environment_specular(&x.l, n0, 1.0, 0.3f, f0, 1.0, spec);
    CHECK_NEAR(o[0][0], spec[0], 1e-6);
    CHECK(o[0][2] == 0.0f);
    so_inputs_free(&in);
    lighting_free(&x);
    free(rgb);
}

int main(void)
{
    test_screen();
    test_constant();
    test_linear_bent();
    return check_report("test_environment_approx");
}
