#include "metrics/reference_halves.h"

#include "core/statistics/mc_film.h"
#include "core/reference_schema.h"

/* Zeroes every channel of `half` where the mask is 0 (none without a mask). */
static void clear_background(image *half, const float *mask)
{
    if (!mask)
        return;
    for (int c = 0; c < half->channel_count; ++c)
        for (size_t i = 0; i < image_pixel_count(half); ++i)
            if (mask[i] == 0.0f)
                half->channels[c].data[i] = 0.0f;
}

int reference_halves_split(const image *img, const char *what, image halves[2], gt_error *e)
{
    mc_film film;
    if (mc_film_read_channels(img, what, &film, e) != 0)
        return -1;
    const float *mask = image_channel_data(img, CH_MASK);
    int rc = 0, made = 0;
    for (int h = 0; h < 2 && rc == 0; ++h) {
        if (image_init(&halves[h], img->width, img->height) != 0) {
            rc = gt_error_set(e, what, "out of memory");
            break;
        }
        ++made;
        if (mc_film_write_half_means(&film, h, &halves[h]) != 0)
            rc = gt_error_set(e, what, "out of memory");
        else
            clear_background(&halves[h], mask);
    }
    mc_film_free(&film);
    if (rc != 0)
        for (int h = 0; h < made; ++h)
            image_free(&halves[h]);
    return rc;
}
