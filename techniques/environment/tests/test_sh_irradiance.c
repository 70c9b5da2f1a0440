/* 9-coefficient SH irradiance (environment/sh_irradiance.h) and the equirect
 * texel moments it is built on (environment/environment_equirect.h):
 *  - the closed-form texel moments against a fine midpoint quadrature, and
 *    the texel solid angles summing to 4 pi;
 *  - a constant environment L: E = pi L in every direction (exact);
 *  - an environment of degree <= 2 in w, stored as its exact texel means:
 *    E is the closed form (a + b.w: pi a + 2 pi/3 b.n; x y: pi/4 n_x n_y)
 *    but for the piecewise-constant texels' own O(h^2) error (h = pi / 128:
 *    1e-3 relative; the basis integrals themselves are exact);
 *  - a clamped-cosine lobe max(0, w.d): E9 equals the 9-term closed form
 *    pi/4 + pi/3 cos g + 5 pi/64 (3 cos^2 g - 1)/2, and its truncation error
 *    against the exact 2/3 ((pi - g) cos g + sin g) is largest at g = 0 and
 *    g = pi, -pi/192 = -0.0164 at both (0.78% of the peak 2 pi/3);
 *  - the exact projection against an independent midpoint-rule projection. */
#include <math.h>
#include <stdlib.h>

#include "environment/sh_irradiance.h"
#include "core/vec3.h" /* M_PI */
#include "tests/check.h"

enum { W = 256, H = 128 };

static void normalize3(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    v[0] /= l, v[1] /= l, v[2] /= l;
}

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void test_moments(void)
{
    double total = 0.0;
    for (int j = 0; j < H; ++j)
        total += W * equirect_texel_solid_angle(W, H, j);
    CHECK_NEAR(total, 4.0 * M_PI, 1e-12);
    /* the mapping of core/optics/environment_map.h: +X at the centre, -Z at u = 1/4, the zenith at v = 0 */
    double w[3], u, v, expect[4][4] = {{0.5, 0.5, 1, 0}, {0.25, 0.5, 0, -1}, {0.75, 0.5, 0, 1}, {0.3, 0.0, 0, 0}};
    for (int k = 0; k < 4; ++k) {
        equirect_direction(expect[k][0], expect[k][1], w);
        CHECK_NEAR(w[0], expect[k][2], 1e-15);
        CHECK_NEAR(w[2], expect[k][3], 1e-15);
    }
    equirect_direction(0.123, 0.77, w);
    equirect_coordinates(w, &u, &v);
    CHECK_NEAR(u, 0.123, 1e-14);
    CHECK_NEAR(v, 0.77, 1e-14);
    int texels[3][2] = {{0, 0}, {17, 40}, {200, 127}};
    for (int t = 0; t < 3; ++t) {
        int n = 200, i = texels[t][0], j = texels[t][1];
        double m[EQUIRECT_MONOMIALS], q[EQUIRECT_MONOMIALS] = {0};
        equirect_texel_moments(W, H, i, j, m);
        for (int a = 0; a < n; ++a)
            for (int b = 0; b < n; ++b) {
                double u = (i + (a + 0.5) / n) / W, v = (j + (b + 0.5) / n) / H, w[3];
                equirect_direction(u, v, w);
                double dw = sin(M_PI * v) * (2.0 * M_PI / W / n) * (M_PI / H / n);
                double mono[EQUIRECT_MONOMIALS] = {1, w[0], w[1], w[2], w[0] * w[1], w[1] * w[2], w[0] * w[2],
                                                   w[0] * w[0], w[1] * w[1], w[2] * w[2]};
                for (int k = 0; k < EQUIRECT_MONOMIALS; ++k)
                    q[k] += mono[k] * dw;
            }
        for (int k = 0; k < EQUIRECT_MONOMIALS; ++k)
            CHECK_NEAR(m[k], q[k], 1e-6 * m[MONO_1]);
    }
}

/* An environment whose texel (i, j) holds f's exact texel mean, f = c0 + c . (m_x, m_y, m_z) + cxy m_xy. */
static float *polynomial_env(double c0, const double c[3], double cxy)
{
    float *rgb = malloc(sizeof(float) * W * H * 3);
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            double m[EQUIRECT_MONOMIALS];
            equirect_texel_moments(W, H, i, j, m);
            double mean = (c0 * m[MONO_1] + c[0] * m[MONO_X] + c[1] * m[MONO_Y] + c[2] * m[MONO_Z] +
                           cxy * m[MONO_XY]) / m[MONO_1];
            for (int k = 0; k < 3; ++k)
                rgb[((size_t)j * W + i) * 3 + k] = (float)(mean * (k + 1));
        }
    return rgb;
}

static const double NORMALS[4][3] = {{0, 1, 0}, {0.6, -0.64, 0.48}, {-1, 0, 0}, {0.267261, 0.534522, -0.801784}};

static void test_constant_and_polynomials(void)
{
    double zero[3] = {0, 0, 0}, b[3] = {0.3, -0.5, 0.2};
    float *constant = polynomial_env(1.5, zero, 0.0), *linear = polynomial_env(1.0, b, 0.0),
          *xy = polynomial_env(0.0, zero, 1.0);
    environment_equirect envs[3] = {{W, H, constant}, {W, H, linear}, {W, H, xy}};
    sh9_rgb sh[3];
    for (int k = 0; k < 3; ++k)
        sh9_project_equirect(&envs[k], &sh[k]);
    for (int t = 0; t < 4; ++t) {
        double n[3] = {NORMALS[t][0], NORMALS[t][1], NORMALS[t][2]}, e[3][3];
        normalize3(n);
        for (int k = 0; k < 3; ++k)
            sh9_irradiance(&sh[k], n, e[k]);
        for (int c = 0; c < 3; ++c) {
            CHECK_NEAR(e[0][c], M_PI * 1.5 * (c + 1), 1e-9);
            CHECK_NEAR(e[1][c], (M_PI + 2.0 * M_PI / 3.0 * dot3(b, n)) * (c + 1), 1e-3 * (c + 1));
            CHECK_NEAR(e[2][c], M_PI / 4.0 * n[0] * n[1] * (c + 1), 1e-3 * (c + 1));
        }
    }
    free(constant), free(linear), free(xy);
}

/* E9 of the clamped-cosine lobe (header). */
static double lobe_e9(double g)
{
    double c = cos(g);
    return M_PI / 4.0 + M_PI / 3.0 * c + 5.0 * M_PI / 64.0 * (3.0 * c * c - 1.0) / 2.0;
}

static double lobe_exact(double g) { return 2.0 / 3.0 * ((M_PI - g) * cos(g) + sin(g)); }

static void test_cosine_lobe(void)
{
    double d[3] = {0.3, 0.8, -0.5};
    normalize3(d);
    float *rgb = malloc(sizeof(float) * W * H * 3);
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            double w[3];
            equirect_texel_direction(W, H, i, j, w);
            for (int k = 0; k < 3; ++k)
                rgb[((size_t)j * W + i) * 3 + k] = (float)fmax(0.0, dot3(w, d));
        }
    environment_equirect env = {W, H, rgb};
    sh9_rgb sh;
    sh9_project_equirect(&env, &sh);
    double worst = 0.0, worst_g = 0.0;
    for (int t = 0; t <= 180; ++t) {
        double g = M_PI * t / 180.0, n[3], e[3];
        /* n at angle g from d, turned about an axis normal to d */
        double a[3] = {d[1], -d[0], 0.0};
        normalize3(a);
        for (int k = 0; k < 3; ++k)
            n[k] = cos(g) * d[k] + sin(g) * a[k];
        sh9_irradiance(&sh, n, e);
        CHECK_NEAR(e[1], lobe_e9(g), 2e-3);
        double err = lobe_e9(g) - lobe_exact(g);
        if (fabs(err) > fabs(worst))
            worst = err, worst_g = g;
    }
    CHECK_NEAR(worst, -M_PI / 192.0, 1e-12);
    CHECK_NEAR(lobe_e9(0.0) - lobe_exact(0.0), -M_PI / 192.0, 1e-12);
    CHECK_NEAR(lobe_e9(M_PI) - lobe_exact(M_PI), -M_PI / 192.0, 1e-12);
    printf("cosine lobe: 9-term truncation error %.5f at g = %.0f deg (%.2f%% of the peak %.4f)\n", worst,
           worst_g * 180.0 / M_PI, 100.0 * fabs(worst) / lobe_exact(0.0), lobe_exact(0.0));
    /* an independent projection: the midpoint rule (centre values of Y times the solid angle) */
    double q[SH9_COEFFICIENTS] = {0};
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            double w[3], y[SH9_COEFFICIENTS], o = equirect_texel_solid_angle(W, H, j);
            equirect_texel_direction(W, H, i, j, w);
            sh9_basis(w, y);
            for (int k = 0; k < SH9_COEFFICIENTS; ++k)
                q[k] += rgb[((size_t)j * W + i) * 3] * y[k] * o;
        }
    for (int k = 0; k < SH9_COEFFICIENTS; ++k)
        CHECK_NEAR(sh.c[k][0], q[k], 2e-4);
    free(rgb);
}

int main(void)
{
    test_moments();
    test_constant_and_polynomials();
    test_cosine_lobe();
    return check_report("test_sh_irradiance");
}
