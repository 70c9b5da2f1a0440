#include "core/image.h"

#include <stdlib.h>
#include <string.h>

int image_init(image *img, int width, int height)
{
    memset(img, 0, sizeof *img);
    if (width <= 0 || height <= 0)
        return -1;
    img->width = width;
    img->height = height;
    return 0;
}

void image_free(image *img)
{
    for (int c = 0; c < img->channel_count; ++c)
        free(img->channels[c].data);
    free(img->channels);
    for (int a = 0; a < img->attribute_count; ++a) {
        free(img->attributes[a].key);
        free(img->attributes[a].value);
    }
    free(img->attributes);
    memset(img, 0, sizeof *img);
}

const image_channel *image_find_channel(const image *img, const char *name)
{
    for (int c = 0; c < img->channel_count; ++c)
        if (strcmp(img->channels[c].name, name) == 0)
            return &img->channels[c];
    return NULL;
}

float *image_channel_data(const image *img, const char *name)
{
    const image_channel *ch = image_find_channel(img, name);
    return ch ? ch->data : NULL;
}

float *image_add_channel(image *img, const char *name)
{
    float *existing = image_channel_data(img, name);
    if (existing)
        return existing;
    if (strlen(name) >= IMAGE_NAME_MAX)
        return NULL;
    image_channel *grown = realloc(img->channels, sizeof *grown * (size_t)(img->channel_count + 1));
    if (!grown)
        return NULL;
    img->channels = grown;
    float *data = calloc(image_pixel_count(img), sizeof *data);
    if (!data)
        return NULL;
    image_channel *ch = &img->channels[img->channel_count++];
    strcpy(ch->name, name);
    ch->data = data;
    return data;
}

static char *duplicate_string(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d)
        memcpy(d, s, n);
    return d;
}

int image_set_attribute(image *img, const char *key, const char *value)
{
    char *v = duplicate_string(value);
    if (!v)
        return -1;
    for (int a = 0; a < img->attribute_count; ++a) {
        if (strcmp(img->attributes[a].key, key) == 0) {
            free(img->attributes[a].value);
            img->attributes[a].value = v;
            return 0;
        }
    }
    image_attribute *grown = realloc(img->attributes, sizeof *grown * (size_t)(img->attribute_count + 1));
    char *k = duplicate_string(key);
    if (!grown || !k) {
        free(v);
        free(k);
        if (grown)
            img->attributes = grown;
        return -1;
    }
    img->attributes = grown;
    img->attributes[img->attribute_count].key = k;
    img->attributes[img->attribute_count].value = v;
    img->attribute_count++;
    return 0;
}

const char *image_get_attribute(const image *img, const char *key)
{
    for (int a = 0; a < img->attribute_count; ++a)
        if (strcmp(img->attributes[a].key, key) == 0)
            return img->attributes[a].value;
    return NULL;
}
