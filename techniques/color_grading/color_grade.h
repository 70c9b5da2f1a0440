/* Colour grades as grading tools apply them (Photoshop's adjustment layers,
 * DaVinci Resolve, the ASC CDL), the exact transform a 3-D LUT tabulates
 * (Kaplanyan 2010, "Color grading": "bake all global color transformations
 * into a 3D LUT [Selan 2007]; 16x16x16 proved to be enough").
 *
 * A grade is a list of operations on display-encoded RGB in [0, 1] (sRGB
 * values, the space grading tools work in), applied in order, each output
 * clamped to [0, 1]:
 *   levels      per channel: ((x - black_in) / (white_in - black_in))^(1/gamma)
 *               remapped to [black_out, white_out] (Photoshop "Levels")
 *   curves      per channel, a monotone cubic through control points
 *               (Fritsch and Carlson 1980: the tangents limited so the curve
 *               never overshoots; Photoshop "Curves")
 *   saturation  mix with the Rec. 709 luma Y: Y + s (x - Y)
 *   hue         rotation by an angle about the grey axis (1, 1, 1)/sqrt(3)
 *   cdl         ASC CDL slope, offset, power: (x slope + offset)^power
 *   exposure    2^stops in linear light (decode sRGB, scale, encode:
 *               core/optics/srgb.h), then
 *               the clamp: a clipped edit, the LUT's hardest case (a kink) */
#ifndef GTLAB_COLOR_GRADING_COLOR_GRADE_H
#define GTLAB_COLOR_GRADING_COLOR_GRADE_H

enum { COLOR_GRADE_MAX_OPS = 6, COLOR_CURVE_MAX_POINTS = 6 };

typedef enum { GRADE_LEVELS, GRADE_CURVES, GRADE_SATURATION, GRADE_HUE, GRADE_CDL, GRADE_EXPOSURE } color_grade_op_kind;

typedef struct {
    color_grade_op_kind kind;
    /* levels: p[0..4] = black_in, white_in, gamma, black_out, white_out;
     * saturation: p[0]; hue: p[0] degrees; exposure: p[0] stops;
     * cdl: slope[3], offset[3], power[3] */
    double p[5];
    double slope[3], offset[3], power[3];
    /* curves: per channel, count points (x increasing, from 0 to 1) */
    int count[3];
    double x[3][COLOR_CURVE_MAX_POINTS], y[3][COLOR_CURVE_MAX_POINTS];
} color_grade_op;

typedef struct {
    const char *name;
    int count;
    color_grade_op ops[COLOR_GRADE_MAX_OPS];
} color_grade;

/* The study's grades: identity, and five looks, each exercising the
 * operations above (color_grade.c lists their parameters). */
enum { COLOR_GRADE_PRESETS = 6 };
const color_grade *color_grade_preset(int index);

/* out = the grade applied to the display colour in (both in [0, 1]^3). */
void color_grade_apply(const color_grade *g, const double in[3], double out[3]);

#endif
