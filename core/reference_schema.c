#include "core/reference_schema.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

int schema_channel_suffixed(const char *quantity, const char *suffix, char name[IMAGE_NAME_MAX])
{
    int n = snprintf(name, IMAGE_NAME_MAX, "%s.%s", quantity, suffix);
    return n > 0 && n < IMAGE_NAME_MAX ? 0 : -1;
}

const float *schema_stderr_data(const image *img, const char *quantity)
{
    char name[IMAGE_NAME_MAX];
    return schema_channel_suffixed(quantity, CH_SUFFIX_STDERR, name) == 0 ? image_channel_data(img, name) : NULL;
}

int schema_set_int(image *img, const char *key, long value)
{
    char text[32];
    snprintf(text, sizeof text, "%ld", value);
    return image_set_attribute(img, key, text);
}

int schema_set_real(image *img, const char *key, double value)
{
    char text[32];
    snprintf(text, sizeof text, "%.9g", value);
    return image_set_attribute(img, key, text);
}

int schema_get_int(const image *img, const char *key, const char *what, long *value, gt_error *e)
{
    const char *text = image_get_attribute(img, key);
    if (!text)
        return 0;
    char *end;
    errno = 0;
    long v = strtol(text, &end, 10);
    gt_quoted q;
    if (end == text || *end != '\0' || errno != 0)
        return gt_error_set(e, what, "header attribute %s is not an integer: '%s'", key, gt_quote(text, &q));
    *value = v;
    return 1;
}

int schema_get_real(const image *img, const char *key, const char *what, double *value, gt_error *e)
{
    const char *text = image_get_attribute(img, key);
    if (!text)
        return 0;
    char *end;
    double v = strtod(text, &end);
    gt_quoted q;
    if (end == text || *end != '\0' || !isfinite(v))
        return gt_error_set(e, what, "header attribute %s is not a finite number: '%s'", key, gt_quote(text, &q));
    *value = v;
    return 1;
}
