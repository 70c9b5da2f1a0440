/* Colour-grading LUTs (Kaplanyan 2010: "16x16x16 LUT proved to be enough")
 * as `gtlab all` studies them: six grades (color_grade.h) baked into
 * 16^3, 32^3 and 64^3 LUTs indexed in sRGB, linear or log2 values, stored as
 * float or 8 bits, looked up trilinearly or tetrahedrally, and scored
 * against the exact grade on
 *   chart  a photo-like HDR test chart (hue and saturation sweeps over seven
 *          stops of exposure, skin tones, a grey ramp over twelve stops)
 *          tone-mapped by the filmic curve (hdr_precision/hdr_precision.h) to
 *          display values, 192 x 128;
 *   cube   32768 uniformly random display colours: every input a grade can see;
 *   render a gtlab frame of builtin:cornell (raytracer/shaded_frame.h, 2 x 2
 *          samples per pixel, box filter), 192 x 128, tone-mapped like the chart.
 * Errors per pixel: the largest channel difference in 8-bit steps (LSB) and
 * CIEDE2000 (metrics/color_difference.h); max and 99th percentile.
 * A LUT "suffices" perceptually when the max CIEDE2000 on the chart and on
 * the render is below 1;
 * it is "within 1 LSB" when the chart's 99th percentile is. Writes <output>/grading/chart.png and the graded
 * chart per grade (exact and 16^3). */
#ifndef GTLAB_COLOR_GRADING_STUDY_H
#define GTLAB_COLOR_GRADING_STUDY_H

#include "color_grading/color_grade.h"
#include "color_grading/color_lut.h"
#include "project/study_context.h"

#define GRADING_DIR "color_grading"

enum { GRADING_SIZES = 3, GRADING_VARIANTS = 6, GRADING_IMAGES = 3, GRADING_CHART_W = 192, GRADING_CHART_H = 128 };

typedef struct {
    double max_lsb, p99_lsb, max_de, p99_de;
} grading_error;

typedef struct {
    const char *grade;
    int size;
    const char *space, *interpolation, *storage;
    grading_error image[GRADING_IMAGES]; /* chart, cube, render */
    int perceptual;                      /* chart and render: max dE00 < 1 (unnoticeable side by side) */
    int within_1lsb;                     /* on the chart: p99 <= 1 LSB (to the bit, nearly) */
} grading_row;

typedef struct {
    int cube_samples;
    int row_count;
    grading_row rows[COLOR_GRADE_PRESETS * GRADING_SIZES * GRADING_VARIANTS];
} grading_result;

int color_grading_study(const study_context *ctx, grading_result *out, gt_error *e);

#endif
