/* 3-D colour LUTs (color_lut.h). */
#include "color_grading/color_lut.h"

#include <math.h>
#include <stdlib.h>

#include "core/optics/srgb.h"

static const char *const space_names[COLOR_LUT_SPACES] = {"sRGB", "linear", "log2"};
enum { LOG_STOPS = 12 };
static const char *const interpolation_names[COLOR_LUT_INTERPOLATIONS] = {"trilinear", "tetrahedral"};

const char *color_lut_space_name(int space)
{
    return space >= 0 && space < COLOR_LUT_SPACES ? space_names[space] : "?";
}

const char *color_lut_interpolation_name(int interpolation)
{
    return interpolation >= 0 && interpolation < COLOR_LUT_INTERPOLATIONS ? interpolation_names[interpolation] : "?";
}

double color_lut_coordinate(color_lut_space space, double d)
{
    if (space == COLOR_LUT_LOG)
        return (log2(fmax(srgb_to_linear(d), exp2(-LOG_STOPS))) + LOG_STOPS) / LOG_STOPS;
    return space == COLOR_LUT_LINEAR ? srgb_to_linear(d) : d;
}

double color_lut_display_value(color_lut_space space, double u)
{
    if (space == COLOR_LUT_LOG)
        return linear_to_srgb(exp2(u * LOG_STOPS - LOG_STOPS));
    return space == COLOR_LUT_LINEAR ? linear_to_srgb(u) : u;
}

static void apply_grade(const void *ctx, const double in[3], double out[3])
{
    color_grade_apply(ctx, in, out);
}

int color_lut_bake_function(color_lut *lut, int size, color_lut_space space,
                            void (*f)(const void *ctx, const double in[3], double out[3]), const void *ctx)
{
    lut->size = size;
    lut->space = space;
    lut->rgb = malloc(sizeof *lut->rgb * 3 * (size_t)size * (size_t)size * (size_t)size);
    if (!lut->rgb)
        return -1;
    for (int k = 0; k < size; ++k)
        for (int j = 0; j < size; ++j)
            for (int i = 0; i < size; ++i) {
                int idx[3] = {i, j, k};
                double in[3], out[3];
                for (int c = 0; c < 3; ++c)
                    in[c] = color_lut_display_value(space, idx[c] / (double)(size - 1));
                f(ctx, in, out);
                for (int c = 0; c < 3; ++c)
                    lut->rgb[3 * (((size_t)k * size + j) * size + i) + c] = (float)out[c];
            }
    return 0;
}

int color_lut_bake(color_lut *lut, int size, color_lut_space space, const color_grade *g)
{
    return color_lut_bake_function(lut, size, space, apply_grade, g);
}

void color_lut_free(color_lut *lut)
{
    free(lut->rgb);
    lut->rgb = NULL;
}

static const float *lattice(const color_lut *lut, int i, int j, int k)
{
    return lut->rgb + 3 * (((size_t)k * lut->size + j) * lut->size + i);
}

/* The cell's lower corner and the fractional position in it, per axis. */
static void locate(const color_lut *lut, const double d[3], int base[3], double f[3])
{
    for (int c = 0; c < 3; ++c) {
        double u = color_lut_coordinate(lut->space, fmin(1.0, fmax(0.0, d[c]))) * (lut->size - 1);
        base[c] = (int)floor(u);
        if (base[c] >= lut->size - 1)
            base[c] = lut->size - 2;
        f[c] = u - base[c];
    }
}

static void trilinear(const color_lut *lut, const int b[3], const double f[3], double out[3])
{
    for (int c = 0; c < 3; ++c)
        out[c] = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        int di = corner & 1, dj = (corner >> 1) & 1, dk = corner >> 2;
        double w = (di ? f[0] : 1 - f[0]) * (dj ? f[1] : 1 - f[1]) * (dk ? f[2] : 1 - f[2]);
        const float *v = lattice(lut, b[0] + di, b[1] + dj, b[2] + dk);
        for (int c = 0; c < 3; ++c)
            out[c] += w * v[c];
    }
}

/* The tetrahedron from corner 000 to 111 through the corners that add the
 * axes in decreasing order of f: weights are the differences of the sorted
 * fractions. */
static void tetrahedral(const color_lut *lut, const int b[3], const double f[3], double out[3])
{
    int order[3] = {0, 1, 2};
    for (int a = 0; a < 2; ++a)
        for (int c = 0; c < 2 - a; ++c)
            if (f[order[c]] < f[order[c + 1]]) {
                int t = order[c];
                order[c] = order[c + 1];
                order[c + 1] = t;
            }
    int corner[3] = {b[0], b[1], b[2]};
    double w = 1.0 - f[order[0]];
    const float *v = lattice(lut, corner[0], corner[1], corner[2]);
    for (int c = 0; c < 3; ++c)
        out[c] = w * v[c];
    for (int s = 0; s < 3; ++s) {
        corner[order[s]] += 1;
        w = f[order[s]] - (s < 2 ? f[order[s + 1]] : 0.0);
        v = lattice(lut, corner[0], corner[1], corner[2]);
        for (int c = 0; c < 3; ++c)
            out[c] += w * v[c];
    }
}

void color_lut_lookup(const color_lut *lut, color_lut_interpolation interpolation, const double d[3], double out[3])
{
    int b[3];
    double f[3];
    locate(lut, d, b, f);
    if (interpolation == COLOR_LUT_TETRAHEDRAL)
        tetrahedral(lut, b, f, out);
    else
        trilinear(lut, b, f, out);
}
