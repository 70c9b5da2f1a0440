/* Colour grades and 3-D LUTs (color_grade.h, color_lut.h):
 * - each operation at its neutral setting is the identity; hue rotation by
 *   360 degrees is the identity and keeps greys grey at any angle; the curves
 *   pass through their control points and never decrease;
 * - the identity grade in an sRGB-indexed LUT is the identity at the lattice
 *   points and everywhere (it is affine in the coordinates), with both
 *   lookups; in a linear-indexed LUT it is exact at the lattice points, its
 *   error between them falls with N, ~4x per doubling above d = 0.25 (second
 *   order; slower in the shadows, where srgb(u) is steep);
 * - tetrahedral lookup reproduces an affine function exactly, trilinear a
 *   multilinear one (x y z), and both are continuous across cell faces. */
#include <math.h>

#include "color_grading/color_lut.h"
#include "tests/check.h"

static double uniform(unsigned long long *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*s >> 11) * 0x1.0p-53;
}

static double max_diff(const double a[3], const double b[3])
{
    return fmax(fabs(a[0] - b[0]), fmax(fabs(a[1] - b[1]), fabs(a[2] - b[2])));
}

static void check_neutral_ops(void)
{
    color_grade g = {"neutral", 5,
                     {{.kind = GRADE_LEVELS, .p = {0.0, 1.0, 1.0, 0.0, 1.0}},
                      {.kind = GRADE_SATURATION, .p = {1.0}},
                      {.kind = GRADE_HUE, .p = {360.0}},
                      {.kind = GRADE_CDL, .slope = {1, 1, 1}, .offset = {0, 0, 0}, .power = {1, 1, 1}},
                      {.kind = GRADE_EXPOSURE, .p = {0.0}}}};
    color_grade hue = {"hue", 1, {{.kind = GRADE_HUE, .p = {37.0}}}};
    unsigned long long s = 3;
    for (int i = 0; i < 1000; ++i) {
        double c[3] = {uniform(&s), uniform(&s), uniform(&s)}, out[3], grey[3] = {c[0], c[0], c[0]};
        color_grade_apply(&g, c, out);
        CHECK(max_diff(c, out) < 1e-12);
        color_grade_apply(&hue, grey, out);
        CHECK(max_diff(grey, out) < 1e-12);
    }
    for (int p = 0; p < COLOR_GRADE_PRESETS; ++p)
        for (int k = 0; k < color_grade_preset(p)->count; ++k) {
            const color_grade_op *op = &color_grade_preset(p)->ops[k];
            if (op->kind != GRADE_CURVES)
                continue;
            for (int c = 0; c < 3; ++c) {
                color_grade one = {"curve", 1, {*op}};
                double prev = -1.0;
                for (int t = 0; t <= 1000; ++t) {
                    double in[3] = {t / 1000.0, t / 1000.0, t / 1000.0}, out[3];
                    color_grade_apply(&one, in, out);
                    CHECK(out[c] >= prev - 1e-15);
                    prev = out[c];
                }
                for (int q = 0; q < op->count[c]; ++q) {
                    double in[3] = {op->x[c][q], op->x[c][q], op->x[c][q]}, out[3];
                    color_grade_apply(&one, in, out);
                    CHECK_NEAR(out[c], op->y[c][q], 1e-12);
                }
            }
        }
}

/* f(c) = A c + b: affine; g(c) = c0 c1 c2 in every channel: multilinear. */
static void affine(const void *ctx, const double in[3], double out[3])
{
    (void)ctx;
    out[0] = 0.2 + 0.5 * in[0] - 0.3 * in[1] + 0.1 * in[2];
    out[1] = -0.1 + 0.2 * in[0] + 0.9 * in[1];
    out[2] = 0.7 * in[2] - 0.4 * in[0] + 0.05;
}

static void multilinear(const void *ctx, const double in[3], double out[3])
{
    (void)ctx;
    out[0] = out[1] = out[2] = in[0] * in[1] * in[2];
}

/* The worst lookup error at 4000 random colours (lattice points only, or
 * anywhere with display values at least d_min). */
static double lookup_error_above(const color_lut *lut, int interpolation,
                                 void (*f)(const void *, const double *, double *), const void *ctx, int lattice_only,
                                 double d_min)
{
    unsigned long long s = 5;
    double worst = 0.0;
    for (int i = 0; i < 4000; ++i) {
        double d[3], exact[3], got[3];
        for (int c = 0; c < 3; ++c) {
            double u = lattice_only ? floor(uniform(&s) * lut->size) / (lut->size - 1) : uniform(&s);
            d[c] = lattice_only ? color_lut_display_value(lut->space, fmin(1.0, u)) : d_min + (1.0 - d_min) * u;
        }
        f(ctx, d, exact);
        color_lut_lookup(lut, interpolation, d, got);
        worst = fmax(worst, max_diff(exact, got));
    }
    return worst;
}

static double lookup_error(const color_lut *lut, int interpolation,
                           void (*f)(const void *, const double *, double *), const void *ctx, int lattice_only)
{
    return lookup_error_above(lut, interpolation, f, ctx, lattice_only, 0.0);
}

static void identity(const void *ctx, const double in[3], double out[3])
{
    color_grade_apply(ctx, in, out);
}

static void check_luts(void)
{
    const color_grade *id = color_grade_preset(0);
    color_lut lut;
    for (int interp = 0; interp < COLOR_LUT_INTERPOLATIONS; ++interp) {
        CHECK(color_lut_bake(&lut, 17, COLOR_LUT_SRGB, id) == 0);
        CHECK(lookup_error(&lut, interp, identity, id, 0) < 1e-6);
        color_lut_free(&lut);
        double e[2], mid[2];
        for (int k = 0; k < 2; ++k) {
            CHECK(color_lut_bake(&lut, k ? 33 : 17, COLOR_LUT_LINEAR, id) == 0);
            CHECK(lookup_error(&lut, interp, identity, id, 1) < 1e-6);
            e[k] = lookup_error(&lut, interp, identity, id, 0);
            mid[k] = lookup_error_above(&lut, interp, identity, id, 0, 0.25);
            color_lut_free(&lut);
        }
        /* in the shadows d = srgb(u) is not smooth in u (slope ~u^(-7/12)): slower than second order */
        CHECK_MSG(e[1] < e[0] && mid[1] < mid[0] / 3.0 && mid[1] > 0.0, "linear-indexed identity: %g, %g; above "
                  "0.25: %g, %g", e[0], e[1], mid[0], mid[1]);
    }
    CHECK(color_lut_bake(&lut, 17, COLOR_LUT_LOG, id) == 0); /* log2-indexed: exact at the lattice points too */
    CHECK(lookup_error(&lut, COLOR_LUT_TETRAHEDRAL, identity, id, 1) < 1e-6);
    color_lut_free(&lut);
    CHECK(color_lut_bake_function(&lut, 9, COLOR_LUT_SRGB, affine, NULL) == 0);
    CHECK(lookup_error(&lut, COLOR_LUT_TETRAHEDRAL, affine, NULL, 0) < 1e-6);
    CHECK(lookup_error(&lut, COLOR_LUT_TRILINEAR, affine, NULL, 0) < 1e-6);
    color_lut_free(&lut);
    CHECK(color_lut_bake_function(&lut, 9, COLOR_LUT_SRGB, multilinear, NULL) == 0);
    CHECK(lookup_error(&lut, COLOR_LUT_TRILINEAR, multilinear, NULL, 0) < 1e-6);
    CHECK(lookup_error(&lut, COLOR_LUT_TETRAHEDRAL, multilinear, NULL, 0) > 1e-4); /* not multilinear-exact */
    color_lut_free(&lut);
}

int main(void)
{
    check_neutral_ops();
    check_luts();
    return check_report("test_color_lut");
}
