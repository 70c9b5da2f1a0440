/* 9-coefficient SH irradiance (Ramamoorthi and Hanrahan 2001): the basis,
 * the exact per-texel projection and the convolved evaluation. See the
 * header for the equations and the truncation error. */
#include "environment/sh_irradiance.h"

#include <math.h>
#include <string.h>

#include "core/vec3.h" /* M_PI */

/* The basis' constants: 1/2 sqrt(1/pi), sqrt(3/(4 pi)), 1/2 sqrt(15/pi), 1/4 sqrt(5/pi), 1/4 sqrt(15/pi). */
static double k00(void) { return 0.5 * sqrt(1.0 / M_PI); }
static double k1(void) { return sqrt(3.0 / (4.0 * M_PI)); }
static double k2(void) { return 0.5 * sqrt(15.0 / M_PI); }
static double k20(void) { return 0.25 * sqrt(5.0 / M_PI); }
static double k22(void) { return 0.25 * sqrt(15.0 / M_PI); }

double sh9_cosine_band(int l) { return l == 0 ? M_PI : l == 1 ? 2.0 * M_PI / 3.0 : l == 2 ? M_PI / 4.0 : 0.0; }

/* Y_lm written on the ten monomials {1, x, y, z, xy, yz, xz, x^2, y^2, z^2}
 * (values of them at a point, or their integrals over a texel). */
static void basis_from_monomials(const double m[EQUIRECT_MONOMIALS], double y[SH9_COEFFICIENTS])
{
    y[0] = k00() * m[MONO_1];
    y[1] = k1() * m[MONO_Y];
    y[2] = k1() * m[MONO_Z];
    y[3] = k1() * m[MONO_X];
    y[4] = k2() * m[MONO_XY];
    y[5] = k2() * m[MONO_YZ];
    y[6] = k20() * (3.0 * m[MONO_ZZ] - m[MONO_1]);
    y[7] = k2() * m[MONO_XZ];
    y[8] = k22() * (m[MONO_XX] - m[MONO_YY]);
}

void sh9_basis(const double w[3], double y[SH9_COEFFICIENTS])
{
    double x = w[0], yy = w[1], z = w[2];
    double m[EQUIRECT_MONOMIALS] = {1.0, x, yy, z, x * yy, yy * z, x * z, x * x, yy * yy, z * z};
    basis_from_monomials(m, y);
}

static int band_of(int k) { return k == 0 ? 0 : k < 4 ? 1 : 2; }

/* One row's contribution (summed alone, then added: the order is fixed). */
static void project_row(const environment_equirect *env, int j, double row[SH9_COEFFICIENTS][3])
{
    memset(row, 0, sizeof(double) * SH9_COEFFICIENTS * 3);
    for (int i = 0; i < env->width; ++i) {
        double m[EQUIRECT_MONOMIALS], y[SH9_COEFFICIENTS];
        equirect_texel_moments(env->width, env->height, i, j, m);
        basis_from_monomials(m, y);
        const float *L = env->rgb + ((size_t)j * env->width + i) * 3;
        for (int k = 0; k < SH9_COEFFICIENTS; ++k)
            for (int c = 0; c < 3; ++c)
                row[k][c] += L[c] * y[k];
    }
}

void sh9_project_equirect(const environment_equirect *env, sh9_rgb *out)
{
    memset(out, 0, sizeof *out);
    for (int j = 0; j < env->height; ++j) {
        double row[SH9_COEFFICIENTS][3];
        project_row(env, j, row);
        for (int k = 0; k < SH9_COEFFICIENTS; ++k)
            for (int c = 0; c < 3; ++c)
                out->c[k][c] += row[k][c];
    }
}

void sh9_irradiance(const sh9_rgb *sh, const double n[3], double e[3])
{
    double y[SH9_COEFFICIENTS];
    sh9_basis(n, y);
    e[0] = e[1] = e[2] = 0.0;
    for (int k = 0; k < SH9_COEFFICIENTS; ++k)
        for (int c = 0; c < 3; ++c)
            e[c] += sh9_cosine_band(band_of(k)) * sh->c[k][c] * y[k];
}

void sh9_irradiance_clamped(const sh9_rgb *sh, const double n[3], double e[3])
{
    sh9_irradiance(sh, n, e);
    for (int c = 0; c < 3; ++c)
        e[c] = fmax(0.0, e[c]);
}
