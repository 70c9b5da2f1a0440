#include "core/mc_film.h"
#include "core/reference_schema.h"

#include <math.h>
#include <stdio.h>
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
    film->sum = calloc(n, sizeof(double));
    film->sum_sq = calloc(n, sizeof(double));
    film->sum_even = calloc(n, sizeof(double));
    film->count = calloc(pixel_count(film), sizeof(uint32_t));
    film->count_even = calloc(pixel_count(film), sizeof(uint32_t));
    if (!film->quantities || !film->sum || !film->sum_sq || !film->sum_even || !film->count || !film->count_even) {
        mc_film_free(film);
        return -1;
    }
    memcpy(film->quantities, quantities, sizeof *quantities * (size_t)quantity_count);
    for (int q = 0; q < quantity_count; ++q) {
        int exponent = quantities[q].scale_exponent;
        film->grids[q].step = ldexp(1.0, exponent - 24);
        film->grids[q].inverse_step = ldexp(1.0, 24 - exponent);
        film->grids[q].square_step = ldexp(1.0, 2 * exponent - 24);
        film->grids[q].inverse_square_step = ldexp(1.0, 24 - 2 * exponent);
    }
    return 0;
}

void mc_film_free(mc_film *film)
{
    free(film->quantities);
    free(film->sum);
    free(film->sum_sq);
    free(film->sum_even);
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

/* v rounded to the nearest multiple of the grid spacing `step` = 2^k, given
 * inverse_step = 2^-k. Multiplying by powers of two is exact, and rint rounds
 * to the nearest integer (ties to even). */
static double round_to_grid(double v, double step, double inverse_step) { return rint(v * inverse_step) * step; }

void mc_pixel_clear(mc_pixel *acc, const mc_film *film)
{
    size_t n = sizeof(double) * (size_t)film->quantity_count;
    memset(acc->sum, 0, n);
    memset(acc->sum_sq, 0, n);
    memset(acc->sum_even, 0, n);
    acc->count = acc->count_even = 0;
}

void mc_pixel_add_sample(mc_pixel *acc, const mc_film *film, uint32_t sample_index, const float *values)
{
    mc_pixel_add_samples(acc, film, sample_index, 1, values, 1);
}

/* The largest |v| of a run, as the largest magnitude bit pattern: integer
 * comparisons vectorise, and a NaN compares above infinity, so it sends the
 * run to the slow path. */
static float largest_magnitude(const float *restrict column, int count)
{
    uint32_t largest = 0;
    for (int k = 0; k < count; ++k) {
        uint32_t bits;
        memcpy(&bits, &column[k], sizeof bits);
        bits &= 0x7fffffffu;
        largest = bits > largest ? bits : largest;
    }
    float value;
    memcpy(&value, &largest, sizeof value);
    return value;
}

/* The sums of one quantity over a run of samples (sum, sum of squares, sum
 * of the even-indexed samples; the run's first sample is even iff
 * first_even). Every value is rounded onto the grid (exact IEEE arithmetic),
 * so the sums are exact whatever the order or the split into runs. In the
 * usual case (|v| < 2^25 grid steps) they are kept as integers in grid
 * units, which lets the compiler vectorise them (AVX2 where the CPU has
 * it); otherwise as doubles, scalar. Both give the same bits. */
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target_clones("avx2", "default")))
#endif
static void sum_run(const float *restrict column, int count, int first_even, const mc_grid *g, double sums[3])
{
    const int odd_parity = first_even ? 1 : 0; /* k & 1 of the odd-indexed samples */
    if ((double)largest_magnitude(column, count) * g->inverse_step < 0x1p25) {
        /* (x + magic) - magic rounds x to an integer, ties to even, as rint,
         * for |x| < 2^51. n < 2^25 grid steps, so n^2 < 2^50 is exact, and
         * the square in square-grid units is n^2 * 2^-24 rounded, < 2^26. */
        const double magic = 0x1.8p52;
        int64_t sum = 0, sum_sq = 0, sum_even = 0;
        for (int k = 0; k < count; ++k) {
            double n = ((double)column[k] * g->inverse_step + magic) - magic;
            int32_t square = (int32_t)((n * n * 0x1p-24 + magic) - magic);
            sum += (int32_t)n;
            sum_sq += square;
            sum_even += (k & 1) == odd_parity ? 0 : (int32_t)n;
        }
        sums[0] = (double)sum * g->step;
        sums[1] = (double)sum_sq * g->square_step;
        sums[2] = (double)sum_even * g->step;
        return;
    }
    sums[0] = sums[1] = sums[2] = 0.0;
    for (int k = 0; k < count; ++k) {
        double v = round_to_grid(column[k], g->step, g->inverse_step);
        sums[0] += v;
        sums[1] += round_to_grid(v * v, g->square_step, g->inverse_square_step);
        sums[2] += (k & 1) == odd_parity ? 0.0 : v;
    }
}

void mc_pixel_add_samples(mc_pixel *acc, const mc_film *film, uint32_t first_index, int count, const float *values,
                          int stride)
{
    int first_even = (first_index & 1u) == 0;
    for (int q = 0; q < film->quantity_count; ++q) {
        double sums[3];
        sum_run(&values[q * stride], count, first_even, &film->grids[q], sums);
        acc->sum[q] += sums[0];
        acc->sum_sq[q] += sums[1];
        acc->sum_even[q] += sums[2];
    }
    acc->count += (uint32_t)count;
    acc->count_even += (uint32_t)(first_even ? count + 1 : count) / 2;
}

/* sqrt(s^2 / n) with the unbiased sample variance s^2 from the sums. */
static double standard_error(double sum, double sum_sq, double n)
{
    if (n < 2)
        return INFINITY;
    double variance = (sum_sq - sum * sum / n) / (n - 1);
    return sqrt(fmax(variance, 0.0) / n);
}

double mc_pixel_stderr(const mc_pixel *acc, int quantity)
{
    return standard_error(acc->sum[quantity], acc->sum_sq[quantity], acc->count);
}

void mc_film_add_pixel(mc_film *film, int pixel, const mc_pixel *acc)
{
    size_t np = pixel_count(film);
    for (int q = 0; q < film->quantity_count; ++q) {
        size_t i = (size_t)q * np + (size_t)pixel;
        film->sum[i] += acc->sum[q];
        film->sum_sq[i] += acc->sum_sq[q];
        film->sum_even[i] += acc->sum_even[q];
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
    uint32_t n = film->count[pixel];
    return n ? film->sum[(size_t)quantity * pixel_count(film) + (size_t)pixel] / n : 0.0;
}

double mc_film_stderr(const mc_film *film, int quantity, int pixel)
{
    size_t i = (size_t)quantity * pixel_count(film) + (size_t)pixel;
    return standard_error(film->sum[i], film->sum_sq[i], film->count[pixel]);
}

/* Index of quantity "layer.axis", or -1. */
static int find_quantity(const mc_film *film, const char *layer, const char *axis)
{
    char name[2 * IMAGE_NAME_MAX];
    snprintf(name, sizeof name, "%.63s.%.63s", layer, axis);
    for (int q = 0; q < film->quantity_count; ++q)
        if (strcmp(film->quantities[q].name, name) == 0)
            return q;
    return -1;
}

/* Channel "<quantity>.<suffix>" of img, created. */
static float *add_suffixed(image *img, const char *quantity, const char *suffix)
{
    char name[2 * IMAGE_NAME_MAX];
    snprintf(name, sizeof name, "%.63s.%.63s", quantity, suffix);
    return image_add_channel(img, name);
}

/* Normalises the named vector layers in place: a mean vector m becomes
 * m / |m|, and its per-axis standard errors are divided by |m| (first-order
 * propagation, ignoring the projection onto the tangent plane). */
static void normalize_layers(const mc_film *film, image *img, int with_stderr)
{
    static const char *const axes[3] = {"X", "Y", "Z"};
    for (int l = 0; l < film->normalized_count; ++l) {
        float *mean[3] = {0}, *err[3] = {0};
        for (int a = 0; a < 3; ++a) {
            int q = find_quantity(film, film->normalized[l], axes[a]);
            if (q < 0)
                return;
            mean[a] = image_channel_data(img, film->quantities[q].name);
            if (with_stderr)
                err[a] = add_suffixed(img, film->quantities[q].name, CH_SUFFIX_STDERR);
        }
        for (size_t p = 0; p < pixel_count(film); ++p) {
            double len = sqrt((double)mean[0][p] * mean[0][p] + (double)mean[1][p] * mean[1][p] +
                              (double)mean[2][p] * mean[2][p]);
            if (len <= 0.0)
                continue;
            for (int a = 0; a < 3; ++a) {
                mean[a][p] = (float)(mean[a][p] / len);
                if (err[a] && isfinite(err[a][p]))
                    err[a][p] = (float)(err[a][p] / len);
            }
        }
    }
}

static void split_hi_lo(double v, float *hi, float *lo)
{
    *hi = (float)v;
    *lo = (float)(v - (double)*hi);
}

int mc_film_write_channels(const mc_film *film, const float *mask, image *img)
{
    size_t np = pixel_count(film);
    for (int q = 0; q < film->quantity_count; ++q) {
        const char *name = film->quantities[q].name;
        float *mean = image_add_channel(img, name);
        float *err = add_suffixed(img, name, CH_SUFFIX_STDERR);
        float *s = add_suffixed(img, name, CH_SUFFIX_SUM), *s_lo = add_suffixed(img, name, CH_SUFFIX_SUM_LO);
        float *ss = add_suffixed(img, name, CH_SUFFIX_SUMSQ), *ss_lo = add_suffixed(img, name, CH_SUFFIX_SUMSQ_LO);
        float *se = add_suffixed(img, name, CH_SUFFIX_SUMEVEN), *se_lo = add_suffixed(img, name, CH_SUFFIX_SUMEVEN_LO);
        if (!mean || !err || !s || !s_lo || !ss || !ss_lo || !se || !se_lo)
            return -1;
        for (size_t p = 0; p < np; ++p) {
            size_t i = (size_t)q * np + p;
            int background = mask && mask[p] == 0.0f;
            mean[p] = background ? 0.0f : (float)mc_film_mean(film, q, (int)p);
            err[p] = background ? 0.0f : (float)mc_film_stderr(film, q, (int)p);
            split_hi_lo(film->sum[i], &s[p], &s_lo[p]);
            split_hi_lo(film->sum_sq[i], &ss[p], &ss_lo[p]);
            split_hi_lo(film->sum_even[i], &se[p], &se_lo[p]);
        }
    }
    float *n = image_add_channel(img, CH_SPP), *n_even = image_add_channel(img, CH_SPP_EVEN);
    if (!n || !n_even)
        return -1;
    for (size_t p = 0; p < np; ++p) {
        n[p] = (float)film->count[p];
        n_even[p] = (float)film->count_even[p];
    }
    normalize_layers(film, img, 1);
    char layers[MC_FILM_MAX_NORMALIZED * IMAGE_NAME_MAX] = "";
    for (int l = 0; l < film->normalized_count; ++l) {
        if (l)
            strcat(layers, " ");
        strcat(layers, film->normalized[l]);
    }
    char exponents[MC_FILM_MAX_QUANTITIES * (IMAGE_NAME_MAX + 8)] = "";
    size_t len = 0;
    for (int q = 0; q < film->quantity_count; ++q)
        len += (size_t)snprintf(exponents + len, sizeof exponents - len, "%s%s:%d", q ? " " : "",
                                film->quantities[q].name, film->quantities[q].scale_exponent);
    return image_set_attribute(img, ATTR_NORMALIZED, layers) |
           image_set_attribute(img, ATTR_EXPONENTS, exponents);
}

int mc_film_write_half_means(const mc_film *film, int half, image *img)
{
    size_t np = pixel_count(film);
    for (int q = 0; q < film->quantity_count; ++q) {
        float *mean = image_add_channel(img, film->quantities[q].name);
        if (!mean)
            return -1;
        for (size_t p = 0; p < np; ++p) {
            size_t i = (size_t)q * np + p;
            double n_even = film->count_even[p], n_odd = (double)film->count[p] - n_even;
            double sum_odd = film->sum[i] - film->sum_even[i];
            double n = half == 0 ? n_even : n_odd;
            mean[p] = n > 0 ? (float)((half == 0 ? film->sum_even[i] : sum_odd) / n) : 0.0f;
        }
    }
    normalize_layers(film, img, 0);
    return 0;
}

static const float *required_channel(const image *img, const char *quantity, const char *suffix, const char *what,
                                     gt_error *e)
{
    char name[2 * IMAGE_NAME_MAX];
    snprintf(name, sizeof name, "%.63s.%.63s", quantity, suffix);
    const float *data = image_channel_data(img, name);
    if (!data)
        gt_error_set(e, what, "channel %s is missing (not a gtlab reference render?)", name);
    return data;
}

/* A count the file can hold exactly: a whole number in [0, 2^24]. */
static int valid_count(float n) { return n >= 0.0f && n <= 16777216.0f && n == floorf(n); }

/* The exponent E of "name:E" at text: an optional sign and digits, ended by
 * a space or the end, within [-64, 64]. Returns 0, or -1 (no overflow: at
 * most three digits are read). */
static int exponent_at(const char *text, int *out)
{
    const int negative = *text == '-';
    const char *p = text + (negative || *text == '+');
    int v = 0, digits = 0;
    for (; *p >= '0' && *p <= '9' && digits < 3; ++p, ++digits)
        v = 10 * v + (*p - '0');
    if (digits == 0 || (*p != ' ' && *p != '\0') || v > 64)
        return -1;
    *out = negative ? -v : v;
    return 0;
}

/* Restores each quantity's scale exponent from the header ("name:E ..."). */
static int read_exponents(const image *img, const char *what, mc_quantity *quantities, int count, gt_error *e)
{
    const char *text = image_get_attribute(img, ATTR_EXPONENTS);
    if (!text)
        return gt_error_set(e, what, "header attribute %s is missing", ATTR_EXPONENTS);
    for (int q = 0; q < count; ++q) {
        size_t len = strlen(quantities[q].name);
        const char *at = text;
        int found = 0;
        while ((at = strstr(at, quantities[q].name)) != NULL) {
            int starts_token = at == text || at[-1] == ' ';
            if (starts_token && at[len] == ':' && exponent_at(at + len + 1, &quantities[q].scale_exponent) == 0) {
                found = 1;
                break;
            }
            at += len;
        }
        if (!found || quantities[q].scale_exponent < -64 || quantities[q].scale_exponent > 64)
            return gt_error_set(e, what, "no valid scale exponent for %s in %s", quantities[q].name,
                                ATTR_EXPONENTS);
    }
    return 0;
}

int mc_film_read_channels(const image *img, const char *what, mc_film *film, gt_error *e)
{
    /* The quantities are the channels that have a "Q.sum" accumulator. */
    static const char suffix[] = "." CH_SUFFIX_SUM;
    const size_t suffix_len = sizeof suffix - 1;
    mc_quantity quantities[MC_FILM_MAX_QUANTITIES];
    int count = 0;
    for (int c = 0; c < img->channel_count; ++c) {
        const char *name = img->channels[c].name;
        size_t len = strlen(name);
        if (len > suffix_len && strcmp(name + len - suffix_len, suffix) == 0) {
            if (count == MC_FILM_MAX_QUANTITIES)
                return gt_error_set(e, what, "more than %d Monte Carlo quantities", MC_FILM_MAX_QUANTITIES);
            memset(&quantities[count], 0, sizeof quantities[count]);
            memcpy(quantities[count].name, name, len - suffix_len);
            count++;
        }
    }
    if (count == 0)
        return gt_error_set(e, what, "no Monte Carlo accumulator channels (*.sum): not a gtlab reference render");
    if (read_exponents(img, what, quantities, count, e) != 0)
        return -1;
    const float *n = image_channel_data(img, CH_SPP), *n_even = image_channel_data(img, CH_SPP_EVEN);
    if (!n || !n_even)
        return gt_error_set(e, what, "channels spp.N and spp.Neven are missing");
    if (mc_film_init(film, img->width, img->height, quantities, count) != 0)
        return gt_error_set(e, what, "out of memory");
    size_t np = pixel_count(film);
    for (int q = 0; q < count; ++q) {
        const char *qn = quantities[q].name;
        const float *s = required_channel(img, qn, CH_SUFFIX_SUM, what, e), *s_lo = required_channel(img, qn, CH_SUFFIX_SUM_LO, what, e);
        const float *ss = required_channel(img, qn, CH_SUFFIX_SUMSQ, what, e);
        const float *ss_lo = required_channel(img, qn, CH_SUFFIX_SUMSQ_LO, what, e);
        const float *se = required_channel(img, qn, CH_SUFFIX_SUMEVEN, what, e);
        const float *se_lo = required_channel(img, qn, CH_SUFFIX_SUMEVEN_LO, what, e);
        if (!s || !s_lo || !ss || !ss_lo || !se || !se_lo) {
            mc_film_free(film);
            return -1;
        }
        for (size_t p = 0; p < np; ++p) {
            size_t i = (size_t)q * np + p;
            film->sum[i] = (double)s[p] + (double)s_lo[p];
            film->sum_sq[i] = (double)ss[p] + (double)ss_lo[p];
            film->sum_even[i] = (double)se[p] + (double)se_lo[p];
        }
    }
    for (size_t p = 0; p < np; ++p) {
        if (!valid_count(n[p]) || !valid_count(n_even[p]) || n_even[p] > n[p]) {
            mc_film_free(film);
            return gt_error_set(e, what, "invalid sample counts in spp.N / spp.Neven at pixel %zu", p);
        }
        film->count[p] = (uint32_t)n[p];
        film->count_even[p] = (uint32_t)n_even[p];
    }
    const char *layers = image_get_attribute(img, ATTR_NORMALIZED);
    if (layers) {
        char copy[MC_FILM_MAX_NORMALIZED * IMAGE_NAME_MAX];
        snprintf(copy, sizeof copy, "%s", layers);
        for (char *tok = strtok(copy, " "); tok; tok = strtok(NULL, " "))
            mc_film_normalize_layer(film, tok);
    }
    return 0;
}

int mc_film_merge(mc_film *dst, const mc_film *src, const char *what, gt_error *e)
{
    if (dst->width != src->width || dst->height != src->height)
        return gt_error_set(e, what, "size %dx%d differs from %dx%d", src->width, src->height, dst->width,
                            dst->height);
    if (dst->quantity_count != src->quantity_count)
        return gt_error_set(e, what, "holds different quantities");
    for (int q = 0; q < dst->quantity_count; ++q) {
        if (strcmp(dst->quantities[q].name, src->quantities[q].name) != 0)
            return gt_error_set(e, what, "holds different quantities (%s vs %s)", src->quantities[q].name,
                                dst->quantities[q].name);
        /* Sums on different grids would no longer be exact. */
        if (dst->quantities[q].scale_exponent != src->quantities[q].scale_exponent)
            return gt_error_set(e, what, "%s was accumulated on another grid (scale exponent %d vs %d)",
                                src->quantities[q].name, src->quantities[q].scale_exponent,
                                dst->quantities[q].scale_exponent);
    }
    size_t n = pixel_count(dst) * (size_t)dst->quantity_count;
    for (size_t i = 0; i < n; ++i) {
        dst->sum[i] += src->sum[i];
        dst->sum_sq[i] += src->sum_sq[i];
        dst->sum_even[i] += src->sum_even[i];
    }
    for (size_t p = 0; p < pixel_count(dst); ++p) {
        dst->count[p] += src->count[p];
        dst->count_even[p] += src->count_even[p];
    }
    return 0;
}
