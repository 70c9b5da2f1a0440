/* The colour bar of a heatmap (core/files/image_io.h, image_write_heatmap): the
 * heatmap PNG records its colour map and range in its ImageDescription
 * ("gtlab heatmap: inferno, 0 to 0.25"), and the report draws the bar
 * beside it in HTML: the map's colours as a CSS gradient between the
 * range's two ends, so every heatmap carries its numeric scale without
 * changing a pixel of it. */
#ifndef GTLAB_REPORT_HEATMAP_COLOUR_BAR_H
#define GTLAB_REPORT_HEATMAP_COLOUR_BAR_H

#include <stddef.h>

/* The bar's HTML for the heatmap at png_path: 1 when the file is a gtlab
 * heatmap (html written), 0 when it is not or cannot be read. */
int heatmap_colour_bar(const char *png_path, char *html, size_t size);

#endif
