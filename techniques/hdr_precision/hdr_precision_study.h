/* Kaplanyan 2010's precision figures, derived (hdr_precision.h):
 * the point above which 8-bit linear storage is finer than gamma storage
 * (the talk: x = 5/11 ~ 116/255), and the HDR lower bounds c_min / l of the
 * exponential and filmic tone mappers (the talk: 0.00196271 and 0.0119052),
 * each by its closed form and checked by bisection, and the filmic bound of
 * the curve as the slide prints it. Writes <output>/hdr/code_steps.dat
 * (linear x, the step of one 8-bit code in linear units: linear, gamma 2.2,
 * sRGB), the data of the report's plot. */
#ifndef GTLAB_HDR_PRECISION_STUDY_H
#define GTLAB_HDR_PRECISION_STUDY_H

#include "project/study_context.h"

#define HDR_PRECISION_DIR "hdr_precision"

typedef struct {
    double talk_median;                 /* 5/11 */
    double gamma22_point, srgb_point;   /* x* */
    double exponential_c_min, exponential_bisection; /* per unit l */
    double filmic_c_min, filmic_bisection;
    double filmic_transcribed_c_min;    /* the slide's denominator */
    double filmic_display_threshold_c_min; /* threshold on the display-encoded output */
} hdr_precision_result;

int hdr_precision_study(const study_context *ctx, hdr_precision_result *out, gt_error *e);

#endif
