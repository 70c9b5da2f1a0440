/* Dithering and blue noise as INSIDE uses them (Gjoel, GDC 2016, seed 002;
 * issue 17 item 2), measured on two display images:
 *   - a smooth gradient (display values 0.20 .. 0.30 over the width: 25.5
 *     LSB of 8 bits, runs of ~20 pixels undithered);
 *   - an HDR render gtlab makes: the unshadowed sphere light over
 *     builtin:sphere-on-plane (techniques/sphere_light/sphere_light_integrator.h; no rays
 *     are traced), green channel, Reinhard x / (1 + x) after an exposure
 *     putting the 99th percentile at 1, then the sRGB transfer function;
 *     statistics over the pixels that see a surface (the background is 0,
 *     where dither clips).
 * Each is quantised to 8-bit UNORM (round to nearest) with no dither and
 * with every pattern of realtime/dither_patterns.h shaped as RPDF (u - 1/2)
 * and as TPDF by the talk's remap_tri (minus 1/2): one flat-histogram
 * pattern per column, so all have equal noise power (the dither's variance
 * 1/12 or 1/6 LSB^2; the error variance is measured). Two rows reproduce the
 * talk's code as written: "(rand + rand) / 2" (a 1-LSB triangle) and
 * `outcol += tex / 255` (blue RPDF on [0, 1[ into a rounding quantiser).
 * Then the 10-bit UNORM target with no, blue RPDF and blue TPDF dither
 * ("..., 10-bit" rows; errors in 10-bit LSB, the gradient spans 102 of them).
 * Per row: bias and variance of the error (LSB), its noise modulation (the
 * spread of the variance over 32 bins of the signal's fraction f, and the
 * amplitude a of Var(f) = c + a (f (1 - f) - 1/6) by least squares over
 * the bins: 1 for RPDF, 0 for TPDF, with its standard error from the bins'
 * fourth moments), the
 * longest constant run, the share of the error's row power spectrum below
 * a quarter of Nyquist, and DSSIM against the unquantised image, plain and
 * after a display-resolution blur (Gaussian, sigma 1 pixel).
 * R11G11B10: a linear ramp over [0.5, 4[ quantised to the 6-bit-mantissa
 * float with no, RPDF and TPDF dither scaled by the local spacing: bias and
 * error variance in units of that spacing, worst over bins. */
#ifndef GTLAB_DITHER_DITHER_STUDY_H
#define GTLAB_DITHER_DITHER_STUDY_H

#include "dither/dither.h"
#include "realtime/dither_patterns.h"
#include "project/study_context.h"

#define DITHER_DIR "dither"

enum { DITHER_IMAGES = 2, DITHER_MAX_ROWS = 16, DITHER_SMALL_FLOAT_ROWS = 3 };

typedef struct {
    int gradient_width, gradient_height;
    int render_width, render_height, render_spp;
    int blue_noise_size; /* the tiled texture; also written to <output>/dither/ */
    unsigned seed;
} dither_request;

typedef struct {
    char label[48];      /* "blue tpdf-remap" */
    double bias;         /* mean error, LSB */
    double worst_bin_bias; /* max over the bins of f of |mean error|, LSB */
    double variance;     /* error variance, LSB^2 */
    double modulation;   /* max - min binned variance, LSB^2 (biased up by the bins' noise) */
    double modulation_amplitude; /* a of Var(f) = c + a (f (1 - f) - 1/6) fitted over the bins: RPDF 1, TPDF 0 */
    double modulation_amplitude_se;
    int longest_run;
    double low_power_share; /* error power below Nyquist / 4 over all */
    double dssim, dssim_blurred;
} dither_row;

typedef struct {
    const char *image_name; /* "gradient", "sphere light" */
    int row_count;
    dither_row rows[DITHER_MAX_ROWS];
} dither_image_result;

typedef struct {
    const char *kind;
    double worst_bias, worst_variance, best_variance; /* in local spacings */
} dither_small_float_row;

typedef struct {
    dither_request request;
    dither_image_result images[DITHER_IMAGES];
    dither_small_float_row small_float[DITHER_SMALL_FLOAT_ROWS];
    double blue_noise_seconds;
    /* the texture's radial spectrum, rings 1..n/16 and n/4..n/2, over white's (1/12), as is and after remap_tri (over 1/6) */
    double blue_low_ring_power, blue_high_ring_power, remapped_low_ring_power, remapped_high_ring_power;
} dither_result;

dither_request dither_default_request(study_quality quality);

int dither_study(const study_context *ctx, const dither_request *rq, dither_result *out, gt_error *e);

#endif
