/* The colour bar of a heatmap; see heatmap_colour_bar.h. */
#include "report/heatmap_colour_bar.h"

#include <stdio.h>

#include "core/files/image_io.h"

enum { BAR_STOPS = 17 };

/* The CSS gradient of map_name's colours at BAR_STOPS evenly spaced values
 * (sRGB-encoded as in the heatmaps); 0 on failure. */
static int gradient(const char *map_name, char *css, size_t size)
{
    unsigned char rgb[3 * BAR_STOPS];
    if (image_colour_map_srgb(map_name, BAR_STOPS, rgb) != 0)
        return 0;
    int n = snprintf(css, size, "linear-gradient(to right");
    for (int i = 0; i < BAR_STOPS && n > 0 && (size_t)n < size; ++i)
        n += snprintf(css + n, size - (size_t)n, ",#%02x%02x%02x", rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]);
    if (n > 0 && (size_t)n < size)
        n += snprintf(css + n, size - (size_t)n, ")");
    return n > 0 && (size_t)n < size;
}

int heatmap_colour_bar(const char *png_path, char *html, size_t size)
{
    char description[256], map_name[32], css[512];
    double low, high;
    if (image_read_description(png_path, description, sizeof description) != 0 ||
        sscanf(description, "gtlab heatmap: %31[^,], %lf to %lf", map_name, &low, &high) != 3 ||
        !gradient(map_name, css, sizeof css))
        return 0;
    int n = snprintf(html, size,
                     "<div class=\"cbar\" title=\"%s, linear from %g to %g, clamped\"><span>%g</span>"
                     "<span class=\"cbar-ramp\" style=\"background:%s\"></span><span>%g</span></div>",
                     map_name, low, high, low, css, high);
    return n > 0 && (size_t)n < size;
}
