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
