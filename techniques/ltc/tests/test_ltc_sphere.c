/* The LTC polygon and sphere integrals (ltc/ltc_sphere.h)
 * against closed forms:
 *  - the identity M (the clamped cosine itself): the cap's form factor is
 *    sin^2(sigma) cos(theta) while the cap is above the horizon, and the
 *    exact horizon-clipped sphere form factor (Lagarde & de Rousiers 2014,
 *    sphere_illuminance_frostbite / pi) where it straddles it: checks the
 *    clipping and the equal-area N-gon (1024 sides);
 *  - the hemisphere as a polygon (a large square around +z clipped at the
 *    horizon): form factor 1;
 *  - a sheared, scaled M: the polygon integral of a small polygon equals
 *    D(w) times its solid angle (ltc/ltc_ggx.h's density, an independent
 *    formula);
 *  - the N-gon converges to the exact cap (straddling the horizon) as N
 *    grows;
 *  - either winding gives the same value; a polygon below the horizon 0;
 *  - the whole evaluation through a table whose every texel is the clamped
 *    cosine (M^-1 = I) with magnitude E and Fresnel term B: E times the
 *    cap's exact form factor over pi sin^2 sigma, and the Fresnel blend
 *    f0 E + (1 - f0) B. */
#include <math.h>
#include <stdio.h>

#include "core/vec3.h"
#include "ltc/ltc_ggx.h"
#include "ltc/ltc_sphere.h"
#include "realtime/sphere_illuminance.h"
#include "tests/check.h"

static const float IDENTITY[4] = {1.0f, 0.0f, 1.0f, 0.0f};

static vec3 direction(double theta, double phi)
{
    return v3((float)(sin(theta) * cos(phi)), (float)(sin(theta) * sin(phi)), (float)cos(theta));
}

static void check_cosine_caps(void)
{
    const double sins[] = {0.00465, 0.05, 0.3, 0.7};
    const double thetas[] = {0.0, 0.4, 1.2, 1.5, 1.57, 1.65};
    vec3 v = direction(0.7, 0.3);
    for (int s = 0; s < 4; ++s)
        for (int k = 0; k < 6; ++k) {
            vec3 lc = direction(thetas[k], 2.0);
            double want = sphere_illuminance_frostbite(lc.z, (float)sins[s]) / M_PI;
            double got = ltc_sphere_integral(IDENTITY, v, lc, (float)sins[s], 1024);
            double scale = sins[s] * sins[s];
            CHECK_MSG(fabs(got - want) <= 2e-4 * scale + 1e-9, "sin %g theta %g: %.9g vs %.9g", sins[s], thetas[k],
                      got, want);
        }
}

static void check_hemisphere(void)
{
    vec3 offsets[4] = {v3(100, 100, -1), v3(-100, 100, -1), v3(-100, -100, -1), v3(100, -100, -1)};
    vec3 reversed[4] = {offsets[3], offsets[2], offsets[1], offsets[0]};
    vec3 centre = v3(0.0f, 0.0f, 1.0f);
    CHECK_NEAR(ltc_polygon_form_factor(centre, offsets, 4), 1.0, 2e-4); /* z = 0 edges at distance 100 */
    CHECK_NEAR(ltc_polygon_form_factor(centre, reversed, 4), ltc_polygon_form_factor(centre, offsets, 4), 1e-7);
    vec3 below = v3(0.0f, 0.0f, -1.0f);
    CHECK(ltc_polygon_form_factor(below, offsets, 4) == 0.0f);
}

/* Solid angle of the small polygon by the cosine's form factor:
 * F = cos(theta) Omega / pi to first order. */
static void check_small_polygon(void)
{
    const float mf[4] = {2.5f, -0.8f, 1.7f, 0.4f};
    const double md[4] = {2.5, -0.8, 1.7, 0.4};
    vec3 v = direction(0.9, 0.0), w = direction(0.5, 0.6), offsets[4], cos_offsets[4];
    vec3 a = v3_normalize(v3_cross(v3(0, 0, 1), w)), b = v3_cross(w, a);
    const float h = 2e-3f;
    for (int k = 0; k < 4; ++k) {
        float sx = (k == 0 || k == 3) ? h : -h, sy = k < 2 ? h : -h;
        offsets[k] = v3_add(v3_scale(a, sx), v3_scale(b, sy));
        cos_offsets[k] = v3(mf[0] * offsets[k].x + mf[1] * offsets[k].z, mf[2] * offsets[k].y,
                            mf[3] * offsets[k].x + offsets[k].z);
    }
    double omega = M_PI * ltc_polygon_form_factor(w, offsets, 4) / w.z;
    vec3 cw = v3(mf[0] * w.x + mf[1] * w.z, mf[2] * w.y, mf[3] * w.x + w.z); /* v in the xz plane: frame = world */
    double got = ltc_polygon_form_factor(cw, cos_offsets, 4);
    double wd[3] = {w.x, w.y, w.z};
    double want = ltc_density(md, wd) * omega;
    CHECK_MSG(fabs(got / want - 1.0) < 2e-3, "small polygon %.9g vs D omega %.9g", got, want);
    (void)v;
}

/* The N-gon's convergence to the exact cap (identity M, the cap straddling
 * the horizon: the integrand is far from linear over it). */
static void check_ngon_convergence(void)
{
    vec3 v = direction(1.0, 0.0), lc = direction(1.45, 3.0);
    const float sin_sigma = 0.5f;
    double exact = sphere_illuminance_frostbite(lc.z, sin_sigma) / M_PI;
    double e8 = fabs(ltc_sphere_integral(IDENTITY, v, lc, sin_sigma, 8) - exact);
    double e32 = fabs(ltc_sphere_integral(IDENTITY, v, lc, sin_sigma, 32) - exact);
    printf("N-gon against the exact cap %.6g: 8-gon off by %.3g, 32-gon by %.3g\n", exact, e8, e32);
    CHECK_MSG(e32 < 0.25 * e8 && e32 < 1e-3 * exact, "8-gon %.3g, 32-gon %.3g of %.6g", e8, e32, exact);
}

static void check_table_chain(void)
{
    ltc_table t;
    CHECK(ltc_table_alloc(&t, 4) == 0);
    for (int k = 0; k < 16; ++k) {
        float *x = t.data + k * LTC_CHANNELS;
        x[LTC_A] = 1.0f, x[LTC_B] = 0.0f, x[LTC_C] = 1.0f, x[LTC_D] = 0.0f;
        x[LTC_MAGNITUDE] = 0.8f, x[LTC_FRESNEL] = 0.1f;
    }
    const float sin_sigma = 0.05f;
    vec3 v = direction(0.6, 1.0), lc = direction(0.7, 2.5);
    double want = 0.8 * sphere_illuminance_frostbite(lc.z, sin_sigma) / (M_PI * M_PI * sin_sigma * sin_sigma);
    double got = ltc_sphere_ggx(&t, v, lc, sin_sigma, 0.5f);
    CHECK_MSG(fabs(got / want - 1.0) < 2e-3, "%.7g vs %.7g", got, want);
    double blended = ltc_sphere_ggx_fresnel(&t, v, lc, sin_sigma, 0.5f, 0.3f);
    CHECK_NEAR(blended, got * (0.3 * 0.8 + 0.7 * 0.1) / 0.8, 1e-6 * got);
    CHECK(ltc_sphere_specular(&t, v, lc, sin_sigma, 0.5f, 0.3f) == (float)blended);
    ltc_table_free(&t);
}

int main(void)
{
    check_table_chain();
    check_cosine_caps();
    check_hemisphere();
    check_small_polygon();
    check_ngon_convergence();
    return check_report("ltc_sphere");
}
