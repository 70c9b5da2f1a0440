/* The sums of a pixel's samples and of their squares, exact and independent
 * of the order of addition, at a precision relative to the pixel's own
 * largest sample: what its standard error is computed from (issue 23).
 *
 * The film's grid (core/statistics/mc_film.h) is one per quantity, 2^(E-24) with E set
 * by the brightest pixels; squares rounded onto 2^(2E-24) vanished on pixels
 * 2^12 times dimmer, whose standard errors then came out 0. Here the grid
 * follows each pixel.
 *
 * Binned sums, after Demmel and Nguyen 2015 ("Parallel reproducible
 * summation", IEEE Trans. Computers 64(7); ReproBLAS): bins at fixed
 * positions, chosen from the largest term alone, so the rounding does not
 * depend on the order. Here the bins hold integer sums of balanced digits.
 * Positions are multiples of 24 bits. A value x has the digits
 *
 *     d_j(x) = R_j(x) - 2^24 R_{j+1}(x),   R_j(x) = rint(x / 2^(24 j)),
 *
 * |d_j| <= 2^23, which telescope: the digits of positions >= b add up to
 * R_b(x) 2^(24 b), x rounded to the nearest multiple of 2^(24 b). A sum
 * whose terms have peak P (the largest |x|; P = f 2^e with f in [1/2, 1))
 * keeps three limbs, the sums of the terms' digits at positions
 * top = floor(e / 24), top - 1 and b = top - 2: 64-bit integers, within
 * 2^63 for up to 2^40 terms, so exact and the same in any order. A larger peak moves
 * the window up by dropping the lowest limbs, which is exactly rounding each
 * term at the new bottom. So the limbs always hold
 *
 *     sum_i R_b(x_i) 2^(24 b),   b = top(P) - 2,
 *
 * whatever the order of the terms or their split into partial sums (merge
 * of sample blocks, resumed renders): the same bits. Each term is rounded by
 * at most 2^(24 b - 1) <= 2^-48 P; the sum of values keeps every sample
 * within 2^24 of the peak exactly.
 *
 * The sum of values has peak P = max |v|, the sum of squares P^2 (a float's
 * square is exact in a double). The sample variance
 *     s^2 = (n S2 - S1^2) / (n (n - 1))
 * from them is within 2^-45 P^2 of the samples' own: the terms' rounding
 * moves n S2 by at most n^2 2^-48 P^2 and S1^2 by 2 n^2 2^-48 P^2, which is
 * 6 2^-48 P^2 in s^2 for n >= 2, and evaluating it in doubles adds 2^-50 P^2.
 * The bound is relative to the pixel's own peak, not to any other pixel's: a
 * pixel whose samples spread by more than about 2^-22 of its largest has a
 * non-zero standard error, however dim it is next to the rest of the image.
 * (A constant pixel reads a variance within the bound of 0; exactly 0 when
 * its square is exact in the window, as for 0 and 1.) */
#ifndef GTLAB_CORE_STATISTICS_MOMENT_SUMS_H
#define GTLAB_CORE_STATISTICS_MOMENT_SUMS_H

#include <stdint.h>

#define MOMENT_LIMBS 3       /* limb k at position top - k */
#define MOMENT_DIGIT_BITS 24 /* positions are multiples of 2^24 */

typedef struct {
    double peak; /* largest |v| added (a float): 0 before any non-zero sample; NaN or inf once one was */
    int64_t sum[MOMENT_LIMBS], sum_sq[MOMENT_LIMBS]; /* limbs of sum v (peak P) and of sum v^2 (peak P^2) */
} moment_sums;

void moment_sums_clear(moment_sums *m);
/* The largest |v| of values[0 .. count-1], a NaN above everything. */
float moment_sums_run_peak(const float *values, int count);
/* Adds values[0 .. count-1], whose moment_sums_run_peak is run_peak. A NaN
 * or infinity makes the sums unknown (peak non-finite, limbs 0, variance
 * NaN). */
void moment_sums_add_run(moment_sums *m, const float *values, int count, float run_peak);
/* dst += src: the sums of the union of their samples. Exact. */
void moment_sums_merge(moment_sums *dst, const moment_sums *src);

/* The sum of values, sum_i R_b(v_i) 2^(24 b), rounded to a double. */
double moment_sums_total(const moment_sums *m);
/* The unbiased sample variance of the n samples added (n >= 2), from the
 * exact sums (error within 2^-45 peak^2; it may be that far below 0); NaN
 * when the sums are unknown. */
double moment_sums_variance(const moment_sums *m, uint64_t n);

#endif
