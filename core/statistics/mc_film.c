#include "core/statistics/mc_film.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static size_t pixel_count(const mc_film *film) { return (size_t)film->width * (size_t)film->height; }

int mc_film_init(mc_film *film, int width, int height, const mc_quantity *quantities, int quantity_count)
{
    memset(film, 0, sizeof *film);
    if (quantity_count < 1 || quantity_count > MC_FILM_MAX_QUANTITIES)
        return -1;
    film->width = width;
    film->height = height;
    film->quantity_count = quantity_count;
    size_t n = pixel_count(film) * (size_t)quantity_count;
    film->quantities = malloc(sizeof *quantities * (size_t)quantity_count);
    film->sum = calloc(n, sizeof(int64_t));
    film->sum_even = calloc(n, sizeof(int64_t));
    film->moments = calloc(n, sizeof(moment_sums)); /* all zero: cleared sums */
    film->count = calloc(pixel_count(film), sizeof(uint64_t));
    film->count_even = calloc(pixel_count(film), sizeof(uint64_t));
    film->has_moments = 1;
    if (!film->quantities || !film->sum || !film->sum_even || !film->moments || !film->count || !film->count_even) {
        mc_film_free(film);
        return -1;
    }
    memcpy(film->quantities, quantities, sizeof *quantities * (size_t)quantity_count);
    for (int q = 0; q < quantity_count; ++q) {
        int exponent = quantities[q].scale_exponent;
        film->grids[q].step = ldexp(1.0, exponent - 24);
        film->grids[q].inverse_step = ldexp(1.0, 24 - exponent);
    }
    return 0;
}

void mc_film_free(mc_film *film)
{
    free(film->quantities);
    free(film->sum);
    free(film->sum_even);
    free(film->moments);
    free(film->count);
    free(film->count_even);
    memset(film, 0, sizeof *film);
}

int mc_film_normalize_layer(mc_film *film, const char *layer)
{
    if (film->normalized_count >= MC_FILM_MAX_NORMALIZED || strlen(layer) >= IMAGE_NAME_MAX)
        return -1;
    strcpy(film->normalized[film->normalized_count++], layer);
    return 0;
}

int64_t mc_grid_units(double v, const mc_grid *g)
{
    double units = rint(v * g->inverse_step); /* exact: a power of two, then ties to even */
    return fabs(units) < 0x1p53 ? (int64_t)units : MC_GRID_SUM_UNKNOWN; /* a NaN fails the test */
}

int64_t mc_grid_sum_add(int64_t a, int64_t b)
{
    if (a == MC_GRID_SUM_UNKNOWN || b == MC_GRID_SUM_UNKNOWN)
        return MC_GRID_SUM_UNKNOWN;
    if ((b > 0 && a > INT64_MAX - b) || (b < 0 && a <= INT64_MIN - b))
        return MC_GRID_SUM_UNKNOWN;
    return a + b;
}

double mc_grid_sum_value(int64_t units, const mc_grid *g)
{
    return units == MC_GRID_SUM_UNKNOWN ? NAN : (double)units * g->step;
}

void mc_pixel_clear(mc_pixel *acc, const mc_film *film)
{
    size_t n = sizeof(int64_t) * (size_t)film->quantity_count;
    memset(acc->sum, 0, n);
    memset(acc->sum_even, 0, n);
    for (int q = 0; q < film->quantity_count; ++q)
        moment_sums_clear(&acc->moments[q]);
    acc->count = acc->count_even = 0;
}

void mc_pixel_add_sample(mc_pixel *acc, const mc_film *film, uint32_t sample_index, const float *values)
{
    mc_pixel_add_samples(acc, film, sample_index, 1, values, 1);
}

/* The grid sums of one quantity over a run of samples (sum, sum of the
 * even-indexed samples; the run's first sample is even iff first_even), in
 * grid units. Every value is rounded onto the grid (exact IEEE arithmetic),
 * so the sums are exact whatever the order or the split into runs. In the
 * usual case (|v| < 2^25 grid steps) the loop is plain integer sums, which
 * the compiler vectorises (AVX2 where the CPU has it); otherwise each value
 * is checked (mc_grid_units). Both give the same bits. */
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target_clones("avx2", "default")))
#endif
static void sum_run(const float *restrict column, int count, int first_even, float peak, const mc_grid *g,
                    int64_t sums[2])
{
    const int odd_parity = first_even ? 1 : 0; /* k & 1 of the odd-indexed samples */
    if ((double)peak * g->inverse_step < 0x1p25) {
        /* (x + magic) - magic rounds x to an integer, ties to even, as rint,
         * for |x| < 2^51. */
        const double magic = 0x1.8p52;
        int64_t sum = 0, sum_even = 0;
        for (int k = 0; k < count; ++k) {
            double n = ((double)column[k] * g->inverse_step + magic) - magic;
            sum += (int32_t)n;
            sum_even += (k & 1) == odd_parity ? 0 : (int32_t)n;
        }
        sums[0] = sum, sums[1] = sum_even;
        return;
    }
    sums[0] = sums[1] = 0;
    for (int k = 0; k < count; ++k) {
        int64_t units = mc_grid_units(column[k], g);
        sums[0] = mc_grid_sum_add(sums[0], units);
        sums[1] = (k & 1) == odd_parity ? sums[1] : mc_grid_sum_add(sums[1], units);
    }
}

void mc_pixel_add_samples(mc_pixel *acc, const mc_film *film, uint32_t first_index, int count, const float *values,
                          int stride)
{
    int first_even = (first_index & 1u) == 0;
    for (int q = 0; q < film->quantity_count; ++q) {
        const float *column = &values[q * stride];
        float peak = moment_sums_run_peak(column, count); /* a NaN compares above 2^25: the scalar path */
        int64_t sums[2];
        sum_run(column, count, first_even, peak, &film->grids[q], sums);
        acc->sum[q] = mc_grid_sum_add(acc->sum[q], sums[0]);
        acc->sum_even[q] = mc_grid_sum_add(acc->sum_even[q], sums[1]);
        moment_sums_add_run(&acc->moments[q], column, count, peak);
    }
    acc->count += (uint64_t)count;
    acc->count_even += (uint64_t)(first_even ? count + 1 : count) / 2;
}

/* sqrt(s^2 / n) with the unbiased sample variance s^2 of the moment sums
 * (a rounding below 0 is a variance of 0). */
static double standard_error(const moment_sums *m, uint64_t n)
{
    if (n < 2)
        return INFINITY;
    double variance = moment_sums_variance(m, n);
    return isnan(variance) ? NAN : sqrt(fmax(variance, 0.0) / (double)n);
}

double mc_pixel_stderr(const mc_pixel *acc, int quantity)
{
    return standard_error(&acc->moments[quantity], acc->count);
}

void mc_film_add_pixel(mc_film *film, int pixel, const mc_pixel *acc)
{
    size_t np = pixel_count(film);
    for (int q = 0; q < film->quantity_count; ++q) {
        size_t i = (size_t)q * np + (size_t)pixel;
        film->sum[i] = mc_grid_sum_add(film->sum[i], acc->sum[q]);
        film->sum_even[i] = mc_grid_sum_add(film->sum_even[i], acc->sum_even[q]);
        moment_sums_merge(&film->moments[i], &acc->moments[q]);
    }
    film->count[pixel] += acc->count;
    film->count_even[pixel] += acc->count_even;
}

void mc_film_add_sample(mc_film *film, int pixel, uint32_t sample_index, const float *values)
{
    mc_pixel one;
    mc_pixel_clear(&one, film);
    mc_pixel_add_sample(&one, film, sample_index, values);
    mc_film_add_pixel(film, pixel, &one);
}

double mc_film_mean(const mc_film *film, int quantity, int pixel)
{
    double n = (double)film->count[pixel];
    size_t i = (size_t)quantity * pixel_count(film) + (size_t)pixel;
    if (n == 0)
        return 0.0;
    /* Precise relative to the pixel's own peak (issue 23); the quantity's
     * grid (relative to the brightest pixel) only for a film read from a
     * file written before, or a pixel whose sums are unknown (a NaN sample
     * stays visible). */
    if (film->has_moments && isfinite(film->moments[i].peak))
        return moment_sums_total(&film->moments[i]) / n;
    return mc_grid_sum_value(film->sum[i], &film->grids[quantity]) / n;
}

double mc_film_stderr(const mc_film *film, int quantity, int pixel)
{
    if (!film->has_moments)
        return NAN;
    size_t i = (size_t)quantity * pixel_count(film) + (size_t)pixel;
    return standard_error(&film->moments[i], film->count[pixel]);
}

int mc_film_check_moments(const mc_film *film, const char *what, gt_error *e)
{
    if (film->has_moments)
        return 0;
    return gt_error_set(e, what,
                        "written by a gtlab that summed squares on the quantity's grid (before issue 23): its "
                        "standard errors are wrong on dim pixels and cannot be merged; render it again");
}

void mc_film_clear_rows(mc_film *film, int first_row, int end_row)
{
    size_t first = (size_t)first_row * (size_t)film->width, n = (size_t)(end_row - first_row) * (size_t)film->width;
    if (end_row <= first_row)
        return;
    for (int q = 0; q < film->quantity_count; ++q) {
        size_t at = (size_t)q * pixel_count(film) + first;
        memset(film->sum + at, 0, n * sizeof *film->sum);
        memset(film->sum_even + at, 0, n * sizeof *film->sum_even);
        memset(film->moments + at, 0, n * sizeof *film->moments);
    }
    memset(film->count + first, 0, n * sizeof *film->count);
    memset(film->count_even + first, 0, n * sizeof *film->count_even);
}

/* The index of the quantity named `name` in the film, or -1. */
static int quantity_named(const mc_film *film, const char *name)
{
    for (int q = 0; q < film->quantity_count; ++q)
        if (strcmp(film->quantities[q].name, name) == 0)
            return q;
    return -1;
}

/* For every quantity of dst the index of the same quantity (by name, on
 * the same grid) in src, else -1 with e. */
static int match_quantities(const mc_film *dst, const mc_film *src, int from[MC_FILM_MAX_QUANTITIES],
                            const char *what, gt_error *e)
{
    if (dst->quantity_count != src->quantity_count)
        return gt_error_set(e, what, "holds different quantities");
    for (int q = 0; q < dst->quantity_count; ++q) {
        const mc_quantity *d = &dst->quantities[q];
        if ((from[q] = quantity_named(src, d->name)) < 0)
            return gt_error_set(e, what, "holds different quantities (no %s)", d->name);
        /* Sums on different grids would no longer be exact. */
        if (d->scale_exponent != src->quantities[from[q]].scale_exponent)
            return gt_error_set(e, what, "%s was accumulated on another grid (scale exponent %d vs %d)", d->name,
                                src->quantities[from[q]].scale_exponent, d->scale_exponent);
    }
    return 0;
}

int mc_film_merge(mc_film *dst, const mc_film *src, const char *what, gt_error *e)
{
    int from[MC_FILM_MAX_QUANTITIES];
    if (mc_film_check_moments(src, what, e) != 0 || mc_film_check_moments(dst, "the first input", e) != 0)
        return -1;
    if (dst->width != src->width || dst->height != src->height)
        return gt_error_set(e, what, "size %dx%d differs from %dx%d", src->width, src->height, dst->width,
                            dst->height);
    if (match_quantities(dst, src, from, what, e) != 0)
        return -1;
    for (size_t p = 0; p < pixel_count(dst); ++p)
        if ((double)dst->count[p] + (double)src->count[p] > MC_FILM_MAX_COUNT)
            return gt_error_set(e, what,
                                "pixel %zu would hold %.0f samples, more than %.0f (2^32), the range in which "
                                "gtlab keeps its sums exact: merge fewer parts into one file",
                                p, (double)dst->count[p] + (double)src->count[p], MC_FILM_MAX_COUNT);
    for (int q = 0; q < dst->quantity_count; ++q) {
        size_t d = (size_t)q * pixel_count(dst), s = (size_t)from[q] * pixel_count(dst);
        for (size_t p = 0; p < pixel_count(dst); ++p) {
            dst->sum[d + p] = mc_grid_sum_add(dst->sum[d + p], src->sum[s + p]);
            dst->sum_even[d + p] = mc_grid_sum_add(dst->sum_even[d + p], src->sum_even[s + p]);
            moment_sums_merge(&dst->moments[d + p], &src->moments[s + p]);
        }
    }
    for (size_t p = 0; p < pixel_count(dst); ++p) {
        dst->count[p] += src->count[p];
        dst->count_even[p] += src->count_even[p];
    }
    return 0;
}
