/* The Decima atmosphere LUTs (atmosphere/atmosphere_luts.h, atmosphere_lut_errors.h):
 *  - the lookup returns the texels at the grid points, and is linear along
 *    each axis between them (midpoints are the mean of two texels);
 *  - every table against direct numerical integration at random points, the
 *    two errors apart: the build's quadrature (FAST - REFERENCE) within 1e-2
 *    (in-scatter, sky) and 1e-3 (sun) at the 95th percentile and below the
 *    tables' interpolation error, and the interpolation error falling when
 *    the theta_s and y axes are refined 4x (the numbers are printed);
 *  - bounds: sun <= E_sun, everything >= 0, the sun dimmer at larger theta_s
 *    and, at the ground, in the dense fog than in clear air (at 8 km the fog
 *    weather's Mie, scale height 0.6 km, is thinner than the clear one's);
 *  - 1 and 2 threads give the same bits; bad sizes and a bad model refused. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "atmosphere/atmosphere_lut_errors.h"
#include "atmosphere/atmosphere_luts.h"
#include "tests/check.h"

static const atmosphere_lut_sizes SMALL = {{4, 16, 2, 2}, {16, 1, 2, 2}, {8, 1, 2, 2}};

static void test_lookup_at_grid(const atmosphere_luts *l)
{
    const int *n = l->sizes.inscatter;
    int bad = 0;
    for (int w = 0; w < n[3]; ++w)
        for (int y = 0; y < n[2]; ++y)
            for (int v = 0; v < n[1]; ++v)
                for (int s = 0; s < n[0]; ++s) {
                    float got[2][3];
                    atmosphere_lut_inscatter(l, (float)atmosphere_lut_axis_value(0, s, n[0], 0),
                                             (float)atmosphere_lut_axis_value(1, v, n[1], 0),
                                             (float)atmosphere_lut_axis_value(2, y, n[2], l->max_altitude),
                                             (float)atmosphere_lut_axis_value(3, w, n[3], 0), got);
                    const float *texel = l->table[0] + ((((size_t)w * n[2] + y) * n[1] + v) * n[0] + s) * 6;
                    for (int k = 0; k < 6; ++k)
                        bad += fabsf(got[k / 3][k % 3] - texel[k]) > 1e-5f * fabsf(texel[k]) + 1e-12f;
                }
    CHECK_MSG(bad == 0, "%d in-scatter values differ from their texels at the grid points", bad);
    float mid[3], a = (float)atmosphere_lut_axis_value(0, 1, 16, 0), b = (float)atmosphere_lut_axis_value(0, 2, 16, 0);
    atmosphere_lut_light(l, ATMOSPHERE_TABLE_SUN, 0.5f * (a + b), 0.0f, 0.0f, mid);
    for (int c = 0; c < 3; ++c)
        CHECK_NEAR(mid[c], 0.5 * (l->table[1][3 + c] + l->table[1][6 + c]), 1e-5 * mid[c]);
}

static void test_bounds(const atmosphere_luts *l)
{
    int negative = 0, above_sun = 0, brighter = 0;
    for (int table = 0; table < ATMOSPHERE_TABLES; ++table) {
        const int *n = table == 0 ? l->sizes.inscatter : table == 1 ? l->sizes.sun : l->sizes.sky;
        size_t count = (size_t)n[0] * n[1] * n[2] * n[3] * (table == 0 ? 6 : 3);
        for (size_t k = 0; k < count; ++k)
            negative += !(l->table[table][k] >= 0.0f);
    }
    const int *n = l->sizes.sun;
    for (int w = 0; w < n[3]; ++w)
        for (int y = 0; y < n[2]; ++y)
            for (int s = 0; s < n[0]; ++s)
                for (int c = 0; c < 3; ++c) {
                    const float *row = l->table[1] + ((size_t)(w * n[2] + y) * n[0]) * 3;
                    above_sun += row[3 * s + c] > l->model.solar_irradiance[c];
                    brighter += s > 0 && row[3 * s + c] > row[3 * (s - 1) + c];
                    if (w == 1 && y == 0) /* from the ground every ray's fog column exceeds the clear air's */
                        brighter += row[3 * s + c] > l->table[1][((size_t)y * n[0] + s) * 3 + c];
                }
    CHECK_MSG(negative == 0, "%d negative or NaN values", negative);
    CHECK_MSG(above_sun == 0, "%d sun texels above the solar irradiance", above_sun);
    CHECK_MSG(brighter == 0, "%d sun texels brighter than a higher sun or the clear air", brighter);
}

/* Interpolation and quadrature errors at random points, printed. */
static void test_against_integration(const atmosphere_solution *solutions, const atmosphere_luts *coarse)
{
    atmosphere_lut_reference ref;
    CHECK(atmosphere_lut_reference_build(&ref, solutions + 2, 1, 24, 7, 2) == 0);
    atmosphere_lut_sizes fine_sizes = {{16, 16, 8, 2}, {64, 1, 8, 2}, {32, 1, 8, 2}};
    atmosphere_luts fine;
    char msg[200];
    CHECK(atmosphere_luts_build_from(&fine, solutions, 3, &fine_sizes, 2, msg, sizeof msg) == 0);
    atmosphere_table_error ec[ATMOSPHERE_TABLES], ef[ATMOSPHERE_TABLES];
    atmosphere_lut_errors(coarse, &ref, ec);
    atmosphere_lut_errors(&fine, &ref, ef);
    static const char *const names[ATMOSPHERE_TABLES] = {"inscatter", "sun", "sky"};
    const double quadrature_limit[ATMOSPHERE_TABLES] = {1e-2, 1e-3, 1e-2};
    for (int t = 0; t < ATMOSPHERE_TABLES; ++t) {
        printf("%-9s quadrature p95 %.2e max %.2e | interpolation rms %.3e (coarse) %.3e (fine)\n", names[t],
               ec[t].quadrature.p95, ec[t].quadrature.max, ec[t].interpolation.rms, ef[t].interpolation.rms);
        CHECK_MSG(ec[t].quadrature.p95 < quadrature_limit[t], "%s: quadrature p95 %.3g", names[t], ec[t].quadrature.p95);
        CHECK_MSG(ec[t].quadrature.p95 < ec[t].interpolation.p95, "%s: quadrature above interpolation", names[t]);
        CHECK_MSG(ef[t].interpolation.rms < 0.7 * ec[t].interpolation.rms, "%s: refining does not help", names[t]);
    }
    atmosphere_luts_free(&fine);
    atmosphere_lut_reference_free(&ref);
}

static void test_bad_input(const atmosphere_solution *solutions)
{
    atmosphere_luts l;
    char msg[200];
    atmosphere_lut_sizes bad = SMALL;
    bad.inscatter[1] = 0;
    CHECK(atmosphere_luts_build_from(&l, solutions, 3, &bad, 1, msg, sizeof msg) != 0 && strstr(msg, "inscatter"));
    bad = SMALL, bad.sky[1] = 4;
    CHECK(atmosphere_luts_build_from(&l, solutions, 3, &bad, 1, msg, sizeof msg) != 0 && strstr(msg, "sky"));
    bad = SMALL, bad.sun[3] = 4; /* t = 1/3 is not solved */
    CHECK(atmosphere_luts_build_from(&l, solutions, 3, &bad, 1, msg, sizeof msg) != 0 && strstr(msg, "t = 0.333"));
    atmosphere_model m = atmosphere_model_default();
    m.weathers[1].mie_scale_height = 0.0;
    CHECK(atmosphere_luts_build(&l, &m, &SMALL, 1, msg, sizeof msg) != 0 && strstr(msg, "scale height"));
}

int main(void)
{
    atmosphere_model m = atmosphere_model_default();
    atmosphere_solution solutions[3];
    double blends[3] = {0.0, 1.0, 0.5};
    for (int k = 0; k < 3; ++k)
        CHECK(atmosphere_solve(&m, blends[k], 2, &solutions[k]) == 0);
    atmosphere_luts one, two;
    char msg[200];
    CHECK(atmosphere_luts_build_from(&one, solutions, 3, &SMALL, 1, msg, sizeof msg) == 0);
    CHECK(atmosphere_luts_build_from(&two, solutions, 3, &SMALL, 2, msg, sizeof msg) == 0);
    for (int t = 0; t < ATMOSPHERE_TABLES; ++t) {
        const int *n = t == 0 ? SMALL.inscatter : t == 1 ? SMALL.sun : SMALL.sky;
        size_t bytes = sizeof(float) * (size_t)n[0] * n[1] * n[2] * n[3] * (t == 0 ? 6 : 3);
        CHECK(memcmp(one.table[t], two.table[t], bytes) == 0);
    }
    test_lookup_at_grid(&one);
    test_bounds(&one);
    test_against_integration(solutions, &one);
    test_bad_input(solutions);
    atmosphere_luts_free(&one), atmosphere_luts_free(&two);
    for (int k = 0; k < 3; ++k)
        atmosphere_solution_free(&solutions[k]);
    return check_report("test_atmosphere_luts");
}
