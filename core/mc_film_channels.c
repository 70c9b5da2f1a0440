/* The EXR channel form of a film (core/mc_film.h): the means and standard
 * errors people read, and the accumulators a film is rebuilt from exactly
 * (grid sums, moment sums, counts), with the header attributes that go with
 * them. */
#include "core/mc_film.h"
#include "core/reference_schema.h"

#include <math.h>
#include <stdio.h>
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

/* v as hi + lo floats: exact for an integer below 2^48 (hi keeps 24 bits,
 * the rest is an integer below 2^23). */
static void split_hi_lo(double v, float *hi, float *lo)
{
    *hi = (float)v;
    *lo = (float)(v - (double)*hi);
}

/* "<quantity>.m<moment>_<limb>[lo]": limb `limb` of the sum of samples
 * (moment 1) or of their squares (moment 2), its hi or lo part. */
static void limb_suffix(int moment, int limb, int lo, char suffix[16])
{
    snprintf(suffix, 16, CH_SUFFIX_LIMB_FMT, moment, limb, lo ? CH_SUFFIX_LIMB_LO : "");
}

static double limb_of(const moment_sums *m, int moment, int limb)
{
    return moment == 1 ? m->sum[limb] : m->sum_sq[limb];
}

/* Quantity q's moment sums: "Q.peak" and every limb as hi + lo (a limb is an
 * integer within 2^47 for up to 2^24 samples, so the pair is exact). */
static int write_moments(const mc_film *film, int q, image *img)
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
            float *hi = add_suffixed(img, film->quantities[q].name, hi_suffix);
            float *lo = add_suffixed(img, film->quantities[q].name, lo_suffix);
            if (!hi || !lo)
                return -1;
            for (size_t p = 0; p < np; ++p)
                split_hi_lo(limb_of(&m[p], moment, k), &hi[p], &lo[p]);
        }
    return 0;
}

int mc_film_write_channels(const mc_film *film, const float *mask, image *img)
{
    size_t np = pixel_count(film);
    for (int q = 0; q < film->quantity_count; ++q) {
        const char *name = film->quantities[q].name;
        float *mean = image_add_channel(img, name);
        float *err = add_suffixed(img, name, CH_SUFFIX_STDERR);
        float *s = add_suffixed(img, name, CH_SUFFIX_SUM), *s_lo = add_suffixed(img, name, CH_SUFFIX_SUM_LO);
        float *se = add_suffixed(img, name, CH_SUFFIX_SUMEVEN), *se_lo = add_suffixed(img, name, CH_SUFFIX_SUMEVEN_LO);
        if (!mean || !err || !s || !s_lo || !se || !se_lo || write_moments(film, q, img) != 0)
            return -1;
        for (size_t p = 0; p < np; ++p) {
            size_t i = (size_t)q * np + p;
            int background = mask && mask[p] == 0.0f;
            mean[p] = background ? 0.0f : (float)mc_film_mean(film, q, (int)p);
            err[p] = background ? 0.0f : (float)mc_film_stderr(film, q, (int)p);
            split_hi_lo(film->sum[i], &s[p], &s_lo[p]);
            split_hi_lo(film->sum_even[i], &se[p], &se_lo[p]);
        }
    }
    float *n = image_add_channel(img, CH_SPP), *n_even = image_add_channel(img, CH_SPP_EVEN);
    float *n_lo = image_add_channel(img, CH_SPP_LO), *n_even_lo = image_add_channel(img, CH_SPP_EVEN_LO);
    if (!n || !n_even || !n_lo || !n_even_lo)
        return -1;
    for (size_t p = 0; p < np; ++p) {
        split_hi_lo((double)film->count[p], &n[p], &n_lo[p]);
        split_hi_lo((double)film->count_even[p], &n_even[p], &n_even_lo[p]);
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

static int read_grid_sums(const image *img, const char *what, mc_film *film, int q, gt_error *e)
{
    const char *qn = film->quantities[q].name;
    const float *s = required_channel(img, qn, CH_SUFFIX_SUM, what, e);
    const float *s_lo = s ? required_channel(img, qn, CH_SUFFIX_SUM_LO, what, e) : NULL;
    const float *se = s_lo ? required_channel(img, qn, CH_SUFFIX_SUMEVEN, what, e) : NULL;
    const float *se_lo = se ? required_channel(img, qn, CH_SUFFIX_SUMEVEN_LO, what, e) : NULL;
    if (!se_lo)
        return -1;
    size_t np = pixel_count(film);
    for (size_t p = 0; p < np; ++p) {
        film->sum[(size_t)q * np + p] = (double)s[p] + (double)s_lo[p];
        film->sum_even[(size_t)q * np + p] = (double)se[p] + (double)se_lo[p];
    }
    return 0;
}

/* Limb k of moment `moment` of quantity q, from its hi + lo channels: whole
 * numbers, or the file is corrupt. */
static int read_limb(const image *img, const char *what, mc_film *film, int q, int moment, int k, gt_error *e)
{
    char hi_suffix[16], lo_suffix[16];
    limb_suffix(moment, k, 0, hi_suffix);
    limb_suffix(moment, k, 1, lo_suffix);
    const char *qn = film->quantities[q].name;
    const float *hi = required_channel(img, qn, hi_suffix, what, e);
    const float *lo = hi ? required_channel(img, qn, lo_suffix, what, e) : NULL;
    if (!lo)
        return -1;
    size_t np = pixel_count(film);
    for (size_t p = 0; p < np; ++p) {
        double limb = (double)hi[p] + (double)lo[p];
        if (!(limb == floor(limb) && fabs(limb) < 0x1p53))
            return gt_error_set(e, what, "channel %s.%s at pixel %zu is not a whole number", qn, hi_suffix, p);
        moment_sums *m = &film->moments[(size_t)q * np + p];
        *(moment == 1 ? &m->sum[k] : &m->sum_sq[k]) = limb;
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
    for (int moment = 1; moment <= 2; ++moment)
        for (int k = 0; k < MOMENT_LIMBS; ++k)
            if (read_limb(img, what, film, q, moment, k, e) != 0)
                return -1;
    return 0;
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
        film->count[p] = (uint32_t)count;
        film->count_even[p] = (uint32_t)even;
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
    for (int q = 0; q < film->quantity_count; ++q) {
        if (read_grid_sums(img, what, film, q, e) != 0)
            return -1;
        if (film->has_moments && read_moments(img, what, film, q, e) != 0)
            return -1;
    }
    return read_counts(img, what, film, e);
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
