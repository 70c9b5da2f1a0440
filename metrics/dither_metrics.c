/* Banding, spectra and binned moments of dithered quantisation: see dither_metrics.h. */
#include "metrics/dither_metrics.h"

#include <math.h>
#include <stdlib.h>

#include "core/vec3.h" /* M_PI */

int dither_longest_run(const double *values, int width, int height)
{
    int longest = 0;
    for (int y = 0; y < height; ++y) {
        const double *row = values + (size_t)y * (size_t)width;
        int run = 1;
        for (int x = 1; x < width; ++x) {
            run = row[x] == row[x - 1] ? run + 1 : 1;
            longest = run > longest ? run : longest;
        }
        longest = width > 0 && longest < 1 ? 1 : longest;
    }
    return longest;
}

/* The DFT of n complex values in (re, im) with stride, into (out_re, out_im). */
static void dft(const double *re, const double *im, int n, size_t stride, const double *cos_t,
                const double *sin_t, double *out_re, double *out_im)
{
    for (int k = 0; k < n; ++k) {
        double sr = 0.0, si = 0.0;
        for (int x = 0; x < n; ++x) {
            int t = (int)(((long)k * x) % n);
            double a = re[(size_t)x * stride], b = im ? im[(size_t)x * stride] : 0.0;
            sr += a * cos_t[t] + b * sin_t[t];
            si += b * cos_t[t] - a * sin_t[t];
        }
        out_re[k] = sr;
        out_im[k] = si;
    }
}

static int twiddles(int n, double **cos_t, double **sin_t, gt_error *e)
{
    *cos_t = malloc((size_t)n * sizeof(double));
    *sin_t = malloc((size_t)n * sizeof(double));
    if (!*cos_t || !*sin_t)
        return gt_error_set(e, "power spectrum", "out of memory");
    for (int t = 0; t < n; ++t) {
        (*cos_t)[t] = cos(2.0 * M_PI * t / n);
        (*sin_t)[t] = sin(2.0 * M_PI * t / n);
    }
    return 0;
}

static double mean_of(const double *v, size_t count)
{
    double s = 0.0;
    for (size_t i = 0; i < count; ++i)
        s += v[i];
    return count ? s / (double)count : 0.0;
}

int dither_row_power_spectrum(const double *values, int width, int height, double *power, gt_error *e)
{
    double *cos_t = NULL, *sin_t = NULL, *buf = malloc((size_t)width * 3 * sizeof(double));
    int rc = !buf ? gt_error_set(e, "power spectrum", "out of memory") : twiddles(width, &cos_t, &sin_t, e);
    for (int k = 0; k <= width / 2; ++k)
        power[k] = 0.0;
    for (int y = 0; y < height && rc == 0; ++y) {
        const double *row = values + (size_t)y * (size_t)width;
        double m = mean_of(row, (size_t)width);
        for (int x = 0; x < width; ++x)
            buf[x] = row[x] - m;
        dft(buf, NULL, width, 1, cos_t, sin_t, buf + width, buf + 2 * width);
        for (int k = 0; k <= width / 2; ++k)
            power[k] += (buf[width + k] * buf[width + k] + buf[2 * width + k] * buf[2 * width + k]) / width / height;
    }
    free(buf);
    free(cos_t);
    free(sin_t);
    return rc;
}

/* The 2-D DFT of the mean-removed plane: rows, then columns. */
static int dft_2d(const double *values, int n, double *re, double *im, gt_error *e)
{
    size_t count = (size_t)n * (size_t)n;
    double *cos_t = NULL, *sin_t = NULL, *t_re = malloc(count * sizeof(double)), *t_im = malloc(count * sizeof(double));
    double *centred = malloc(count * sizeof(double));
    int rc = !t_re || !t_im || !centred ? gt_error_set(e, "power spectrum", "out of memory")
                                        : twiddles(n, &cos_t, &sin_t, e);
    if (rc == 0) {
        double m = mean_of(values, count);
        for (size_t i = 0; i < count; ++i)
            centred[i] = values[i] - m;
        for (int y = 0; y < n; ++y)
            dft(centred + (size_t)y * n, NULL, n, 1, cos_t, sin_t, t_re + (size_t)y * n, t_im + (size_t)y * n);
        double col_re[1024], col_im[1024];
        for (int x = 0; x < n; ++x) {
            dft(t_re + x, t_im + x, n, (size_t)n, cos_t, sin_t, col_re, col_im);
            for (int k = 0; k < n; ++k) {
                re[(size_t)k * n + x] = col_re[k];
                im[(size_t)k * n + x] = col_im[k];
            }
        }
    }
    free(cos_t), free(sin_t), free(t_re), free(t_im), free(centred);
    return rc;
}

static int signed_frequency(int k, int n) { return k <= n / 2 ? k : k - n; }

int dither_radial_power_spectrum(const double *values, int n, double *power, gt_error *e)
{
    if (n < 2 || n > 1024)
        return gt_error_set(e, "power spectrum", "size %d outside [2, 1024]", n);
    size_t count = (size_t)n * (size_t)n;
    double *re = malloc(count * sizeof(double)), *im = malloc(count * sizeof(double));
    long ring_count[513] = {0};
    int rc = re && im ? dft_2d(values, n, re, im, e) : gt_error_set(e, "power spectrum", "out of memory");
    for (int k = 0; k <= n / 2; ++k)
        power[k] = 0.0;
    for (int ky = 0; ky < n && rc == 0; ++ky)
        for (int kx = 0; kx < n; ++kx) {
            int fx = signed_frequency(kx, n), fy = signed_frequency(ky, n);
            int ring = (int)floor(sqrt((double)(fx * fx + fy * fy)) + 0.5);
            size_t i = (size_t)ky * n + kx;
            if (ring <= n / 2) {
                power[ring] += (re[i] * re[i] + im[i] * im[i]) / (double)count;
                ++ring_count[ring];
            }
        }
    for (int k = 0; k <= n / 2; ++k)
        power[k] = ring_count[k] ? power[k] / ring_count[k] : 0.0;
    free(re);
    free(im);
    return rc;
}

int dither_spectrum_peak_ratio(const double *values, int n, double *ratio, gt_error *e)
{
    if (n < 2 || n > 1024)
        return gt_error_set(e, "power spectrum", "size %d outside [2, 1024]", n);
    size_t count = (size_t)n * (size_t)n;
    double *re = malloc(count * sizeof(double)), *im = malloc(count * sizeof(double));
    int rc = re && im ? dft_2d(values, n, re, im, e) : gt_error_set(e, "power spectrum", "out of memory");
    double peak = 0.0, sum = 0.0;
    for (size_t i = 1; i < count && rc == 0; ++i) {
        double p = re[i] * re[i] + im[i] * im[i];
        peak = fmax(peak, p), sum += p;
    }
    *ratio = sum > 0.0 ? peak / (sum / (double)(count - 1)) : 0.0;
    free(re);
    free(im);
    return rc;
}

int dither_binned_init(dither_binned_moments *b, int bin_count, double lo, double hi, gt_error *e)
{
    b->bin_count = bin_count;
    b->lo = lo;
    b->hi = hi;
    b->sum = calloc((size_t)bin_count, sizeof(double));
    b->sum_sq = calloc((size_t)bin_count, sizeof(double));
    b->count = calloc((size_t)bin_count, sizeof(long));
    if (b->sum && b->sum_sq && b->count)
        return 0;
    dither_binned_free(b);
    return gt_error_set(e, "binned moments", "out of memory");
}

void dither_binned_free(dither_binned_moments *b)
{
    free(b->sum), free(b->sum_sq), free(b->count);
    b->sum = b->sum_sq = NULL;
    b->count = NULL;
}

void dither_binned_add(dither_binned_moments *b, double coordinate, double error)
{
    int i = (int)floor((coordinate - b->lo) / (b->hi - b->lo) * b->bin_count);
    if (i < 0 || i >= b->bin_count)
        return;
    b->sum[i] += error;
    b->sum_sq[i] += error * error;
    ++b->count[i];
}

double dither_binned_mean(const dither_binned_moments *b, int i) { return b->count[i] ? b->sum[i] / b->count[i] : 0.0; }

double dither_binned_variance(const dither_binned_moments *b, int i)
{
    if (!b->count[i])
        return 0.0;
    double m = dither_binned_mean(b, i);
    return b->sum_sq[i] / b->count[i] - m * m;
}
