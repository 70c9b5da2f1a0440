/* FLIP, the image-difference evaluator of Andersson, Nilsson, Akenine-Möller,
 * Oskarsson, Åström and Fairchild, "FLIP: A Difference Evaluator for
 * Alternating Images", HPG 2020 (LDR-FLIP), and of Andersson, Nilsson,
 * Shirley and Akenine-Möller, "Visualizing Errors in Rendered High Dynamic
 * Range Images", Eurographics 2021 (HDR-FLIP). Per pixel an error in [0, 1]
 * of a TEST image against a REFERENCE image, seen at `ppd` pixels per degree
 * of visual angle (default 67: a 0.7 m wide 4K monitor at 0.7 m).
 *
 * LDR-FLIP, inputs linear RGB in [0, 1] (the paper's sRGB inputs decoded;
 * gtlab's quantities are linear already):
 *
 *  Colour pipeline (paper section 4.1)
 *   1. linear RGB -> XYZ (sRGB primaries, D65) -> YCxCz (Johnson and Fairchild):
 *        Y' = 116 Y/Yn - 16,  Cx = 500 (X/Xn - Y/Yn),  Cz = 200 (Y/Yn - Z/Zn);
 *   2. each channel filtered by its contrast-sensitivity function, a sum of
 *      Gaussians in the spatial domain (eq. 2):
 *        S(x) = a1 sqrt(pi/b1) exp(-pi^2 x^2/b1) + a2 sqrt(pi/b2) exp(-pi^2 x^2/b2),
 *      x in degrees (pixel / ppd), normalised to sum 1 over the kernel,
 *        achromatic  a1 = 1,    b1 = 0.0047, a2 = 0
 *        red-green   a1 = 1,    b1 = 0.0053, a2 = 0
 *        blue-yellow a1 = 34.1, b1 = 0.04,   a2 = 13.5, b2 = 0.025,
 *      on a (2r+1)^2 kernel, r = ceil(3 sqrt(b_max / (2 pi^2)) ppd) (b_max
 *      = 0.04), the image's edges replicated;
 *   3. back to linear RGB, clamped to [0, 1], to CIELAB (D65), then the Hunt
 *      adjustment a* <- 0.01 L* a*, b* <- 0.01 L* b* (eq. 3);
 *   4. HyAB distance |dL| + sqrt(da^2 + db^2) (eq. 4), raised to q_c = 0.7,
 *      compressed to [0, 1] (eq. 5) with c_max = HyAB(green, blue)^q_c of the
 *      Hunt-adjusted primaries, p_c = 0.4, p_t = 0.95:
 *        dE_c = p_t / (p_c c_max) e                          e < p_c c_max
 *             = p_t + (e - p_c c_max) / (c_max - p_c c_max) (1 - p_t)  otherwise.
 *
 *  Feature pipeline (section 4.2), on the luminance Y/Yn = (Y' + 16)/116 of
 *  the UNFILTERED images:
 *   edges:  the first derivative of a Gaussian, points: the second, of
 *     standard deviation sigma = 0.5 w ppd, w = 0.082 degrees, on a
 *     (2 ceil(3 sigma) + 1)^2 kernel, positive weights normalised to sum 1
 *     and negative ones to -1, in x and in y; |edge| and |point| the norms of
 *     the (x, y) responses;
 *   dE_f = (max(| |edge_r| - |edge_t| |, | |point_r| - |point_t| |) / sqrt 2)^q_f, q_f = 0.5.
 *
 *  FLIP = dE_c^(1 - dE_f) (eq. 7).
 *
 * HDR-FLIP (HDR paper, section 4): every exposure c of a range is applied to
 * both images (2^c v, negatives clamped to 0), tone mapped by Narkowicz's
 * ACES fit with the 0.6 pre-exposure folded in,
 *   T(x) = (k0 x^2 + k1 x) / (k3 x^2 + k4 x + k5),  k0 = 0.6^2 2.51,
 *   k1 = 0.6 0.03, k3 = 0.6^2 2.43, k4 = 0.6 0.59, k5 = 0.14,
 * clamped to [0, 1] and scored by LDR-FLIP; HDR-FLIP is the per-pixel maximum
 * over the exposures. The automatic range (section 4.2) comes from the
 * REFERENCE's luminance Y = 0.2126 R + 0.7152 G + 0.0722 B:
 *   start = log2(x_t / Y_max),  stop = log2(x_t / Y_median),
 *   x_t the tone mapper's input with output t = 0.85 (the positive root of
 *   T(x) = t), exposures N = max(2, ceil(stop - start)), evenly spaced from
 *   start to stop inclusive.
 * gtlab takes Y_max and Y_median over the pixels inside the mask (the
 * background is not image content); where that median is 0, over the
 * positive values inside it; an all-zero reference gives start = stop = 0.
 *
 * Which input is which: LDR-FLIP is symmetric in its inputs (HyAB and the
 * feature difference are), HDR-FLIP is not, its exposures being the
 * reference's; gtlab passes the ground truth as the reference.
 *
 * Masks as in metrics/image_error.h: every pixel enters the filters (as
 * SSIM's windows do), the mask selects the pixels the mean averages.
 *
 * The Gaussians are separable, so every 2-D kernel is applied as a row pass
 * and a column pass (the blue-yellow CSF, a sum of two Gaussians, as two).
 * Rows are independent and summed in a fixed order: any number of OpenMP
 * threads gives the same bits. Inputs must be finite. */
#ifndef GTLAB_METRICS_FLIP_H
#define GTLAB_METRICS_FLIP_H

#include <stddef.h>

#include "core/error.h"

#define FLIP_DEFAULT_PPD (0.7 * 3840.0 / 0.7 * 3.14159265358979323846 / 180.0) /* 67.02 */
#define FLIP_QC 0.7
#define FLIP_QF 0.5
#define FLIP_PC 0.4
#define FLIP_PT 0.95
#define FLIP_EDGE_WIDTH 0.082 /* w, degrees */
#define FLIP_EXPOSURE_T 0.85

/* A linear RGB image as three planes (width * height floats, row-major); a
 * grey image points all three at one plane. */
typedef struct {
    int width, height;
    const float *plane[3];
} flip_image;

/* The exposures HDR-FLIP uses. */
typedef struct {
    double start, stop;
    int count;
} flip_exposures;

/* LDR-FLIP of test against reference (same size, linear RGB in [0, 1])
 * into map (width * height floats). `what` names the comparison in errors.
 * Returns 0, or -1 with e: sizes differ, out of memory. */
int flip_ldr(const flip_image *reference, const flip_image *test, double ppd, const char *what, float *map,
             gt_error *e);

/* The automatic exposure range of `reference` (mask may be NULL). */
flip_exposures flip_exposure_range(const flip_image *reference, const float *mask);

/* T(x), the ACES fit clamped to [0, 1], and x_t, its input giving t. */
double flip_tone_map(double x);
double flip_tone_map_inverse(double t);

/* HDR-FLIP over `exposures` (from flip_exposure_range, or chosen) into map.
 * Returns 0, or -1 with e as flip_ldr. */
int flip_hdr(const flip_image *reference, const flip_image *test, flip_exposures exposures, double ppd,
             const char *what, float *map, gt_error *e);

/* The mean of map over the pixels inside mask (NULL: all); NaN if none. */
double flip_mean(const float *map, const float *mask, size_t count);

/* The figure gtlab reports for one channel of two images (a grey pair):
 * LDR-FLIP when every reference value inside the mask is at most 1, else
 * HDR-FLIP with the automatic exposures; the mean over the mask at the
 * default ppd. map (may be NULL) receives the per-pixel FLIP. */
typedef struct {
    double mean;
    int hdr; /* whether HDR-FLIP was used */
    flip_exposures exposures;
} flip_result;

int flip_grey(const float *reference, const float *test, const float *mask, int width, int height, const char *what,
              float *map, flip_result *out, gt_error *e);

#endif
