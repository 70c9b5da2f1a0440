/* SSIM and DSSIM (Wang et al. 2004) and the noise floor of a reference; see
 * ssim.h for the definition followed and how masks are handled.
 *
 * The Gaussian window is separable, w(i, j) = g[i] g[j], so each output row
 * takes 11-tap vertical sums of the five products a, b, a^2, b^2, ab for every
 * column, then 11-tap horizontal sums of those: 110 multiply-adds per centre
 * instead of 605. Rows are independent and each is summed in a fixed order,
 * so any number of OpenMP threads gives the same bits. */
#include "metrics/ssim.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/statistics/mc_film.h"
#include "metrics/image_error.h"

void ssim_gaussian_weights(double g[SSIM_WINDOW])
{
    double sum = 0.0;
    for (int k = 0; k < SSIM_WINDOW; ++k) {
        double d = k - SSIM_RADIUS;
        g[k] = exp(-d * d / (2.0 * SSIM_SIGMA * SSIM_SIGMA));
        sum += g[k];
    }
    for (int k = 0; k < SSIM_WINDOW; ++k)
        g[k] /= sum;
}

/* The weighted moments of one window: E[a], E[b], E[a^2], E[b^2], E[ab]. */
enum { MOMENT_A, MOMENT_B, MOMENT_AA, MOMENT_BB, MOMENT_AB, MOMENT_COUNT };

/* SSIM of one window from its moments, with the population variances
 * sigma^2 = E[x^2] - mu^2 (the weights sum to 1). Every operation is
 * symmetric in a and b, and a == b makes numerator and denominator the same
 * bits, so identical images give exactly 1 and swapping images the same value. */
static double ssim_from_moments(const double m[MOMENT_COUNT])
{
    const double c1 = (SSIM_K1 * SSIM_DYNAMIC_RANGE) * (SSIM_K1 * SSIM_DYNAMIC_RANGE);
    const double c2 = (SSIM_K2 * SSIM_DYNAMIC_RANGE) * (SSIM_K2 * SSIM_DYNAMIC_RANGE);
    double mu_a = m[MOMENT_A], mu_b = m[MOMENT_B];
    double var_a = m[MOMENT_AA] - mu_a * mu_a;
    double var_b = m[MOMENT_BB] - mu_b * mu_b;
    double cov = m[MOMENT_AB] - mu_a * mu_b;
    return (2.0 * mu_a * mu_b + c1) * (2.0 * cov + c2) / ((mu_a * mu_a + mu_b * mu_b + c1) * (var_a + var_b + c2));
}

/* SSIM at the valid centres of row y into row_ssim[SSIM_RADIUS .. width -
 * SSIM_RADIUS - 1]. columns: scratch of MOMENT_COUNT * width doubles. */
static void ssim_row(const float *a, const float *b, int width, int y, const double g[SSIM_WINDOW], double *columns,
                     double *row_ssim)
{
    double *col[MOMENT_COUNT];
    for (int q = 0; q < MOMENT_COUNT; ++q)
        col[q] = columns + (size_t)q * (size_t)width;
    memset(columns, 0, sizeof *columns * MOMENT_COUNT * (size_t)width);
    for (int k = 0; k < SSIM_WINDOW; ++k) {
        size_t row = (size_t)(y - SSIM_RADIUS + k) * (size_t)width;
        const float *ra = a + row, *rb = b + row;
        double w = g[k];
        for (int x = 0; x < width; ++x) {
            double va = ra[x], vb = rb[x];
            col[MOMENT_A][x] += w * va;
            col[MOMENT_B][x] += w * vb;
            col[MOMENT_AA][x] += w * (va * va);
            col[MOMENT_BB][x] += w * (vb * vb);
            col[MOMENT_AB][x] += w * (va * vb);
        }
    }
    for (int x = SSIM_RADIUS; x < width - SSIM_RADIUS; ++x) {
        double m[MOMENT_COUNT] = {0};
        for (int j = 0; j < SSIM_WINDOW; ++j) {
            int i = x - SSIM_RADIUS + j;
            for (int q = 0; q < MOMENT_COUNT; ++q)
                m[q] += g[j] * col[q][i];
        }
        row_ssim[x] = ssim_from_moments(m);
    }
}

int ssim_compute(const float *a, const float *b, const float *mask, int width, int height, const char *what,
                 float *map, ssim_result *out, gt_error *e)
{
    if (width < SSIM_WINDOW || height < SSIM_WINDOW)
        return gt_error_set(e, what, "image is %dx%d, smaller than the %dx%d SSIM window", width, height,
                            SSIM_WINDOW, SSIM_WINDOW);
    double g[SSIM_WINDOW];
    ssim_gaussian_weights(g);
    int rows = height - 2 * SSIM_RADIUS;
    double *row_sum = calloc((size_t)rows, sizeof *row_sum);
    size_t *row_count = calloc((size_t)rows, sizeof *row_count);
    if (!row_sum || !row_count) {
        free(row_sum);
        free(row_count);
        return gt_error_set(e, what, "out of memory");
    }
    if (map)
        for (size_t i = 0; i < (size_t)width * (size_t)height; ++i)
            map[i] = NAN;

    int failed = 0;
#pragma omp parallel
    {
        double *scratch = malloc(sizeof *scratch * (MOMENT_COUNT + 1) * (size_t)width);
#pragma omp for schedule(dynamic, 4)
        for (int r = 0; r < rows; ++r) {
            if (!scratch) {
#pragma omp atomic write
                failed = 1;
                continue;
            }
            int y = r + SSIM_RADIUS;
            double *row_ssim = scratch + MOMENT_COUNT * (size_t)width;
            ssim_row(a, b, width, y, g, scratch, row_ssim);
            double sum = 0.0;
            size_t count = 0;
            for (int x = SSIM_RADIUS; x < width - SSIM_RADIUS; ++x) {
                size_t i = (size_t)y * (size_t)width + (size_t)x;
                if (map)
                    map[i] = (float)row_ssim[x];
                if (metrics_in_mask(mask, i)) {
                    sum += row_ssim[x];
                    count++;
                }
            }
            row_sum[r] = sum;
            row_count[r] = count;
        }
        free(scratch);
    }

    /* Rows are added in order, whatever thread computed them. */
    double sum = 0.0;
    size_t count = 0;
    for (int r = 0; r < rows; ++r) {
        sum += row_sum[r];
        count += row_count[r];
    }
    free(row_sum);
    free(row_count);
    if (failed)
        return gt_error_set(e, what, "out of memory");
    if (count == 0)
        return gt_error_set(e, what,
                            "no SSIM window centre inside the mask (centres must lie %d pixels inside the image "
                            "border)",
                            SSIM_RADIUS);
    out->ssim = sum / (double)count;
    out->dssim = (1.0 - out->ssim) / 2.0;
    out->centres = count;
    return 0;
}

static int find_quantity(const mc_film *film, const char *name)
{
    for (int q = 0; q < film->quantity_count; ++q)
        if (strcmp(film->quantities[q].name, name) == 0)
            return q;
    return -1;
}

/* Both halves of the samples must be non-empty wherever SSIM is averaged. */
static int check_halves(const mc_film *film, const float *mask, const char *what, gt_error *e)
{
    for (int y = 0; y < film->height; ++y) {
        for (int x = 0; x < film->width; ++x) {
            size_t p = (size_t)y * (size_t)film->width + (size_t)x;
            uint32_t n = film->count[p], n_even = film->count_even[p];
            if (metrics_in_mask(mask, p) && (n_even == 0 || n - n_even == 0))
                return gt_error_set(e, what,
                                    "pixel (%d, %d) has %u sample(s): the noise floor needs samples in both halves "
                                    "(even and odd sample indices)",
                                    x, y, n);
        }
    }
    return 0;
}

int ssim_noise_floor(const image *reference, const char *what, const char *channel, const float *mask,
                     ssim_result *out, gt_error *e)
{
    mc_film film;
    if (mc_film_read_channels(reference, what, &film, e) != 0)
        return -1;
    if (find_quantity(&film, channel) < 0) {
        mc_film_free(&film);
        return gt_error_set(e, what, "channel %s is not one of this reference's Monte Carlo quantities", channel);
    }
    if (check_halves(&film, mask, what, e) != 0) {
        mc_film_free(&film);
        return -1;
    }
    image halves[2];
    const float *planes[2] = {NULL, NULL};
    int status = 0;
    for (int h = 0; h < 2; ++h) {
        float *plane = NULL;
        if (image_init(&halves[h], film.width, film.height) == 0 && mc_film_write_half_means(&film, h, &halves[h]) == 0)
            plane = image_channel_data(&halves[h], channel);
        if (!plane) {
            status = gt_error_set(e, what, "out of memory");
            continue;
        }
        /* As in the written mean channel (mc_film_write_channels), background holds 0. */
        for (size_t p = 0; p < image_pixel_count(&halves[h]); ++p)
            if (!metrics_in_mask(mask, p))
                plane[p] = 0.0f;
        planes[h] = plane;
    }
    if (status == 0)
        status = ssim_compute(planes[0], planes[1], mask, film.width, film.height, what, NULL, out, e);
    image_free(&halves[0]);
    image_free(&halves[1]);
    mc_film_free(&film);
    return status;
}
