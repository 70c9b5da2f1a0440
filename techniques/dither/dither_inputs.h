/* The dither study's inputs and helpers (dither_study.h): the gradient,
 * the tone-mapped HDR render, the display blur, the blue-noise texture and
 * the R11G11B10 rows. */
#ifndef GTLAB_DITHER_DITHER_INPUTS_H
#define GTLAB_DITHER_DITHER_INPUTS_H

#include "core/image.h"
#include "dither/dither_study.h"
#include "luts/blue_noise.h"

typedef struct {
    const char *name;
    int width, height;
    double *values; /* display values in [0, 1], row-major */
    unsigned char *mask; /* 1 where the statistics count, or NULL: everywhere */
} dither_input;

/* 0.20 .. 0.30 across the width, constant down the columns. */
int dither_gradient(const dither_request *rq, dither_input *out, gt_error *e);

/* The unshadowed sphere light on builtin:sphere-on-plane, green, Reinhard
 * after scaling the 99th percentile of covered pixels to 1, sRGB-encoded
 * (the HDR image: techniques/sphere_light/sphere_light_hdr_test_image.h). */
int dither_render(const study_context *ctx, const dither_request *rq, dither_input *out, gt_error *e);

/* In place: a separable Gaussian of sigma 1 pixel (radius 3, clamped edges). */
int dither_blur_display(float *plane, int width, int height, gt_error *e);

/* Builds the rq->blue_noise_size^2 texture (4 channels), writes
 * <dir>/blue_noise_<n>.{exr,png}, and fills out's timing and spectrum fields. */
int dither_blue_noise(const char *dir, const dither_request *rq, blue_noise_texture *blue, dither_result *out,
                      gt_error *e);

/* The R11G11B10 (6-bit mantissa) rows: none, RPDF and TPDF (sum) dither scaled by the local spacing. */
void dither_small_float_rows(unsigned seed, dither_small_float_row rows[DITHER_SMALL_FLOAT_ROWS]);

#endif
