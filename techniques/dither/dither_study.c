/* Dither patterns at equal noise power on a gradient and an HDR render: see dither_study.h. */
#include "dither/dither_study.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/progress.h"
#include "dither/dither_inputs.h"
#include "dither/dither_quality.h"
#include "metrics/dither_metrics.h"
#include "metrics/ssim.h"

enum { MODULATION_BINS = 32, UNORM_BITS = 8, WIDE_UNORM_BITS = 10 };

dither_request dither_default_request(study_quality quality)
{
    const dither_quality *q = dither_quality_of(quality);
    dither_request rq = {512, 256, q->render_width, q->render_height, q->render_spp, q->blue_noise_size, 1};
    return rq;
}

/* One way to dither: a pattern shaped into a kind, with or without the round quantiser's shift. */
typedef struct {
    dither_pattern pattern;
    dither_kind kind;
    int as_written; /* 1: the talk's formula as written; 2: and without dither_offset (tex / 255 into UNORM) */
    int bits;       /* the UNORM target: UNORM_BITS, or WIDE_UNORM_BITS for the 10-bit rows */
} dither_way;

static double dither_at(const dither_way *w, const blue_noise_texture *blue, int x, int y)
{
    if (w->kind == DITHER_NONE)
        return 0.0;
    double u0 = dither_pattern_value(w->pattern, blue, 0, x, y), u1 = dither_pattern_value(w->pattern, blue, 1, x, y);
    return dither_value(w->kind, u0, u1) + (w->as_written == 2 ? 0.0 : dither_offset(DITHER_ROUND));
}

/* Quantised image and its error in LSB. */
static void quantise(const dither_input *in, const dither_way *w, const blue_noise_texture *blue, double *q,
                     double *err, double *runs)
{
    double lsb = 1.0 / (ldexp(1.0, w->bits) - 1.0);
    for (int y = 0; y < in->height; ++y)
        for (int x = 0; x < in->width; ++x) {
            size_t i = (size_t)y * in->width + x;
            q[i] = dither_unorm(in->values[i], w->bits, dither_at(w, blue, x, y));
            err[i] = in->mask && !in->mask[i] ? 0.0 : (q[i] - in->values[i]) / lsb;
            runs[i] = in->mask && !in->mask[i] ? -1.0 - (double)i : q[i]; /* outside: never a run */
        }
}

/* The amplitude a of Var(f) = c + a (g(f)), g = f (1 - f) - 1/6, by least
 * squares over the bins' variances, and its standard error from each bin's
 * variance error sqrt((m4 - var^2) / n). */
static void modulation_amplitude(const dither_binned_moments *b, const double *m4, dither_row *row)
{
    double sg = 0, sv = 0, sgg = 0, sgv = 0, var_a = 0;
    int used = 0;
    for (int k = 0; k < b->bin_count; ++k)
        if (b->count[k] > 1) {
            double f = (k + 0.5) / b->bin_count, g = f * (1 - f) - 1.0 / 6.0, v = dither_binned_variance(b, k);
            sg += g, sv += v, sgg += g * g, sgv += g * v, ++used;
        }
    double gm = used ? sg / used : 0.0, sxx = sgg - used * gm * gm;
    row->modulation_amplitude = sxx > 0 ? (sgv - gm * sv) / sxx : 0.0;
    for (int k = 0; k < b->bin_count && sxx > 0; ++k)
        if (b->count[k] > 1) {
            double f = (k + 0.5) / b->bin_count, g = f * (1 - f) - 1.0 / 6.0 - gm, v = dither_binned_variance(b, k);
            var_a += g * g / (sxx * sxx) * fmax(m4[k] - v * v, 0.0) / b->count[k];
        }
    row->modulation_amplitude_se = sqrt(var_a);
}

/* Bias, variance and noise modulation over bins of the signal's fraction (LSB). */
static int error_moments(const dither_input *in, const double *err, int bits, dither_row *row, gt_error *e)
{
    dither_binned_moments b;
    double m4[MODULATION_BINS] = {0}, sum = 0, sum_sq = 0, lo = INFINITY, hi = -INFINITY, scale = ldexp(1.0, bits) - 1.0;
    size_t n = (size_t)in->width * in->height, counted = 0;
    if (dither_binned_init(&b, MODULATION_BINS, 0.0, 1.0, e) != 0)
        return -1;
    for (size_t i = 0; i < n; ++i)
        if (!in->mask || in->mask[i]) {
            double s = in->values[i] * scale;
            dither_binned_add(&b, s - floor(s), err[i]);
            sum += err[i], sum_sq += err[i] * err[i], ++counted;
        }
    for (size_t i = 0; i < n; ++i) /* fourth central moments per bin */
        if (!in->mask || in->mask[i]) {
            double s = in->values[i] * scale;
            int k = (int)((s - floor(s)) * MODULATION_BINS);
            double c = err[i] - dither_binned_mean(&b, k);
            m4[k] += c * c * c * c / (double)b.count[k];
        }
    for (int k = 0; k < MODULATION_BINS; ++k)
        if (b.count[k] > 1) {
            lo = fmin(lo, dither_binned_variance(&b, k)), hi = fmax(hi, dither_binned_variance(&b, k));
            row->worst_bin_bias = fmax(row->worst_bin_bias, fabs(dither_binned_mean(&b, k)));
        }
    row->bias = counted ? sum / counted : 0.0;
    row->variance = counted ? sum_sq / counted - row->bias * row->bias : 0.0;
    row->modulation = hi > lo ? hi - lo : 0.0;
    modulation_amplitude(&b, m4, row);
    dither_binned_free(&b);
    return 0;
}

static int low_power_share(const dither_input *in, const double *err, double *share, gt_error *e)
{
    double *p = malloc(((size_t)in->width / 2 + 1) * sizeof(double)), low = 0, all = 0;
    if (!p)
        return gt_error_set(e, "dither", "out of memory");
    int rc = dither_row_power_spectrum(err, in->width, in->height, p, e);
    for (int k = 1; k <= in->width / 2 && rc == 0; ++k) {
        all += p[k];
        low += k < in->width / 8 ? p[k] : 0.0;
    }
    *share = all > 0 ? low / all : 0.0;
    free(p);
    return rc;
}

static int dssim_pair(const dither_input *in, const double *q, int blurred, double *dssim, gt_error *e)
{
    size_t n = (size_t)in->width * in->height;
    float *a = malloc(n * sizeof(float)), *b = malloc(n * sizeof(float)), *mask = NULL;
    int rc = a && b ? 0 : gt_error_set(e, "dither", "out of memory");
    if (rc == 0 && in->mask && !(mask = malloc(n * sizeof(float))))
        rc = gt_error_set(e, "dither", "out of memory");
    for (size_t i = 0; i < n && rc == 0; ++i) {
        a[i] = (float)in->values[i], b[i] = (float)q[i];
        if (mask)
            mask[i] = in->mask[i] ? 1.0f : 0.0f;
    }
    if (rc == 0 && blurred)
        rc = dither_blur_display(a, in->width, in->height, e) || dither_blur_display(b, in->width, in->height, e);
    ssim_result r;
    rc = rc == 0 ? ssim_compute(b, a, mask, in->width, in->height, "dither", NULL, &r, e) : rc;
    *dssim = rc == 0 ? r.dssim : 0.0;
    free(a), free(b), free(mask);
    return rc;
}

static int score_way(const dither_input *in, const dither_way *w, const blue_noise_texture *blue, dither_row *row,
                     gt_error *e)
{
    size_t n = (size_t)in->width * in->height;
    double *q = malloc(n * sizeof(double)), *err = malloc(n * sizeof(double)), *runs = malloc(n * sizeof(double));
    int rc = q && err && runs ? 0 : gt_error_set(e, "dither", "out of memory");
    if (rc == 0) {
        quantise(in, w, blue, q, err, runs);
        row->longest_run = dither_longest_run(runs, in->width, in->height);
        rc = error_moments(in, err, w->bits, row, e) || low_power_share(in, err, &row->low_power_share, e) ||
             dssim_pair(in, q, 0, &row->dssim, e) || dssim_pair(in, q, 1, &row->dssim_blurred, e);
    }
    free(q), free(err), free(runs);
    return rc ? -1 : 0;
}

/* none; each pattern as RPDF and TPDF (remap); the talk's two as-written forms; then the 10-bit
 * target (issue 17 item 2): none, blue RPDF and blue TPDF (remap). */
static int dither_ways(dither_way *ways)
{
    int n = 0;
    ways[n++] = (dither_way){DITHER_PATTERN_WHITE, DITHER_NONE, 0, UNORM_BITS};
    for (int p = 0; p < DITHER_PATTERN_COUNT; ++p) {
        ways[n++] = (dither_way){(dither_pattern)p, DITHER_RPDF, 0, UNORM_BITS};
        ways[n++] = (dither_way){(dither_pattern)p, DITHER_TPDF_REMAP, 0, UNORM_BITS};
    }
    ways[n++] = (dither_way){DITHER_PATTERN_WHITE, DITHER_TPDF_AVERAGE, 1, UNORM_BITS};
    ways[n++] = (dither_way){DITHER_PATTERN_BLUE, DITHER_RPDF, 2, UNORM_BITS};
    ways[n++] = (dither_way){DITHER_PATTERN_WHITE, DITHER_NONE, 0, WIDE_UNORM_BITS};
    ways[n++] = (dither_way){DITHER_PATTERN_BLUE, DITHER_RPDF, 0, WIDE_UNORM_BITS};
    ways[n++] = (dither_way){DITHER_PATTERN_BLUE, DITHER_TPDF_REMAP, 0, WIDE_UNORM_BITS};
    return n;
}

static void way_label(const dither_way *w, char *label, size_t size)
{
    const char *target = w->bits == UNORM_BITS ? "" : ", 10-bit";
    if (w->kind == DITHER_NONE)
        snprintf(label, size, "none%s", target);
    else
        snprintf(label, size, "%s %s%s%s", dither_pattern_name(w->pattern), dither_kind_name(w->kind),
                 w->as_written ? " (as written)" : "", target);
}

static int study_image(const dither_input *in, const blue_noise_texture *blue, dither_image_result *out,
                       gt_error *e)
{
    dither_way ways[DITHER_MAX_ROWS];
    out->row_count = dither_ways(ways);
    for (int r = 0; r < out->row_count; ++r) {
        way_label(&ways[r], out->rows[r].label, sizeof out->rows[r].label);
        if (score_way(in, &ways[r], blue, &out->rows[r], e) != 0)
            return -1;
    }
    return 0;
}

int dither_study(const study_context *ctx, const dither_request *rq, dither_result *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    out->request = *rq;
    char dir[4096];
    blue_noise_texture blue;
    dither_input inputs[DITHER_IMAGES];
    memset(inputs, 0, sizeof inputs);
    if (study_make_dir(ctx, DITHER_DIR, dir, sizeof dir, e) != 0 || dither_blue_noise(dir, rq, &blue, out, e) != 0)
        return -1;
    int rc = dither_gradient(rq, &inputs[0], e) || dither_render(ctx, rq, &inputs[1], e);
    for (int i = 0; i < DITHER_IMAGES && rc == 0; ++i) {
        out->images[i].image_name = inputs[i].name;
        rc = study_image(&inputs[i], &blue, &out->images[i], e);
    }
    if (rc == 0)
        dither_small_float_rows(rq->seed, out->small_float);
    for (int i = 0; i < DITHER_IMAGES; ++i)
        free(inputs[i].values), free(inputs[i].mask);
    blue_noise_free(&blue);
    return rc ? -1 : 0;
}
