/* Measures of a dithered quantisation and of a dither pattern (INSIDE, GDC
 * 2016, seed 002; issue 17 item 2):
 *   - banding: the longest run of one constant quantised value along a row
 *     (a smooth gradient quantised without dither gives runs of
 *     1 / slope pixels; dither breaks them to a few pixels);
 *   - the power spectrum of a pattern or an error: the periodogram
 *         P(k) = |sum_x (v(x) - mean) exp(-2 pi i k.x / n)|^2 / N
 *     (N the number of values, so white noise of variance s^2 has
 *     E[P(k)] = s^2 at every k != 0), averaged over rows (1-D, k = 0 ..
 *     width/2) or over rings k - 1/2 <= |k| < k + 1/2 (the radially averaged
 *     power spectrum, Ulichney 1987 "Digital Halftoning", ch. 3), so a blue
 *     noise texture shows low energy below a cut-off and a flat top;
 *   - bias and error variance as a function of the signal: binned moments.
 * Plain DFTs (O(n) per output), in double, fixed order: the same bits on
 * every run. */
#ifndef GTLAB_METRICS_DITHER_METRICS_H
#define GTLAB_METRICS_DITHER_METRICS_H

#include "core/error.h"

/* The longest run of equal consecutive values in any row of a width x height plane. */
int dither_longest_run(const double *values, int width, int height);

/* Row power spectrum into power[0 .. width/2]: each row's periodogram
 * (mean removed per row), averaged over rows. Returns 0 or -1 with e. */
int dither_row_power_spectrum(const double *values, int width, int height, double *power, gt_error *e);

/* Radially averaged power spectrum of an n x n plane into power[0 .. n/2]
 * (ring k; ring 0 holds the removed mean, i.e. 0). Returns 0 or -1 with e. */
int dither_radial_power_spectrum(const double *values, int n, double *power, gt_error *e);

/* How peaked an n x n plane's periodogram is: the largest P(k) over the
 * mean P(k), both over k != 0 (the mean removed). A pattern repeating with
 * a period puts its power into a few frequencies, a noise spreads it: a
 * pure cosine gives (n^2 - 1) / 2, white noise about ln(n^2). It sees the
 * structure a blur cannot (a Bayer or gradient pattern's error). Returns 0
 * or -1 with e. */
int dither_spectrum_peak_ratio(const double *values, int n, double *ratio, gt_error *e);

/* Binned first and second moments of errors against a signal coordinate in [lo, hi[. */
typedef struct {
    int bin_count;
    double lo, hi;
    double *sum, *sum_sq; /* bin_count each */
    long *count;
} dither_binned_moments;

int dither_binned_init(dither_binned_moments *b, int bin_count, double lo, double hi, gt_error *e);
void dither_binned_free(dither_binned_moments *b);
void dither_binned_add(dither_binned_moments *b, double coordinate, double error);
/* Mean and (population) variance of bin i; 0 when the bin is empty. */
double dither_binned_mean(const dither_binned_moments *b, int i);
double dither_binned_variance(const dither_binned_moments *b, int i);

#endif
