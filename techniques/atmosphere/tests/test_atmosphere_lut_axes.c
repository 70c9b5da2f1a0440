/* The atmosphere LUTs' axes (atmosphere/atmosphere_lut_axes.h): the published
 * mappings of Yusov 2013 and Bruneton & Neyret 2008 at values that follow
 * from their definitions (endpoints, the horizon split into two halves with
 * their own ends, a power's or a distance's half-way point), the round trip
 * grid point -> parameter -> position on every point but those the papers
 * clamp (checked apart: what they hold), Yusov's positions against the
 * texture coordinates his sample's shaders compute, and a Yusov table at 4x the talk's
 * size per spatial axis, whose sky (atmosphere/atmosphere_lut_errors.h) is within
 * one sRGB code value at 95% of the pixels: where the parametrization's
 * table should be near exact. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "atmosphere/atmosphere_lut_axes.h"
#include "atmosphere/atmosphere_lut_errors.h"
#include "atmosphere/atmosphere_luts.h"
#include "atmosphere/atmosphere_luts_writers.h"
#include "report/claim_thresholds.h"
#include "tests/check.h"

#define PI 3.14159265358979323846
#define CHECK_K 3.0 /* standard errors */

static atmosphere_lut_frame frame(atmosphere_lut_parametrization kind)
{
    atmosphere_model m = atmosphere_model_default();
    return (atmosphere_lut_frame){kind, m.bottom_radius, m.top_radius, ATMOSPHERE_LUT_MAX_ALTITUDE};
}

static const int TALK[4] = {8, 64, 8, 4};

static atmosphere_lut_position at(const atmosphere_lut_frame *f, const int n[4], double theta_s, double theta_v,
                                  double y, int axis)
{
    atmosphere_lut_position p[4];
    atmosphere_lut_positions(f, n, theta_s, theta_v, y, 0.5, p);
    return p[axis];
}

/* Bruneton's sun formula: u(1) = 1, u(0) = 0.37 (atan 0 = 0), u(-0.1975) = 0 to 1e-3, below clamped. */
static void test_sun_formula(void)
{
    CHECK_NEAR(atmosphere_lut_sun_unit(1.0), 1.0, 1e-12);
    CHECK_NEAR(atmosphere_lut_sun_unit(0.0), 0.37, 1e-12);
    CHECK_NEAR(atmosphere_lut_sun_unit(ATMOSPHERE_LUT_MU_S_MIN), 0.0, 1e-3);
    CHECK(atmosphere_lut_sun_unit(-0.5) == atmosphere_lut_sun_unit(ATMOSPHERE_LUT_MU_S_MIN));
    for (double mu = -0.19; mu <= 1.0; mu += 0.01)
        CHECK_NEAR(atmosphere_lut_sun_from_unit(atmosphere_lut_sun_unit(mu)), mu, 1e-12);
    CHECK_NEAR(atmosphere_lut_horizon_cosine(0.0, 6.36e6), 0.0, 0.0);
    CHECK_NEAR(atmosphere_lut_horizon_cosine(2000.0, 6.36e6), -sqrt(1.0 - pow(6.36e6 / 6.362e6, 2.0)), 1e-12);
}

static void test_yusov(void)
{
    atmosphere_lut_frame f = frame(ATMOSPHERE_PARAM_YUSOV);
    double m = ATMOSPHERE_LUT_YUSOV_MARGIN, top = f.max_altitude;
    /* height: sqrt of the margin-clamped fraction: a quarter of the range sits half-way */
    CHECK_NEAR(at(&f, TALK, 0, 0, 0.0, 2).p, 0.0, 1e-12);
    CHECK_NEAR(at(&f, TALK, 0, 0, m, 2).p, 0.0, 1e-12);
    CHECK_NEAR(at(&f, TALK, 0, 0, top - m, 2).p, 7.0, 1e-12);
    CHECK_NEAR(at(&f, TALK, 0, 0, top, 2).p, 7.0, 1e-12);
    CHECK_NEAR(at(&f, TALK, 0, 0, m + 0.25 * (top - 2 * m), 2).p, 3.5, 1e-9);
    /* view: zenith at the last point; the horizon's two sides at n/2 and 0, nadir at n/2 - 1 */
    double y = 500.0, c = atmosphere_lut_horizon_cosine(y, f.bottom_radius), h = acos(c);
    atmosphere_lut_position zenith = at(&f, TALK, 0, 0.0, y, 1), nadir = at(&f, TALK, 0, PI, y, 1);
    atmosphere_lut_position above = at(&f, TALK, 0, h - 1e-9, y, 1), below = at(&f, TALK, 0, h + 1e-9, y, 1);
    CHECK_NEAR(zenith.p, 63.0, 1e-9);
    CHECK(zenith.lo == 32 && zenith.hi == 63 && above.lo == 32 && below.lo == 0 && below.hi == 31);
    CHECK_NEAR(nadir.p, 31.0, 1e-9);
    CHECK_NEAR(above.p, 32.0, 0.5);
    CHECK_NEAR(below.p, 0.0, 0.5);
    /* the power 0.2: (mu - c) / (1 - c) = 2^-5 sits half-way up the upper half */
    CHECK_NEAR(at(&f, TALK, 0, acos(c + (1.0 - c) / 32.0), y, 1).p, 32.0 + 15.5, 1e-9);
    CHECK_NEAR(at(&f, TALK, 0, acos(c - (c + 1.0) / 32.0), y, 1).p, 15.5, 1e-9);
    /* sun: the formula */
    CHECK_NEAR(at(&f, TALK, 0.0, 0, y, 0).p, 7.0, 1e-12);
    CHECK_NEAR(at(&f, TALK, 0.5 * PI, 0, y, 0).p, 0.37 * 7.0, 1e-12);
}

/* Yusov's texture coordinates as his sample's shaders write them
 * (OutdoorLightScattering, ZenithAngle2TexCoord and
 * WorldParams2InsctrLUTCoords: SafetyHeightMargin 16, HeightPower 0.5,
 * ViewZenithPower 0.2, the sun by Bruneton's formula), in [0, 1] texture
 * space: the upper half of the view axis on [0.5 + 0.5/D, 1 - 0.5/D], the
 * lower on [0.5/D, 0.5 - 0.5/D]; the other axes' texel centres at
 * (u (D - 1) + 0.5) / D. A texture coordinate is (p + 0.5) / n of a position. */
static double yusov_view_texcoord(double mu, double h, double D)
{
    double c = atmosphere_lut_horizon_cosine(h, 6360e3);
    if (mu > c)
        return 0.5 + 0.5 / D + pow(fmin(fmax((mu - c) / (1.0 - c), 0.0), 1.0), 0.2) * (D / 2 - 1) / D;
    return 0.5 / D + pow(fmin(fmax((c - mu) / (c + 1.0), 0.0), 1.0), 0.2) * (D / 2 - 1) / D;
}

static void test_yusov_texcoords(void)
{
    atmosphere_lut_frame f = frame(ATMOSPHERE_PARAM_YUSOV);
    int worst = 0;
    CHECK(f.bottom_radius == 6360e3);
    for (double y = 20.0; y < 1980.0; y += 97.0)
        for (double mu = -0.999; mu < 1.0; mu += 0.0371) {
            double h = y, top = f.max_altitude, m = 16.0;
            atmosphere_lut_position p[4];
            atmosphere_lut_positions(&f, TALK, acos(0.3), acos(mu), y, 0.5, p);
            double view = yusov_view_texcoord(mu, h, TALK[1]);
            double height = (pow((h - m) / (top - 2 * m), 0.5) * (TALK[2] - 1) + 0.5) / TALK[2];
            double sun = ((atan(0.3 * tan(1.26 * 1.1)) / 1.1 + (1.0 - 0.26)) * 0.5 * (TALK[0] - 1) + 0.5) / TALK[0];
            worst += fabs((p[1].p + 0.5) / TALK[1] - view) > 1e-12 || fabs((p[2].p + 0.5) / TALK[2] - height) > 1e-12 ||
                     fabs((p[0].p + 0.5) / TALK[0] - sun) > 1e-12;
        }
    CHECK_MSG(worst == 0, "%d points where a position is not Yusov's texture coordinate", worst);
}

static void test_bruneton(void)
{
    atmosphere_lut_frame f = frame(ATMOSPHERE_PARAM_BRUNETON);
    double R = f.bottom_radius, Rt = f.top_radius, top = f.max_altitude, H = sqrt(Rt * Rt - R * R);
    double rho_max = sqrt(pow(R + top, 2.0) - R * R);
    /* height: the distance to the horizon rho, linear: rho_max / 2 sits half-way */
    CHECK_NEAR(at(&f, TALK, 0, 0, 0.0, 2).p, 0.0, 1e-12);
    CHECK_NEAR(at(&f, TALK, 0, 0, top, 2).p, 7.0, 1e-9);
    CHECK_NEAR(at(&f, TALK, 0, 0, sqrt(R * R + 0.25 * rho_max * rho_max) - R, 2).p, 3.5, 1e-6);
    /* view: the sky's horizon at the last point, the ground's at 0; a sky ray
     * reaching the top at (rho + H) / 2 sits half-way up the upper half */
    double y = 500.0, r = R + y, rho = sqrt(r * r - R * R), c = -rho / r, h = acos(c);
    CHECK_NEAR(at(&f, TALK, 0, h - 1e-9, y, 1).p, 63.0, 1e-3);
    CHECK_NEAR(at(&f, TALK, 0, h + 1e-9, y, 1).p, 0.0, 0.05);
    CHECK(at(&f, TALK, 0, h + 1e-6, y, 1).hi == 31 && at(&f, TALK, 0, h - 1e-6, y, 1).lo == 32);
    CHECK_NEAR(at(&f, TALK, 0, 0.0, y, 1).p, 32.0 + 31.0 * (Rt - r) / (rho + H), 1e-9);
    CHECK_NEAR(at(&f, TALK, 0, PI, y, 1).p, 31.0 * (1.0 - y / rho), 1e-9);
    double d = 0.5 * (rho + H), mu = (Rt * Rt - r * r - d * d) / (2.0 * r * d);
    CHECK_NEAR(at(&f, TALK, 0, acos(mu), y, 1).p, 32.0 + 15.5, 1e-6);
    /* the ground's half: a ray reaching the ground at rho / 2 sits half-way */
    d = 0.5 * rho, mu = (R * R - r * r - d * d) / (2.0 * r * d);
    CHECK_NEAR(at(&f, TALK, 0, acos(mu), y, 1).p, 15.5, 1e-6);
}

/* Whether the paper clamps what view point iv of n holds at altitude y (the
 * papers' rules, restated): Yusov keeps mu 1e-4 off the horizon (the first
 * points of each half, whose power-5 offset is smaller, hold the same mu);
 * Bruneton clamps the distance d to [R_t - r, 0.999 (rho + H)] above and
 * [r - R, 0.999 rho] below, and keeps mu 0.001 below the horizon. */
static int view_clamped(const atmosphere_lut_frame *f, int iv, int n, double y)
{
    int m = n / 2, upper = iv >= m;
    double frac = upper ? (double)(iv - m) / (m - 1) : (double)iv / (m - 1);
    double R = f->bottom_radius, Rt = f->top_radius, r = R + y, rho = sqrt(r * r - R * R);
    double H = sqrt(Rt * Rt - R * R), c = atmosphere_lut_horizon_cosine(y, R);
    if (f->kind == ATMOSPHERE_PARAM_YUSOV)
        return pow(frac, 5.0) * (upper ? 1.0 - c : c + 1.0) < 1e-4;
    if (upper)
        return frac * (rho + H) < Rt - r || frac == 1.0;
    double d = (1.0 - frac) * rho, mu = (R * R - r * r - d * d) / (2.0 * r * d);
    return d < r - R || frac == 0.0 || mu > c - 1e-3;
}

/* Grid point -> parameter -> position: the point itself, except where the
 * paper clamps what a point holds (counted; the sun formula's lowest
 * point, whose mu_s is 5e-4 of the axis below the formula's clamp, within
 * 1e-3 of the axis; Bruneton's ground point holds 10 m). */
static void round_trip(atmosphere_lut_parametrization kind, const int n[4])
{
    atmosphere_lut_frame f = frame(kind);
    int off = 0, clamped = 0;
    for (int iy = 0; iy < n[2]; ++iy)
        for (int iv = 0; iv < n[1]; ++iv)
            for (int is = 0; is < n[0]; ++is) {
                int i[4] = {is, iv, iy, 1};
                double x[4];
                atmosphere_lut_position p[4];
                atmosphere_lut_grid_parameters(&f, n, i, x);
                atmosphere_lut_positions(&f, n, x[0], x[1], x[2], x[3], p);
                int linear = kind == ATMOSPHERE_PARAM_LINEAR;
                for (int a = 0; a < 4; ++a) {
                    double tolerance = a == 0 && is == 0 && !linear ? 1e-3 * (n[0] - 1) : 1e-6;
                    int ok = fabs(p[a].p - i[a]) < tolerance && p[a].lo <= i[a] && i[a] <= p[a].hi;
                    if (a == 1 && !linear && view_clamped(&f, iv, n[1], x[2]))
                        clamped += !ok, ok = p[a].lo <= p[a].p && p[a].p <= p[a].hi; /* on its own side */
                    if (a == 2 && kind == ATMOSPHERE_PARAM_BRUNETON && iy == 0)
                        ok = x[2] == ATMOSPHERE_LUT_BRUNETON_GROUND;
                    if (!ok && off++ < 3)
                        printf("  point (%d, %d, %d) axis %d at %.9g [%d, %d]\n", is, iv, iy, a, p[a].p, p[a].lo, p[a].hi);
                }
            }
    CHECK_MSG(off == 0, "%s (%d, %d, %d): %d grid points off their place", atmosphere_lut_parametrization_name(kind),
              n[0], n[1], n[2], off);
    printf("%s (%d, %d, %d): %d of %d points hold a direction the paper clamps\n",
           atmosphere_lut_parametrization_name(kind), n[0], n[1], n[2], clamped, n[0] * n[1] * n[2]);
    /* Yusov's horizon points hold mu 1e-4 off the horizon, on their own side */
    if (kind == ATMOSPHERE_PARAM_YUSOV) {
        int i[4] = {0, n[1] / 2, 3, 0}, j[4] = {0, 0, 3, 0};
        double x[4], z[4];
        atmosphere_lut_grid_parameters(&f, n, i, x), atmosphere_lut_grid_parameters(&f, n, j, z);
        double c = atmosphere_lut_horizon_cosine(x[2], f.bottom_radius);
        CHECK_NEAR(cos(x[1]), c + 1e-4, 1e-12);
        CHECK_NEAR(cos(z[1]), c - 1e-4, 1e-12);
    }
}

static void test_checks(void)
{
    char msg[200];
    int odd[4] = {8, 63, 8, 4}, small[4] = {8, 2, 8, 4};
    CHECK(atmosphere_lut_parametrization_check(ATMOSPHERE_PARAM_YUSOV, TALK, msg, sizeof msg) == 0);
    CHECK(atmosphere_lut_parametrization_check(ATMOSPHERE_PARAM_YUSOV, odd, msg, sizeof msg) != 0);
    CHECK(atmosphere_lut_parametrization_check(ATMOSPHERE_PARAM_BRUNETON, small, msg, sizeof msg) != 0);
    CHECK(atmosphere_lut_parametrization_check(ATMOSPHERE_PARAM_LINEAR, odd, msg, sizeof msg) == 0);
}

/* Yusov's table at 4x the talk's size per spatial axis, clear weather
 * (t = 0, a size-1 t axis: one precomputation, the test stays fast): the day's sky within one sRGB code
 * value at 95% of its pixels. Twilight is printed: the table's hardest
 * regime (the section reports it). */
static void test_near_exact(double t)
{
    atmosphere_model m = atmosphere_model_default();
    atmosphere_solution s;
    CHECK(atmosphere_solve(&m, t, 2, &s) == 0);
    atmosphere_lut_sizes sizes = {{32, 256, 32, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}};
    atmosphere_luts luts;
    char msg[200];
    CHECK(atmosphere_luts_build_parametrized(&luts, &s, 1, &sizes, ATMOSPHERE_PARAM_YUSOV, 2, msg, sizeof msg) == 0);
    double day = 80.0 * PI / 180.0, night = 96.0 * PI / 180.0;
    atmosphere_sky_sample daylight, twilight;
    CHECK(atmosphere_sky_sample_build(&daylight, &s, 1, 400, 0.0, day, 3, 2) == 0);
    CHECK(atmosphere_sky_sample_build(&twilight, &s, 1, 400, day, night, 4, 2) == 0);
    atmosphere_error_stats a, b;
    CHECK(atmosphere_sky_errors(&luts, &daylight, &a) == 0 && atmosphere_sky_errors(&luts, &twilight, &b) == 0);
    printf("Yusov (32, 256, 32) at t = %g: sky p95 %.4f +- %.4f (day), %.4f (twilight); max %.3f, %.3f\n", t, a.p95,
           a.p95_se, b.p95, a.max, b.max);
    CHECK_MSG(a.p95 + CHECK_K * a.p95_se < CLAIM_ONE_CODE_VALUE_SRGB_RELATIVE, "day p95 %.4f", a.p95);
    /* the files' lookup is linear: a Yusov table is refused, nothing written */
    gt_error e;
    CHECK(atmosphere_luts_write_all(check_tmp_dir(), &luts, &e) != 0 && strstr(e.message, "Yusov"));
    atmosphere_sky_sample_free(&daylight), atmosphere_sky_sample_free(&twilight);
    atmosphere_luts_free(&luts);
    atmosphere_solution_free(&s);
}

int main(void)
{
    test_sun_formula();
    test_yusov();
    test_yusov_texcoords();
    test_bruneton();
    int big[4] = {32, 256, 32, 4};
    for (int k = 0; k < ATMOSPHERE_PARAMS; ++k)
        round_trip((atmosphere_lut_parametrization)k, TALK), round_trip((atmosphere_lut_parametrization)k, big);
    test_checks();
    test_near_exact(0.0);
    return check_report("test_atmosphere_lut_axes");
}
