/* Colour grades (color_grade.h). */
#include "color_grading/color_grade.h"

#include <math.h>
#include <stddef.h>

#include "core/optics/srgb.h"
#include "core/vec3.h" /* M_PI */

static double clamp01(double x)
{
    return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x);
}

static double levels(const double p[5], double x)
{
    double t = clamp01((x - p[0]) / (p[1] - p[0]));
    return p[3] + (p[4] - p[3]) * pow(t, 1.0 / p[2]);
}

/* The tangent at point i of monotone data: the harmonic mean of the
 * neighbouring secants (Fritsch and Butland 1984, the monotone variant of
 * Fritsch-Carlson), 0 at a local extremum, the secant at the ends; each
 * tangent is at most 2 min(secants) <= 3 x secant, so the cubic is monotone. */
static double curve_tangent(const double *x, const double *y, int n, int i)
{
    double d0 = i > 0 ? (y[i] - y[i - 1]) / (x[i] - x[i - 1]) : 0.0;
    double d1 = i < n - 1 ? (y[i + 1] - y[i]) / (x[i + 1] - x[i]) : 0.0;
    if (i == 0)
        return d1;
    if (i == n - 1)
        return d0;
    return d0 * d1 <= 0.0 ? 0.0 : 2.0 * d0 * d1 / (d0 + d1);
}

/* The cubic Hermite curve through the points, at t. */
static double curve(const double *x, const double *y, int n, double t)
{
    int i = 0;
    while (i < n - 2 && t > x[i + 1])
        ++i;
    double h = x[i + 1] - x[i], s = (t - x[i]) / h, s2 = s * s, s3 = s2 * s;
    double m0 = curve_tangent(x, y, n, i) * h, m1 = curve_tangent(x, y, n, i + 1) * h;
    return (2 * s3 - 3 * s2 + 1) * y[i] + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * y[i + 1] + (s3 - s2) * m1;
}

static void saturation(double s, double c[3])
{
    double y = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    for (int i = 0; i < 3; ++i)
        c[i] = y + s * (c[i] - y);
}

/* Rodrigues' rotation about the grey axis by `degrees`. */
static void hue_rotation(double degrees, double c[3])
{
    double a = degrees * M_PI / 180.0, k = 1.0 / sqrt(3.0), cs = cos(a), sn = sin(a);
    double kc = k * (c[0] + c[1] + c[2]), r[3];
    double cross[3] = {k * (c[2] - c[1]), k * (c[0] - c[2]), k * (c[1] - c[0])};
    for (int i = 0; i < 3; ++i)
        r[i] = c[i] * cs + cross[i] * sn + k * kc * (1.0 - cs);
    for (int i = 0; i < 3; ++i)
        c[i] = r[i];
}

static void apply_op(const color_grade_op *op, double c[3])
{
    switch (op->kind) {
    case GRADE_LEVELS: for (int i = 0; i < 3; ++i) c[i] = levels(op->p, c[i]); break;
    case GRADE_CURVES:
        for (int i = 0; i < 3; ++i)
            c[i] = curve(op->x[i], op->y[i], op->count[i], c[i]);
        break;
    case GRADE_SATURATION: saturation(op->p[0], c); break;
    case GRADE_HUE: hue_rotation(op->p[0], c); break;
    case GRADE_CDL:
        for (int i = 0; i < 3; ++i)
            c[i] = pow(fmax(0.0, c[i] * op->slope[i] + op->offset[i]), op->power[i]);
        break;
    case GRADE_EXPOSURE:
        for (int i = 0; i < 3; ++i)
            c[i] = linear_to_srgb(fmin(1.0, srgb_to_linear(c[i]) * pow(2.0, op->p[0])));
        break;
    }
    for (int i = 0; i < 3; ++i)
        c[i] = clamp01(c[i]);
}

void color_grade_apply(const color_grade *g, const double in[3], double out[3])
{
    for (int i = 0; i < 3; ++i)
        out[i] = clamp01(in[i]);
    for (int k = 0; k < g->count; ++k)
        apply_op(&g->ops[k], out);
}

/* A curve op with the same points on the three channels. */
#define CURVE_RGB(n, X, Y) {.kind = GRADE_CURVES, .count = {n, n, n}, .x = {X, X, X}, .y = {Y, Y, Y}}
#define S_CURVE_X {0.0, 0.25, 0.75, 1.0}
#define S_CURVE_Y {0.0, 0.18, 0.84, 1.0}
#define BLEACH_X {0.0, 0.3, 0.7, 1.0}
#define BLEACH_Y {0.0, 0.14, 0.9, 1.0}

static const color_grade presets[COLOR_GRADE_PRESETS] = {
    {"identity", 0, {{0}}},
    {"warm contrast", 3,
     {CURVE_RGB(4, S_CURVE_X, S_CURVE_Y),
      {.kind = GRADE_CDL, .slope = {1.06, 1.0, 0.9}, .offset = {0.01, 0.0, -0.01}, .power = {1.0, 1.0, 1.05}},
      {.kind = GRADE_SATURATION, .p = {1.15}}}},
    {"teal and orange", 3,
     {{.kind = GRADE_HUE, .p = {12.0}},
      {.kind = GRADE_SATURATION, .p = {1.35}},
      {.kind = GRADE_LEVELS, .p = {0.03, 0.95, 1.1, 0.0, 1.0}}}},
    {"bleach bypass", 2, {{.kind = GRADE_SATURATION, .p = {0.35}}, CURVE_RGB(4, BLEACH_X, BLEACH_Y)}},
    {"cross-process curves", 1,
     {{.kind = GRADE_CURVES,
       .count = {4, 3, 4},
       .x = {{0.0, 0.2, 0.7, 1.0}, {0.0, 0.5, 1.0}, {0.0, 0.3, 0.8, 1.0}},
       .y = {{0.06, 0.16, 0.82, 1.0}, {0.0, 0.55, 1.0}, {0.1, 0.26, 0.7, 0.86}}}}},
    {"clipped exposure +1.5", 2, {{.kind = GRADE_EXPOSURE, .p = {1.5}}, {.kind = GRADE_SATURATION, .p = {1.2}}}},
};

const color_grade *color_grade_preset(int index)
{
    return index >= 0 && index < COLOR_GRADE_PRESETS ? &presets[index] : NULL;
}
