/* The moments of dithered quantisation errors against their laws: see dither_check.h. */
#include "dither/dither_check.h"

#include <math.h>

#include "luts/blue_noise.h"

static double variance_law(dither_kind kind, double f) { return kind == DITHER_RPDF ? f * (1.0 - f) : 0.25; }

/* Mean, variance and their standard errors at signal s. */
static void moments_at(dither_kind kind, double s, int samples, uint64_t seed, double m[4])
{
    double sum = 0, sum2 = 0, sum3 = 0, sum4 = 0;
    for (int i = 0; i < samples; ++i) {
        double d = dither_value(kind, blue_noise_uniform(seed, 2 * (uint64_t)i), blue_noise_uniform(seed, 2 * (uint64_t)i + 1));
        double x = dither_quantise_lsb(s + d, DITHER_FLOOR) - s;
        sum += x, sum2 += x * x, sum3 += x * x * x, sum4 += x * x * x * x;
    }
    double mean = sum / samples, var = sum2 / samples - mean * mean;
    double m4 = sum4 / samples - 4 * mean * sum3 / samples + 6 * mean * mean * sum2 / samples - 3 * pow(mean, 4);
    m[0] = mean, m[1] = var;
    m[2] = sqrt(var / samples) + 1e-12, m[3] = sqrt(fmax(m4 - var * var, 0.0) / samples) + 1e-12;
}

static void check_kind(dither_kind kind, int signals, int samples, unsigned seed, dither_check_row *row)
{
    *row = (dither_check_row){kind, kind != DITHER_TPDF_AVERAGE, 0, 0, 0, INFINITY, 0};
    for (int k = 0; k < signals; ++k) {
        double s = 2.0 + (double)k / (signals - 1), f = s - floor(s), m[4];
        moments_at(kind, s, samples, (uint64_t)seed * 1000 + (uint64_t)k, m);
        row->worst_bias_se = fmax(row->worst_bias_se, fabs(m[0]) / m[2]);
        row->worst_bias = fmax(row->worst_bias, fabs(m[0]));
        row->worst_variance_se = fmax(row->worst_variance_se, fabs(m[1] - variance_law(kind, f)) / m[3]);
        row->min_variance = fmin(row->min_variance, m[1]), row->max_variance = fmax(row->max_variance, m[1]);
    }
}

int dither_check_run(int signals, int samples, unsigned seed, dither_check_result *out, gt_error *e)
{
    static const dither_kind kinds[DITHER_CHECK_KINDS] = {DITHER_RPDF, DITHER_TPDF_SUM, DITHER_TPDF_REMAP,
                                                          DITHER_TPDF_AVERAGE};
    if (signals < 2 || samples < 100)
        return gt_error_set(e, "check dither", "need at least 2 signals and 100 samples");
    out->signals = signals, out->samples = samples;
    for (int k = 0; k < DITHER_CHECK_KINDS; ++k)
        check_kind(kinds[k], signals, samples, seed, &out->rows[k]);
    return 0;
}

int dither_check_print(const dither_check_result *r, FILE *out)
{
    int failed = 0;
    fprintf(out, "%-14s %12s %12s %12s %12s %12s\n", "dither", "|bias|/SE", "|var-law|/SE", "max |bias|", "min var",
            "max var");
    for (int k = 0; k < DITHER_CHECK_KINDS; ++k) {
        const dither_check_row *w = &r->rows[k];
        int bad = w->has_law && (w->worst_bias_se > 5 || w->worst_variance_se > 5);
        char law[32] = "           -";
        if (w->has_law)
            snprintf(law, sizeof law, "%12.2f", w->worst_variance_se);
        fprintf(out, "%-14s %12.2f %s %12.4f %12.4f %12.4f%s\n", dither_kind_name(w->kind), w->worst_bias_se, law,
                w->worst_bias, w->min_variance, w->max_variance,
                !w->has_law ? "  (no law: the talk's formula as written)" : bad ? "  FAIL" : "");
        failed |= bad;
    }
    return failed;
}
