/* A named-channel float image: the in-memory form of every EXR gtlab reads or
 * writes. Channels are planar (one float plane per channel) and named
 * "layer.channel" as in DESIGN.md ("ao.V", "N.X", "ao.V.stderr").
 * Pixel (x, y): x = column from the left, y = row from the top; plane index
 * y * width + x. Header attributes are strings (numbers are written as text
 * by the caller); they become EXR string attributes. */
#ifndef GTLAB_CORE_IMAGE_H
#define GTLAB_CORE_IMAGE_H

#include <stddef.h>

#define IMAGE_NAME_MAX 64

typedef struct {
    char name[IMAGE_NAME_MAX];
    float *data; /* width * height floats */
} image_channel;

typedef struct {
    char *key;
    char *value;
} image_attribute;

typedef struct {
    int width, height;
    int channel_count;
    image_channel *channels;
    int attribute_count;
    image_attribute *attributes;
} image;

/* An empty image of the given size (no channels). Returns 0, or -1 when out of memory. */
int image_init(image *img, int width, int height);
void image_free(image *img);

/* Adds a zero-filled channel, or returns the existing one of that name.
 * Returns its plane, or NULL when out of memory or the name is too long. */
float *image_add_channel(image *img, const char *name);
/* The plane of the named channel, or NULL. */
float *image_channel_data(const image *img, const char *name);
const image_channel *image_find_channel(const image *img, const char *name);

/* Header attributes: set replaces an existing key. get returns NULL if absent. */
int image_set_attribute(image *img, const char *key, const char *value);
const char *image_get_attribute(const image *img, const char *key);

static inline size_t image_pixel_count(const image *img) { return (size_t)img->width * (size_t)img->height; }

#endif
