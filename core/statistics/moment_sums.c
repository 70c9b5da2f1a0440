#include "core/statistics/moment_sums.h"

#include <math.h>
#include <string.h>

#define DIGIT_BASE 0x1p24 /* 2^MOMENT_DIGIT_BITS */

void moment_sums_clear(moment_sums *m) { memset(m, 0, sizeof *m); }

/* |v| as its bit pattern, which orders as the magnitudes do (a NaN above
 * infinity): peaks compare as integers, in any order the same. */
static uint32_t magnitude_bits(float v)
{
    uint32_t bits;
    memcpy(&bits, &v, sizeof bits);
    return bits & 0x7fffffffu;
}

static double larger_peak(double a, float b) { return magnitude_bits((float)a) >= magnitude_bits(b) ? a : b; }

/* Compared as signed integers: the masked bit patterns are non-negative,
 * and signed maxima vectorise on every x86-64. */
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target_clones("avx2", "default")))
#endif
float moment_sums_run_peak(const float *restrict values, int count)
{
    int32_t largest = 0;
    for (int k = 0; k < count; ++k) {
        int32_t bits = (int32_t)magnitude_bits(values[k]);
        largest = bits > largest ? bits : largest;
    }
    float peak;
    memcpy(&peak, &largest, sizeof peak);
    return peak;
}

/* frexp's exponent e of x (> 0, finite, normal), x = f 2^e with f in
 * [1/2, 1), read from the bits (peaks and their squares are normal doubles). */
static int exponent_of(double x)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    return (int)((bits >> 52) & 0x7ff) - 1022;
}

/* The position of the top limb for terms of peak x (> 0, finite):
 * floor(e / 24). Then every term |t| <= x < 2^(24 (top + 1)) / 2, so its
 * digits above top are 0. */
static int window_top(double x)
{
    int e = exponent_of(x);
    return e >= 0 ? e / MOMENT_DIGIT_BITS : -((MOMENT_DIGIT_BITS - 1 - e) / MOMENT_DIGIT_BITS);
}

/* 2^k, k within the normal range of a double / of a float. */
static double power_of_two(int k)
{
    uint64_t bits = (uint64_t)(k + 1023) << 52;
    double x;
    memcpy(&x, &bits, sizeof x);
    return x;
}

static float power_of_two_f(int k)
{
    uint32_t bits = (uint32_t)(k + 127) << 23;
    float x;
    memcpy(&x, &bits, sizeof x);
    return x;
}

/* Moves limbs from the window whose top is `from` to the one whose top is
 * `to` (>= from). The terms' digits above `from` are 0, and dropping the
 * lowest limbs rounds every term at the new bottom. */
static void raise_window(int64_t limb[MOMENT_LIMBS], int from, int to)
{
    int shift = to - from;
    for (int k = MOMENT_LIMBS - 1; k >= 0 && shift > 0; --k)
        limb[k] = k >= shift ? limb[k - shift] : 0;
}

/* Sets the peak to `peak` (>= the current one), moving both windows; a
 * non-finite peak leaves nothing to keep. */
static void set_peak(moment_sums *m, double peak)
{
    if (!isfinite(peak)) {
        moment_sums_clear(m);
        m->peak = peak;
        return;
    }
    if (m->peak > 0.0) {
        double before = m->peak;
        raise_window(m->sum, window_top(before), window_top(peak));
        raise_window(m->sum_sq, window_top(before * before), window_top(peak * peak));
    }
    m->peak = peak;
}

/* The balanced digits of a term x at the window of top `top`: with scales
 * s_k = 2^-(24 (top - k)), r_0 = rint(x s_0) and r_k - 2^24 r_(k-1),
 * r_k = rint(x s_k). They are integers within 2^23; x s_k is exact (a
 * power of two), and so is the subtraction (Sterbenz: the operands are
 * within 2^23 of each other and beyond 2^24, or r_(k-1) = 0). The loops
 * below sum them as 32-bit integers, at most CHUNK terms at a time (within
 * 2^31), so they vectorise (AVX2 where the CPU has it). */
enum { CHUNK = 128 };

/* Digits of the values themselves in float arithmetic, eight at a time:
 * exact as long as the scales are floats (top >= -3, peaks above 2^-72). */
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target_clones("avx2", "default")))
#endif
static void value_digits_float(const float *restrict values, int count, int top, int32_t digits[MOMENT_LIMBS])
{
    const float s0 = power_of_two_f(-MOMENT_DIGIT_BITS * top), s1 = s0 * 0x1p24f, s2 = s1 * 0x1p24f;
    int32_t d0 = 0, d1 = 0, d2 = 0;
    for (int k = 0; k < count; ++k) {
        float r0 = rintf(values[k] * s0), r1 = rintf(values[k] * s1), r2 = rintf(values[k] * s2);
        d0 += (int32_t)r0;
        d1 += (int32_t)(r1 - 0x1p24f * r0);
        d2 += (int32_t)(r2 - 0x1p24f * r1);
    }
    digits[0] = d0, digits[1] = d1, digits[2] = d2;
}

/* Digits of the values (square = 0) or of their squares (1, exact in a
 * double) in double arithmetic. */
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target_clones("avx2", "default")))
#endif
static void term_digits_double(const float *restrict values, int count, int square, int top,
                               int32_t digits[MOMENT_LIMBS])
{
    const double s0 = power_of_two(-MOMENT_DIGIT_BITS * top), s1 = s0 * DIGIT_BASE, s2 = s1 * DIGIT_BASE;
    int32_t d0 = 0, d1 = 0, d2 = 0;
    for (int k = 0; k < count; ++k) {
        double v = values[k], x = v * (square ? v : 1.0);
        double r0 = rint(x * s0), r1 = rint(x * s1), r2 = rint(x * s2);
        d0 += (int32_t)r0;
        d1 += (int32_t)(r1 - DIGIT_BASE * r0);
        d2 += (int32_t)(r2 - DIGIT_BASE * r1);
    }
    digits[0] = d0, digits[1] = d1, digits[2] = d2;
}

static void add_limbs(int64_t limb[MOMENT_LIMBS], const int32_t digits[MOMENT_LIMBS])
{
    for (int k = 0; k < MOMENT_LIMBS; ++k)
        limb[k] += digits[k];
}

void moment_sums_add_run(moment_sums *m, const float *values, int count, float run_peak)
{
    set_peak(m, larger_peak(m->peak, run_peak));
    if (!isfinite(m->peak) || m->peak == 0.0)
        return;
    int top = window_top(m->peak), top_sq = window_top(m->peak * m->peak);
    for (int first = 0; first < count; first += CHUNK) {
        int n = count - first < CHUNK ? count - first : CHUNK;
        int32_t digits[MOMENT_LIMBS];
        if (top >= -3)
            value_digits_float(values + first, n, top, digits);
        else
            term_digits_double(values + first, n, 0, top, digits);
        add_limbs(m->sum, digits);
        term_digits_double(values + first, n, 1, top_sq, digits);
        add_limbs(m->sum_sq, digits);
    }
}

void moment_sums_merge(moment_sums *dst, const moment_sums *src)
{
    double peak = larger_peak(dst->peak, (float)src->peak);
    moment_sums aligned = *src;
    set_peak(dst, peak);
    set_peak(&aligned, peak);
    for (int k = 0; k < MOMENT_LIMBS; ++k) {
        dst->sum[k] += aligned.sum[k];
        dst->sum_sq[k] += aligned.sum_sq[k];
    }
}

/* sum_k limb[k] 2^(24 (top - k)), each product exact (below 2^53 a limb
 * is a double exactly; beyond, it is rounded by 2^-53 of itself), summed
 * from the smallest: within 2^-52 of the sum's magnitude. */
static double limbs_value(const int64_t limb[MOMENT_LIMBS], int top)
{
    double value = 0.0;
    for (int k = MOMENT_LIMBS - 1; k >= 0; --k)
        value += (double)limb[k] * power_of_two(MOMENT_DIGIT_BITS * (top - k));
    return value;
}

double moment_sums_total(const moment_sums *m)
{
    if (!isfinite(m->peak))
        return NAN;
    if (m->peak == 0.0)
        return 0.0;
    return limbs_value(m->sum, window_top(m->peak));
}

double moment_sums_variance(const moment_sums *m, uint64_t n)
{
    if (!isfinite(m->peak) || n < 2)
        return NAN;
    if (m->peak == 0.0)
        return 0.0;
    double peak = m->peak, count = (double)n;
    double s1 = limbs_value(m->sum, window_top(peak)), s2 = limbs_value(m->sum_sq, window_top(peak * peak));
    return (count * s2 - s1 * s1) / (count * (count - 1.0));
}
