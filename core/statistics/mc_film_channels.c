/* The EXR channel form of a film (core/statistics/mc_film.h): the means and standard
 * errors people read, and the accumulators a film is rebuilt from exactly
 * (grid sums, moment sums, counts), with the header attributes that go with
 * them. */
#include "core/statistics/mc_film.h"
#include "core/reference_schema.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static size_t pixel_count(const mc_film *film) { return (size_t)film->width * (size_t)film->height; }

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

/* "<quantity>.<suffix>" into name. */
static void suffixed_name(char name[2 * IMAGE_NAME_MAX], const char *quantity, const char *suffix)
{
    snprintf(name, 2 * IMAGE_NAME_MAX, "%.63s.%.63s", quantity, suffix);
}

/* Known sums and counts stay below 2^62 in magnitude (core/statistics/mc_film.h): a
 * float of one converts back to an int64_t without overflow. */
#define EXACT_LIMIT 0x1p62

/* An integer v (|v| < 2^62) as three floats, hi + lo + lo2 = v exactly, hi
 * the nearest float to v: each takes the next 24 bits of what is left. An
 * unknown grid sum is NaN, 0, 0. */
static void split_exact(int64_t v, float part[3])
{
    if (v == MC_GRID_SUM_UNKNOWN) {
        part[0] = NAN, part[1] = part[2] = 0.0f;
        return;
    }
    part[0] = (float)v;
    int64_t rest = v - (int64_t)part[0];
    part[1] = (float)rest;
    part[2] = (float)(rest - (int64_t)part[1]);
}

/* Writes units[0 .. np) times `scale` (a power of two, so exact) as the
 * channels hi_name and lo_name, and lo_name + CH_SUFFIX_THIRD_PART when
 * some pixel needs a third float. */
static int write_exact(image *img, const char *hi_name, const char *lo_name, const int64_t *units, size_t np,
                       double scale)
{
    float *hi = image_add_channel(img, hi_name), *lo = image_add_channel(img, lo_name);
    if (!hi || !lo)
        return -1;
    int needs_third = 0;
    for (size_t p = 0; p < np; ++p) {
        float part[3];
        split_exact(units[p], part);
        hi[p] = (float)(part[0] * scale), lo[p] = (float)(part[1] * scale);
        needs_third |= part[2] != 0.0f;
    }
    if (!needs_third)
        return 0;
    char name[2 * IMAGE_NAME_MAX + 4];
    snprintf(name, sizeof name, "%s%s", lo_name, CH_SUFFIX_THIRD_PART);
    float *third = image_add_channel(img, name);
    if (!third)
        return -1;
    for (size_t p = 0; p < np; ++p) {
        float part[3];
        split_exact(units[p], part);
        third[p] = (float)(part[2] * scale);
    }
    return 0;
}

static int write_suffixed_exact(image *img, const char *quantity, const char *hi_suffix, const char *lo_suffix,
                                const int64_t *units, size_t np, double scale)
{
    char hi_name[2 * IMAGE_NAME_MAX], lo_name[2 * IMAGE_NAME_MAX];
    suffixed_name(hi_name, quantity, hi_suffix);
    suffixed_name(lo_name, quantity, lo_suffix);
    return write_exact(img, hi_name, lo_name, units, np, scale);
}

/* "<quantity>.m<moment>_<limb>[lo]": limb `limb` of the sum of samples
 * (moment 1) or of their squares (moment 2), its hi or lo part. */
static void limb_suffix(int moment, int limb, int lo, char suffix[16])
{
    snprintf(suffix, 16, CH_SUFFIX_LIMB_FMT, moment, limb, lo ? CH_SUFFIX_LIMB_LO : "");
}

static int64_t limb_of(const moment_sums *m, int moment, int limb)
{
    return moment == 1 ? m->sum[limb] : m->sum_sq[limb];
}

/* Quantity q's moment sums: "Q.peak" and every limb, exactly (write_exact).
 * `units` is scratch space for np values. */
static int write_moments(const mc_film *film, int q, image *img, int64_t *units)
{
    size_t np = pixel_count(film);
    const moment_sums *m = &film->moments[(size_t)q * np];
    float *peak = add_suffixed(img, film->quantities[q].name, CH_SUFFIX_PEAK);
    if (!peak)
        return -1;
    for (size_t p = 0; p < np; ++p)
        peak[p] = (float)m[p].peak; /* a float's magnitude */
    for (int moment = 1; moment <= 2; ++moment)
        for (int k = 0; k < MOMENT_LIMBS; ++k) {
            char hi_suffix[16], lo_suffix[16];
            limb_suffix(moment, k, 0, hi_suffix);
            limb_suffix(moment, k, 1, lo_suffix);
            for (size_t p = 0; p < np; ++p)
                units[p] = limb_of(&m[p], moment, k);
            if (write_suffixed_exact(img, film->quantities[q].name, hi_suffix, lo_suffix, units, np, 1.0) != 0)
                return -1;
        }
    return 0;
}

/* Quantity q's channels: mean, standard error, grid sums, moment sums. */
static int write_quantity(const mc_film *film, int q, image *img, int64_t *units)
{
    size_t np = pixel_count(film);
    const char *name = film->quantities[q].name;
    const int64_t *sum = &film->sum[(size_t)q * np], *sum_even = &film->sum_even[(size_t)q * np];
    float *mean = image_add_channel(img, name);
    float *err = add_suffixed(img, name, CH_SUFFIX_STDERR);
    double step = film->grids[q].step;
    if (!mean || !err ||
        write_suffixed_exact(img, name, CH_SUFFIX_SUM, CH_SUFFIX_SUM_LO, sum, np, step) != 0 ||
        write_suffixed_exact(img, name, CH_SUFFIX_SUMEVEN, CH_SUFFIX_SUMEVEN_LO, sum_even, np, step) != 0 ||
        write_moments(film, q, img, units) != 0)
        return -1;
    for (size_t p = 0; p < np; ++p) {
        int background = film->count[p] == 0;
        mean[p] = background ? 0.0f : (float)mc_film_mean(film, q, (int)p);
        err[p] = background ? 0.0f : (float)mc_film_stderr(film, q, (int)p);
    }
    return 0;
}

static int write_counts(const mc_film *film, image *img, int64_t *units)
{
    size_t np = pixel_count(film);
    for (size_t p = 0; p < np; ++p)
        units[p] = (int64_t)film->count[p];
    if (write_exact(img, CH_SPP, CH_SPP_LO, units, np, 1.0) != 0)
        return -1;
    for (size_t p = 0; p < np; ++p)
        units[p] = (int64_t)film->count_even[p];
    return write_exact(img, CH_SPP_EVEN, CH_SPP_EVEN_LO, units, np, 1.0);
}

int mc_film_write_channels(const mc_film *film, image *img)
{
    int64_t *units = malloc(sizeof *units * pixel_count(film));
    int rc = units ? 0 : -1;
    for (int q = 0; q < film->quantity_count && rc == 0; ++q)
        rc = write_quantity(film, q, img, units);
    rc = rc == 0 ? write_counts(film, img, units) : -1;
    free(units);
    if (rc != 0)
        return -1;
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
            double n_even = (double)film->count_even[p], n_odd = (double)film->count[p] - n_even;
            double sum = mc_grid_sum_value(film->sum[i], &film->grids[q]);
            double sum_even = mc_grid_sum_value(film->sum_even[i], &film->grids[q]);
            double n = half == 0 ? n_even : n_odd;
            mean[p] = n > 0 ? (float)((half == 0 ? sum_even : sum - sum_even) / n) : 0.0f;
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

/* A count as hi + lo (lo absent in files written before: hi alone, exact to
 * 2^24): a whole number in [0, MC_FILM_MAX_COUNT], or -1. */
static double count_of(const float *hi, const float *lo, size_t p)
{
    double n = (double)hi[p] + (lo ? (double)lo[p] : 0.0);
    int whole = n >= 0.0 && n <= MC_FILM_MAX_COUNT && n == floor(n) && (lo || hi[p] <= 16777216.0f);
    return whole ? n : -1.0;
}

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

/* The quantities: the channels that have a "Q.sum" accumulator. Returns
 * their number, or -1 with e set. */
static int find_quantities(const image *img, const char *what, mc_quantity quantities[MC_FILM_MAX_QUANTITIES],
                           gt_error *e)
{
    static const char suffix[] = "." CH_SUFFIX_SUM;
    const size_t suffix_len = sizeof suffix - 1;
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
    return count;
}

/* A part of an exact sum in units (part * inverse_scale): a whole number
 * below 2^62, or -1. */
static int part_units(float part, double inverse_scale, int64_t *units)
{
    double u = (double)part * inverse_scale;
    if (!(u == floor(u) && fabs(u) < EXACT_LIMIT))
        return -1;
    *units = (int64_t)u;
    return 0;
}

/* The sum hi + lo + lo2 of a pixel in units, as written by write_exact: a
 * whole number below 2^62, MC_GRID_SUM_UNKNOWN for a NaN hi when
 * allow_unknown (whatever the other parts), or -1. */
static int exact_units(const float *const part[3], size_t p, double inverse_scale, int allow_unknown,
                       int64_t *units)
{
    if (allow_unknown && isnan(part[0][p])) {
        *units = MC_GRID_SUM_UNKNOWN;
        return 0;
    }
    int64_t u[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
        if (part[k] && part_units(part[k][p], inverse_scale, &u[k]) != 0)
            return -1;
    int64_t total = u[0] + u[1] + u[2]; /* each below 2^62: no overflow */
    if (total <= -(int64_t)EXACT_LIMIT || total >= (int64_t)EXACT_LIMIT)
        return -1;
    *units = total;
    return 0;
}

/* Reads "Q.<hi_suffix>", "Q.<lo_suffix>" and, if present, its third part
 * into units[0 .. np): whole numbers of 1 / inverse_scale, or the file is
 * corrupt. */
static int read_exact(const image *img, const char *what, const char *quantity, const char *hi_suffix,
                      const char *lo_suffix, double inverse_scale, int allow_unknown, int64_t *units, size_t np,
                      gt_error *e)
{
    const float *part[3] = {required_channel(img, quantity, hi_suffix, what, e), NULL, NULL};
    part[1] = part[0] ? required_channel(img, quantity, lo_suffix, what, e) : NULL;
    if (!part[1])
        return -1;
    char third[2 * IMAGE_NAME_MAX + 4];
    snprintf(third, sizeof third, "%.63s.%.63s%s", quantity, lo_suffix, CH_SUFFIX_THIRD_PART);
    part[2] = image_channel_data(img, third);
    for (size_t p = 0; p < np; ++p)
        if (exact_units(part, p, inverse_scale, allow_unknown, &units[p]) != 0)
            return gt_error_set(e, what, "channel %s.%s at pixel %zu is not a whole number of units below 2^62",
                                quantity, hi_suffix, p);
    return 0;
}

static int read_grid_sums(const image *img, const char *what, mc_film *film, int q, gt_error *e)
{
    size_t np = pixel_count(film);
    const char *qn = film->quantities[q].name;
    double inverse_step = film->grids[q].inverse_step;
    return read_exact(img, what, qn, CH_SUFFIX_SUM, CH_SUFFIX_SUM_LO, inverse_step, 1, &film->sum[(size_t)q * np],
                      np, e) |
           read_exact(img, what, qn, CH_SUFFIX_SUMEVEN, CH_SUFFIX_SUMEVEN_LO, inverse_step, 1,
                      &film->sum_even[(size_t)q * np], np, e);
}

/* Limb k of moment `moment` of quantity q, exact (read_exact), and within
 * what the pixel's samples can sum: each adds a digit within 2^23. */
static int read_limb(const image *img, const char *what, mc_film *film, int q, int moment, int k, int64_t *units,
                     gt_error *e)
{
    char hi_suffix[16], lo_suffix[16];
    limb_suffix(moment, k, 0, hi_suffix);
    limb_suffix(moment, k, 1, lo_suffix);
    const char *qn = film->quantities[q].name;
    size_t np = pixel_count(film);
    if (read_exact(img, what, qn, hi_suffix, lo_suffix, 1.0, 0, units, np, e) != 0)
        return -1;
    for (size_t p = 0; p < np; ++p) {
        if ((double)llabs(units[p]) > 0x1p23 * (double)film->count[p])
            return gt_error_set(e, what, "channel %s.%s at pixel %zu holds more than %.0f samples can sum", qn,
                                hi_suffix, p, (double)film->count[p]);
        moment_sums *m = &film->moments[(size_t)q * np + p];
        *(moment == 1 ? &m->sum[k] : &m->sum_sq[k]) = units[p];
    }
    return 0;
}

static int read_moments(const image *img, const char *what, mc_film *film, int q, gt_error *e)
{
    const float *peak = required_channel(img, film->quantities[q].name, CH_SUFFIX_PEAK, what, e);
    if (!peak)
        return -1;
    size_t np = pixel_count(film);
    for (size_t p = 0; p < np; ++p) {
        if (peak[p] < 0.0f)
            return gt_error_set(e, what, "channel %s.%s is negative at pixel %zu", film->quantities[q].name,
                                CH_SUFFIX_PEAK, p);
        film->moments[(size_t)q * np + p].peak = peak[p];
    }
    int64_t *units = malloc(sizeof *units * np);
    int rc = units ? 0 : gt_error_set(e, what, "out of memory");
    for (int moment = 1; moment <= 2 && rc == 0; ++moment)
        for (int k = 0; k < MOMENT_LIMBS && rc == 0; ++k)
            rc = read_limb(img, what, film, q, moment, k, units, e);
    free(units);
    return rc;
}

/* A file written before issue 23: squares summed on the grid ("Q.sumsq"),
 * no moment sums. */
static int is_legacy(const image *img, const char *quantity)
{
    char name[2 * IMAGE_NAME_MAX];
    snprintf(name, sizeof name, "%.63s.%.63s", quantity, CH_SUFFIX_PEAK);
    if (image_channel_data(img, name))
        return 0;
    snprintf(name, sizeof name, "%.63s.%.63s", quantity, CH_SUFFIX_SUMSQ_LEGACY);
    return image_channel_data(img, name) != NULL;
}

static int read_counts(const image *img, const char *what, mc_film *film, gt_error *e)
{
    const float *n = image_channel_data(img, CH_SPP), *n_even = image_channel_data(img, CH_SPP_EVEN);
    if (!n || !n_even)
        return gt_error_set(e, what, "channels %s and %s are missing", CH_SPP, CH_SPP_EVEN);
    const float *n_lo = image_channel_data(img, CH_SPP_LO), *n_even_lo = image_channel_data(img, CH_SPP_EVEN_LO);
    if (!n_lo != !n_even_lo)
        return gt_error_set(e, what, "one of the channels %s and %s is missing", CH_SPP_LO, CH_SPP_EVEN_LO);
    for (size_t p = 0; p < pixel_count(film); ++p) {
        double count = count_of(n, n_lo, p), even = count_of(n_even, n_even_lo, p);
        if (count < 0.0 || even < 0.0 || even > count)
            return gt_error_set(e, what, "invalid sample counts in %s / %s at pixel %zu", CH_SPP, CH_SPP_EVEN, p);
        film->count[p] = (uint64_t)count;
        film->count_even[p] = (uint64_t)even;
    }
    return 0;
}

static void read_normalized(const image *img, mc_film *film)
{
    const char *layers = image_get_attribute(img, ATTR_NORMALIZED);
    if (!layers)
        return;
    char copy[MC_FILM_MAX_NORMALIZED * IMAGE_NAME_MAX];
    snprintf(copy, sizeof copy, "%s", layers);
    for (char *tok = strtok(copy, " "); tok; tok = strtok(NULL, " "))
        mc_film_normalize_layer(film, tok);
}

static int read_accumulators(const image *img, const char *what, mc_film *film, gt_error *e)
{
    film->has_moments = !is_legacy(img, film->quantities[0].name);
    if (read_counts(img, what, film, e) != 0)
        return -1;
    for (int q = 0; q < film->quantity_count; ++q) {
        if (read_grid_sums(img, what, film, q, e) != 0)
            return -1;
        if (film->has_moments && read_moments(img, what, film, q, e) != 0)
            return -1;
    }
    return 0;
}

int mc_film_read_channels(const image *img, const char *what, mc_film *film, gt_error *e)
{
    mc_quantity quantities[MC_FILM_MAX_QUANTITIES];
    int count = find_quantities(img, what, quantities, e);
    if (count < 0 || read_exponents(img, what, quantities, count, e) != 0)
        return -1;
    if (!image_channel_data(img, CH_SPP) || !image_channel_data(img, CH_SPP_EVEN))
        return gt_error_set(e, what, "channels %s and %s are missing", CH_SPP, CH_SPP_EVEN);
    if (mc_film_init(film, img->width, img->height, quantities, count) != 0)
        return gt_error_set(e, what, "out of memory");
    if (read_accumulators(img, what, film, e) != 0) {
        mc_film_free(film);
        return -1;
    }
    read_normalized(img, film);
    return 0;
}
