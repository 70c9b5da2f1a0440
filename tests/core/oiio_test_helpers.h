/* C-callable OpenImageIO helpers for the core tests: a reader and writer
 * independent of gtlab's own I/O (OIIO reads and writes EXR through the
 * OpenEXR C++ library), so files can be checked by a second implementation
 * and files of kinds gtlab never writes (tiled, HALF, UINT, offset windows)
 * can be made. */
#ifndef GTLAB_TESTS_CORE_OIIO_TEST_HELPERS_H
#define GTLAB_TESTS_CORE_OIIO_TEST_HELPERS_H

#define OIIO_TEST_MAX_CHANNELS 16

typedef struct {
    int width, height, channels;              /* data window size */
    int x, y;                                 /* data window origin */
    int full_x, full_y, full_width, full_height; /* display window */
    int tile_width;                           /* 0: scanline file */
    char format[16];                          /* pixel type in the file: "uint8", "half", "float", "uint" */
    char compression[32];
    char channel_names[OIIO_TEST_MAX_CHANNELS][64];
    float *pixels; /* width * height * channels, interleaved, malloc'd */
} oiio_test_image;

/* Reads the first subimage as float (8-bit values come back as v / 255).
 * Returns 0, or -1 with a message on stderr. */
int oiio_test_read(const char *path, oiio_test_image *img);

/* Writes an EXR with OIIO: pixel_type "half", "float" or "uint" (pixels are
 * then converted by value, not rescaled), tiled when tile_size > 0, with the
 * windows and channel names of img, and one string and one int attribute
 * ("test.string" = string_value, "test.int" = 7). Returns 0 or -1. */
int oiio_test_write_exr(const char *path, const oiio_test_image *img, const char *pixel_type, int tile_size,
                        const char *string_value);

/* OIIO's colour map `map` (ImageBufAlgo::color_map) at x, on a 1-pixel image:
 * the linear RGB colour. Returns 0 or -1. */
int oiio_test_color_map(const char *map, float x, float rgb[3]);

void oiio_test_image_free(oiio_test_image *img);

#endif
