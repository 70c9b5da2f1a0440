/* Perceptual colour difference of display colours: CIEDE2000 (Sharma, Wu
 * and Dalal 2005) between two sRGB-encoded colours, through Little CMS 2
 * (Debian liblcms2): sRGB (IEC 61966-2-1) to CIELAB under D50 (the ICC
 * connection space, relative colorimetric intent), then cmsCIE2000DeltaE
 * with kL = kC = kH = 1. A difference below 1 is about the smallest a viewer
 * notices side by side. */
#ifndef GTLAB_METRICS_COLOR_DIFFERENCE_H
#define GTLAB_METRICS_COLOR_DIFFERENCE_H

#include <stddef.h>

#include "core/error.h"

typedef struct color_difference color_difference;

/* NULL with e if Little CMS cannot build the transform. */
color_difference *color_difference_create(gt_error *e);
void color_difference_free(color_difference *cd);

/* delta[i] = CIEDE2000 between the sRGB colours a[3i..3i+2] and b[3i..3i+2]
 * (values in [0, 1]) for i < count. Thread-safe for one `cd`. */
void color_difference_ciede2000(const color_difference *cd, const double *a, const double *b, size_t count,
                                double *delta);

#endif
