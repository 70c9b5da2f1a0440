/* 8-bit previews and error heatmaps through OpenImageIO (a C++ adapter behind
 * this C header). Any format OIIO can write to memory is accepted (png,
 * tif, exr, jpg, bmp, tga, hdr, webp, ...; not fits, heif, ico, rla, sgi,
 * zfile); the path's extension chooses it (.png is what gtlab itself
 * writes). Written atomically: encoded in memory, then written with every
 * write and the close checked, so a full disk is an error naming the file
 * and leaves nothing under its name. Also
 * the one float reader of pictures gtlab does not write (HDR environments:
 * EXR of any compression OpenEXR's C++ library decodes, DWAB included,
 * Radiance .hdr, ...). */
#ifndef GTLAB_CORE_FILES_IMAGE_IO_H
#define GTLAB_CORE_FILES_IMAGE_IO_H

#include <stddef.h>

#include "core/error.h"

/* A preview of 1 (grey) or 3 (RGB) planar float channels holding linear values:
 * each value is multiplied by `exposure`, clamped to [0, 1] and encoded as sRGB.
 * planes[c] points at width*height floats. Returns 0 or -1 with e. */
int image_write_preview(const char *path, const float *const *planes, int channel_count, int width, int height,
                        float exposure, gt_error *e);

/* A heatmap of `values` through OIIO's colour map `map_name` ("inferno",
 * "viridis", "magma", "plasma", "turbo"), with values mapped linearly from
 * [0, vmax] to [0, 1] and clamped. Pixels where mask is non-NULL and mask[i]
 * is 0 are written black. The file's ImageDescription records its scale,
 * "gtlab heatmap: <map_name>, 0 to <vmax as %g>", for a colour bar
 * (report/heatmap_colour_bar.h). Returns 0 or -1 with e. */
int image_write_heatmap(const char *path, const float *values, const float *mask, int width, int height,
                        float vmax, const char *map_name, gt_error *e);

/* The same heatmap with a colour bar below it: image_heatmap_bar_rows(height)
 * black rows, then as many rows of the map's ramp from 0 (left) to vmax
 * (right column); the file is height + 2 image_heatmap_bar_rows(height) rows
 * high and its ImageDescription states the bar's range. Returns 0 or -1. */
int image_write_heatmap_with_bar(const char *path, const float *values, const float *mask, int width, int height,
                                 float vmax, const char *map_name, gt_error *e);
int image_heatmap_bar_rows(int height); /* max(4, height / 16) */

/* The colours a heatmap gives `count` (>= 2) evenly spaced values from 0 to
 * vmax: map_name's colours at k / (count - 1), sRGB-encoded to 8 bits as in
 * the heatmap's file (rgb[3 k + c]). Returns 0, or -1 for an unknown map. */
int image_colour_map_srgb(const char *map_name, int count, unsigned char *rgb);

/* A file's ImageDescription (its header only read) into text; 0, or -1
 * when the file cannot be read or has none. */
int image_read_description(const char *path, char *text, size_t size);

/* Data (not a picture): one channel of values in [0, 1] quantised linearly
 * to 8 bits (no sRGB encoding), as a LUT a shader samples; `description`
 * (may be NULL) goes to the file's ImageDescription metadata (a PNG tEXt
 * chunk). Returns 0 or -1 with e. */
int image_write_data8(const char *path, const float *values, int width, int height, const char *description,
                      gt_error *e);

/* Data of 1 to 4 planar channels in [0, 1] quantised linearly to 16 bits
 * (no sRGB encoding), e.g. a two-channel LUT as RG with blue 0; planes[c]
 * points at width*height floats, a NULL plane writes zeros. Returns 0 or -1. */
int image_write_data16(const char *path, const float *const *planes, int channel_count, int width, int height,
                       const char *description, gt_error *e);

/* The first subimage of any file OIIO reads as linear float RGB, interleaved
 * (rgb[3 (y width + x) + c], row y = 0 at the top; malloc'd, the caller
 * frees it): channels R, G, B by name, else the first three, and a single
 * channel repeated three times. No colour conversion (the values are taken
 * as stored; HDR formats store linear values). *floating_point says whether
 * the file stores floating-point texels (half, float, double: what HDR
 * formats hold) rather than 8- or 16-bit integers (display-referred
 * images). Returns 0, or -1 with e naming the file (missing, unreadable, no
 * channels, more than 2^28 pixels or 2^30 values, out of memory). */
int image_read_rgb_float(const char *path, int *width, int *height, float **rgb, int *floating_point, gt_error *e);

#endif
