/* A colour grade baked into an N^3 LUT and looked up as a shader does
 * (Selan 2007, "Using Lookup Tables to Accelerate Color Transformations",
 * GPU Gems 2 ch. 24; Kaplanyan 2010 bakes its grades into 16^3).
 *
 * Lattice point (i, j, k), i along red, holds the grade of the colour whose
 * LUT coordinates are (i, j, k) / (N - 1). The coordinates of a display
 * colour d depend on the LUT's input space:
 *   COLOR_LUT_SRGB    u = d (the display-encoded value: the usual choice)
 *   COLOR_LUT_LINEAR  u = srgb_to_linear(d) (lattice uniform in linear light)
 *   COLOR_LUT_LOG     u = (log2(max(x, 2^-12)) + 12) / 12, x = srgb_to_linear(d)
 *                     (uniform in stops over the 12 stops below white, the
 *                     shaper of log-encoded grading LUTs; darker values clamp)
 * Lookups:
 *   trilinear    the 8 corners of the lattice cell (what a GPU's 3-D texture
 *                filter computes), exact for functions linear in each axis;
 *   tetrahedral  the 4 corners of the cell's tetrahedron holding u (the cube
 *                cut into 6 along its main diagonal by the order of the
 *                fractional parts; Kasson, Nin, Plouffe and Hafner 1995),
 *                exact for affine functions, and keeping greys on the grey
 *                diagonal. */
#ifndef GTLAB_COLOR_GRADING_COLOR_LUT_H
#define GTLAB_COLOR_GRADING_COLOR_LUT_H

#include "color_grading/color_grade.h"

typedef enum { COLOR_LUT_SRGB, COLOR_LUT_LINEAR, COLOR_LUT_LOG, COLOR_LUT_SPACES } color_lut_space;
typedef enum { COLOR_LUT_TRILINEAR, COLOR_LUT_TETRAHEDRAL, COLOR_LUT_INTERPOLATIONS } color_lut_interpolation;

typedef struct {
    int size;
    color_lut_space space;
    float *rgb; /* size^3 x 3, (k * size + j) * size + i */
} color_lut;

const char *color_lut_space_name(int space);
const char *color_lut_interpolation_name(int interpolation);

/* The LUT's coordinate of display value d, and back. */
double color_lut_coordinate(color_lut_space space, double d);
double color_lut_display_value(color_lut_space space, double u);

/* Bakes any colour function f(ctx, in, out) on display values; 0, or -1 if
 * out of memory. */
int color_lut_bake_function(color_lut *lut, int size, color_lut_space space,
                            void (*f)(const void *ctx, const double in[3], double out[3]), const void *ctx);
int color_lut_bake(color_lut *lut, int size, color_lut_space space, const color_grade *g);
void color_lut_free(color_lut *lut);

/* The LUT's value for the display colour d. */
void color_lut_lookup(const color_lut *lut, color_lut_interpolation interpolation, const double d[3], double out[3]);

#endif
