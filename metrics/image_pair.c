/* The set-up of a comparison of two images; see image_pair.h. */
#include "metrics/image_pair.h"
#include "core/reference_schema.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const metrics_default_channels[] = {CH_AO, CH_MULTIBOUNCE, CH_SPECOCC, CH_AO_UNIFORM, NULL};

/* "name, name, ..." of a list into buf, ending in "..." where the rest would
 * not fit (one line of an error message). */
static void join_names(const char *const *names, int count, char *buf, size_t size)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < count; ++i) {
        const char *separator = i ? ", " : "";
        /* Keep room for ", ..." after every name. */
        if (used + strlen(separator) + strlen(names[i]) + sizeof ", ..." > size) {
            snprintf(buf + used, size - used, "%s...", separator);
            return;
        }
        used += (size_t)snprintf(buf + used, size - used, "%s%s", separator, names[i]);
    }
}

static void list_channels(const image *img, char *buf, size_t size)
{
    const char *names[256];
    int count = img->channel_count < 256 ? img->channel_count : 256;
    for (int c = 0; c < count; ++c)
        names[c] = img->channels[c].name;
    join_names(names, count, buf, size);
}

/* The first default channel in both images; failing that, an error on b if
 * a has a default channel b lacks, else on a. */
static int choose_default_channel(const image *a, const char *what_a, const image *b, const char *what_b,
                                  const char **channel, gt_error *e)
{
    const char *only_in_a = NULL;
    int tried = 0;
    for (; metrics_default_channels[tried]; ++tried) {
        const char *name = metrics_default_channels[tried];
        if (!image_find_channel(a, name))
            continue;
        if (image_find_channel(b, name)) {
            *channel = name;
            return 0;
        }
        if (!only_in_a)
            only_in_a = name;
    }
    char present[640];
    if (only_in_a) {
        list_channels(b, present, sizeof present);
        return gt_error_set(e, what_b, "no channel %s to compare with %s (channels: %s); name one with --channel",
                            only_in_a, what_a, present);
    }
    char defaults[256];
    join_names(metrics_default_channels, tried, defaults, sizeof defaults);
    list_channels(a, present, sizeof present);
    return gt_error_set(e, what_a, "none of the default channels (%s) is here (channels: %s); name one with "
                        "--channel", defaults, present);
}

static const float *require_channel(const image *img, const char *what, const char *channel, gt_error *e)
{
    const float *plane = image_channel_data(img, channel);
    if (!plane) {
        char present[640];
        list_channels(img, present, sizeof present);
        gt_error_set(e, what, "no channel %s (channels: %s)", channel, present);
    }
    return plane;
}

/* SSIM windows reach outside the mask, so every pixel must be finite. */
static int check_finite(const float *plane, int width, int height, const char *what, const char *channel,
                        gt_error *e)
{
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float v = plane[(size_t)y * (size_t)width + (size_t)x];
            if (!isfinite(v))
                return gt_error_set(e, what, "channel %s holds %g at pixel (%d, %d)", channel, v, x, y);
        }
    return 0;
}

int metrics_pair_init(metrics_pair *pair, const image *a, const char *what_a, const image *b, const char *what_b,
                      const char *channel, gt_error *e)
{
    memset(pair, 0, sizeof *pair);
    if (a->width != b->width || a->height != b->height)
        return gt_error_set(e, what_b, "size %dx%d differs from %s's %dx%d", b->width, b->height, what_a, a->width,
                            a->height);
    if (!channel && choose_default_channel(a, what_a, b, what_b, &channel, e) != 0)
        return -1;
    const float *pa = require_channel(a, what_a, channel, e);
    const float *pb = pa ? require_channel(b, what_b, channel, e) : NULL;
    if (!pb)
        return -1;
    if (check_finite(pa, a->width, a->height, what_a, channel, e) != 0 ||
        check_finite(pb, b->width, b->height, what_b, channel, e) != 0)
        return -1;
    size_t n = image_pixel_count(a);
    pair->mask = malloc(sizeof *pair->mask * n);
    if (!pair->mask)
        return gt_error_set(e, what_a, "out of memory");
    const float *mask_a = image_channel_data(a, CH_MASK);
    const float *mask_b = image_channel_data(b, CH_MASK);
    for (size_t i = 0; i < n; ++i)
        pair->mask[i] = metrics_in_mask(mask_a, i) && metrics_in_mask(mask_b, i) ? 1.0f : 0.0f;
    strcpy(pair->channel, channel); /* fits: it names a channel of a */
    pair->width = a->width;
    pair->height = a->height;
    pair->a = pa;
    pair->b = pb;
    return 0;
}

void metrics_pair_free(metrics_pair *pair)
{
    free(pair->mask);
    memset(pair, 0, sizeof *pair);
}

int metrics_is_reference_of(const image *img, const char *channel)
{
    char name[IMAGE_NAME_MAX];
    return schema_channel_suffixed(channel, CH_SUFFIX_SUM, name) == 0 && image_find_channel(img, name) != NULL;
}

static int measure_noise_floors(const metrics_pair *pair, const image *a, const char *what_a, const image *b,
                                const char *what_b, metrics_pair_figures *out, gt_error *e)
{
    if (ssim_noise_floor(a, what_a, pair->channel, pair->mask, &out->floor_a, e) != 0)
        return -1;
    out->has_floor_a = 1;
    if (!metrics_is_reference_of(b, pair->channel))
        return 0;
    if (ssim_noise_floor(b, what_b, pair->channel, pair->mask, &out->floor_b, e) != 0)
        return -1;
    out->has_floor_b = 1;
    return 0;
}

int metrics_pair_measure(const metrics_pair *pair, const image *a, const char *what_a, const image *b,
                         const char *what_b, int noise_floor, float *ssim_map, metrics_pair_figures *out,
                         gt_error *e)
{
    memset(out, 0, sizeof *out);
    if (image_error_compute(pair->a, pair->b, pair->mask, pair->width, pair->height, what_a, &out->error, e) != 0 ||
        ssim_compute(pair->a, pair->b, pair->mask, pair->width, pair->height, what_a, ssim_map, &out->ssim, e) != 0 ||
        flip_grey(pair->a, pair->b, pair->mask, pair->width, pair->height, what_a, NULL, &out->flip, e) != 0)
        return -1;
    return noise_floor ? measure_noise_floors(pair, a, what_a, b, what_b, out, e) : 0;
}

/* Per pixel: |A-B|, or the window's DSSIM; 0 and outside where not defined. */
static void heatmap_values(const metrics_pair *pair, const float *ssim_map, metrics_heatmap *h)
{
    size_t n = (size_t)pair->width * (size_t)pair->height;
    for (size_t i = 0; i < n; ++i) {
        int inside = pair->mask[i] != 0.0f && (!ssim_map || !isnan(ssim_map[i]));
        double v = ssim_map ? (1.0 - ssim_map[i]) / 2.0 : fabs((double)pair->a[i] - (double)pair->b[i]);
        h->values[i] = inside ? (float)v : 0.0f;
        h->mask[i] = inside ? 1.0f : 0.0f;
    }
}

/* The percentile, else the maximum, else 1 (see metrics_pair_heatmap). */
static int heatmap_scale(metrics_heatmap *h, size_t n, double percentile, const char *what, gt_error *e)
{
    h->scale = HEATMAP_SCALE_PERCENTILE;
    if (metrics_percentile(h->values, h->mask, n, percentile, what, &h->vmax, e) != 0)
        return -1;
    if (!(h->vmax > 0.0f)) {
        h->scale = HEATMAP_SCALE_MAXIMUM;
        if (metrics_percentile(h->values, h->mask, n, 100.0, what, &h->vmax, e) != 0)
            return -1;
    }
    if (!(h->vmax > 0.0f)) {
        h->scale = HEATMAP_SCALE_ARBITRARY;
        h->vmax = 1.0f;
    }
    return 0;
}

int metrics_pair_heatmap(const metrics_pair *pair, const float *ssim_map, double percentile, const char *what,
                         metrics_heatmap *out, gt_error *e)
{
    size_t n = (size_t)pair->width * (size_t)pair->height;
    memset(out, 0, sizeof *out);
    out->values = malloc(sizeof *out->values * n);
    out->mask = malloc(sizeof *out->mask * n);
    if (!out->values || !out->mask) {
        metrics_heatmap_free(out);
        return gt_error_set(e, what, "out of memory");
    }
    heatmap_values(pair, ssim_map, out);
    if (heatmap_scale(out, n, percentile, what, e) != 0) {
        metrics_heatmap_free(out);
        return -1;
    }
    return 0;
}

void metrics_heatmap_free(metrics_heatmap *h)
{
    free(h->values);
    free(h->mask);
    h->values = h->mask = NULL;
}
