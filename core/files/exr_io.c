/* EXR reading and writing through the OpenEXR C API (OpenEXRCore, 3.1).
 *
 * Writing: one scanline part, ZIP compression, every channel FLOAT, every
 * image attribute a string attribute; into a temporary file (atomic_file.h)
 * renamed into place only when OpenEXR has finished it.
 *
 * Reading: the first part, scanline or tiled (level 0 of a mipmapped file),
 * any pixel type converted to float by OpenEXR's own unpackers. The image is
 * the display window: image pixel (x, y) is EXR pixel (display.min.x + x,
 * display.min.y + y); pixels outside the data window are 0 and data outside
 * the display window is dropped. Channels come back in the EXR's (sorted)
 * order; only string attributes are loaded.
 *
 * The chunk loops follow the pipeline protocol documented in OpenEXR's
 * openexr_encode.h and openexr_decode.h: initialise (or update) a pipeline
 * per chunk, point its channels at our planes, choose the default routines,
 * run. */
#define _POSIX_C_SOURCE 200809L /* pread */
#include "core/files/exr_io.h"

#include <openexr.h>
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/files/atomic_file.h"
#include "core/files/input_file.h"

/* Largest image accepted on read, in pixels: a corrupt header must not make
 * us allocate terabytes. */
#define EXR_MAX_PIXELS ((int64_t)1 << 28)
/* ... and all its channels together, in floats (4 GiB): a header of a few
 * KB must not claim twenty channels of 2^28 pixels. The fuzz build lowers
 * it (libFuzzer's convention FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION), so
 * that inputs claiming the maximum do not spend the fuzzer's time and memory
 * on zeros; the code that checks it is the same. */
#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
#define EXR_MAX_FLOATS ((int64_t)1 << 24)
#else
#define EXR_MAX_FLOATS ((int64_t)1 << 30)
#endif

/* The most bytes of pixels one stored byte can decode to, per compression
 * (issue 41: a 3 KB header claiming 16384 x 8192 pixels made gtlab allocate
 * 1.7 GB before the first chunk failed). A file of n bytes holds at most
 * n times this of raw pixel data (its data window times each channel's
 * bytes per sample), so a header claiming more is refused before anything
 * is allocated. Each figure is an upper bound of the method's best case:
 *   NONE   1      the pixels as they are
 *   RLE    64     a run of 128 equal bytes is stored as 2 (count, value)
 *   ZIP(S) 1032   deflate's limit: a 258-byte match in at least 2 bits
 *   PIZ    410    Huffman with run codes: 256 equal 16-bit values in at
 *                 least 1 + 1 + 8 bits (code, run code, run length)
 *   PXR24  1376   floats cut to 24 bits (4/3), then deflate (1032)
 *   B44(A) 11     a flat 4x4 block of halves (32 bytes) in 3 bytes
 *   DWAA/B 66048  alpha-like channels: RLE (64), then deflate (1032)
 * A compression OpenEXR adds later gets the largest figure until it is
 * listed. The display window can be larger than the data window (its
 * pixels outside are zeros, read from nothing): it is bounded by the
 * largest figure, so no file of n bytes makes gtlab allocate more than
 * about n * 66048 * 4 / (bytes per stored pixel) bytes. */
#define EXR_MAX_EXPANSION_ANY INPUT_MAX_DECODE_RATIO
static double exr_max_expansion(exr_compression_t c)
{
    switch (c) {
    case EXR_COMPRESSION_NONE: return 1.0;
    case EXR_COMPRESSION_RLE: return 64.0;
    case EXR_COMPRESSION_ZIPS:
    case EXR_COMPRESSION_ZIP: return 1032.0;
    case EXR_COMPRESSION_PIZ: return 410.0;
    case EXR_COMPRESSION_PXR24: return 1376.0;
    case EXR_COMPRESSION_B44:
    case EXR_COMPRESSION_B44A: return 11.0;
    default: return EXR_MAX_EXPANSION_ANY;
    }
}

/* OpenEXR reports problems through a callback, whose default prints to
 * stderr; library code must not print. The callback gets no pointer of ours
 * when OpenEXR does the file I/O itself, so the first message of the current
 * call is kept per thread. */
static _Thread_local char exr_message[512];

static void keep_first_message(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    (void)ctxt;
    if (exr_message[0])
        return;
    snprintf(exr_message, sizeof exr_message, "%s", msg ? msg : exr_get_error_code_as_string(code));
    /* One printable line, even when the message quotes bytes of a corrupt
     * header. */
    for (unsigned char *c = (unsigned char *)exr_message; *c; ++c)
        if (*c < 0x20 || *c >= 0x7f)
            *c = '?';
}

static exr_context_initializer_t quiet_initializer(void)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = keep_first_message;
    /* A truncated file must be an error, not silently patched up. */
    init.flags = EXR_CONTEXT_FLAG_DISABLE_CHUNK_RECONSTRUCTION;
    return init;
}

/* "<path>: <what>: <OpenEXR's first message, or its error name>". */
static int exr_error(gt_error *e, const char *path, const char *what, exr_result_t rv)
{
    return gt_error_set(e, path, "%s: %s", what, exr_message[0] ? exr_message : exr_get_error_code_as_string(rv));
}

/* ---------------------------------------------------------------- writing */

static int needs_long_names(const image *img)
{
    for (int c = 0; c < img->channel_count; ++c)
        if (strlen(img->channels[c].name) > 31)
            return 1;
    for (int a = 0; a < img->attribute_count; ++a)
        if (strlen(img->attributes[a].key) > 31)
            return 1;
    return 0;
}

/* OpenEXR keeps the channel list sorted by name, as the file format requires,
 * whatever order the channels are added in. */
static exr_result_t define_header(exr_context_t ctxt, const image *img)
{
    int part = 0;
    exr_result_t rv = exr_add_part(ctxt, NULL, EXR_STORAGE_SCANLINE, &part);
    if (rv == EXR_ERR_SUCCESS && needs_long_names(img))
        rv = exr_set_longname_support(ctxt, 1);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_initialize_required_attr_simple(ctxt, part, img->width, img->height, EXR_COMPRESSION_ZIP);
    for (int c = 0; rv == EXR_ERR_SUCCESS && c < img->channel_count; ++c)
        rv = exr_add_channel(ctxt, part, img->channels[c].name, EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LINEAR, 1, 1);
    for (int a = 0; rv == EXR_ERR_SUCCESS && a < img->attribute_count; ++a)
        rv = exr_attr_set_string(ctxt, part, img->attributes[a].key, img->attributes[a].value);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_write_header(ctxt);
    return rv;
}

/* Points every channel of the encoder at rows [y, y + chunk height) of the
 * image plane of the same name (the encoder lists channels in file order). */
static void point_encoder_at_rows(exr_encode_pipeline_t *enc, const image *img, int y)
{
    for (int c = 0; c < enc->channel_count; ++c) {
        exr_coding_channel_info_t *ch = &enc->channels[c];
        const float *plane = image_channel_data(img, ch->channel_name);
        ch->encode_from_ptr = (const uint8_t *)(plane + (size_t)y * (size_t)img->width);
        ch->user_bytes_per_element = sizeof(float);
        ch->user_data_type = EXR_PIXEL_FLOAT;
        ch->user_pixel_stride = sizeof(float);
        ch->user_line_stride = (int32_t)sizeof(float) * img->width;
    }
}

static exr_result_t write_scanlines(exr_context_t ctxt, const image *img)
{
    int32_t lines = 0;
    exr_result_t rv = exr_get_scanlines_per_chunk(ctxt, 0, &lines);
    if (rv == EXR_ERR_SUCCESS && lines <= 0)
        rv = EXR_ERR_INVALID_ARGUMENT;
    exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
    int started = 0;
    for (int y = 0; rv == EXR_ERR_SUCCESS && y < img->height; y += lines) {
        exr_chunk_info_t cinfo;
        rv = exr_write_scanline_chunk_info(ctxt, 0, y, &cinfo);
        if (rv != EXR_ERR_SUCCESS)
            break;
        int first = !started;
        rv = first ? exr_encoding_initialize(ctxt, 0, &cinfo, &enc) : exr_encoding_update(ctxt, 0, &cinfo, &enc);
        started = 1; /* so the pipeline is destroyed even after a failed start */
        if (rv != EXR_ERR_SUCCESS)
            break;
        point_encoder_at_rows(&enc, img, y);
        if (first)
            rv = exr_encoding_choose_default_routines(ctxt, 0, &enc);
        if (rv == EXR_ERR_SUCCESS)
            rv = exr_encoding_run(ctxt, 0, &enc);
    }
    if (started)
        exr_encoding_destroy(ctxt, &enc);
    return rv;
}

int exr_write(const char *path, const image *img, gt_error *e)
{
    if (img->width <= 0 || img->height <= 0 || img->channel_count <= 0)
        return gt_error_set(e, path, "cannot write EXR: the image has no pixels or no channels");
    atomic_file out;
    if (atomic_file_begin(&out, path, e) != 0)
        return -1;
    exr_message[0] = '\0';
    exr_context_initializer_t init = quiet_initializer();
    exr_context_t ctxt = NULL;
    exr_result_t rv = exr_start_write(&ctxt, out.temp_path, EXR_WRITE_FILE_DIRECTLY, &init);
    if (rv == EXR_ERR_SUCCESS)
        rv = define_header(ctxt, img);
    if (rv == EXR_ERR_SUCCESS)
        rv = write_scanlines(ctxt, img);
    /* exr_finish writes the chunk offset table, so its result counts too. */
    exr_result_t finished = exr_finish(&ctxt);
    if (rv == EXR_ERR_SUCCESS)
        rv = finished;
    if (rv != EXR_ERR_SUCCESS) {
        atomic_file_abort(&out);
        return exr_error(e, path, "cannot write EXR", rv);
    }
    return atomic_file_commit(&out, e);
}

/* ---------------------------------------------------------------- reading */

/* Where the decoded pixels go: the image and the EXR coordinates of its
 * pixel (0, 0) (the display window's corner). */
typedef struct {
    image *img;
    int origin_x, origin_y;
    exr_decode_pipeline_t dec;
    int started;
    float *chunk; /* decoded chunk, planar: channel_count planes of width * height floats */
    size_t chunk_floats;
} exr_reader;

/* Copies the decoded chunk whose top-left pixel is (x0, y0) in EXR
 * coordinates into the image, where it overlaps it. */
static void place_chunk(exr_reader *r, int x0, int y0, int width, int height)
{
    image *img = r->img;
    int ix0 = x0 - r->origin_x, iy0 = y0 - r->origin_y;
    int first_x = ix0 < 0 ? -ix0 : 0, last_x = img->width - ix0 < width ? img->width - ix0 : width;
    int first_y = iy0 < 0 ? -iy0 : 0, last_y = img->height - iy0 < height ? img->height - iy0 : height;
    if (first_x >= last_x || first_y >= last_y)
        return;
    size_t n = (size_t)width * (size_t)height;
    for (int c = 0; c < r->dec.channel_count; ++c) {
        float *plane = image_channel_data(img, r->dec.channels[c].channel_name);
        const float *src = r->chunk + (size_t)c * n;
        for (int y = first_y; y < last_y; ++y)
            memcpy(plane + (size_t)(iy0 + y) * (size_t)img->width + (size_t)(ix0 + first_x),
                   src + (size_t)y * (size_t)width + (size_t)first_x, sizeof(float) * (size_t)(last_x - first_x));
    }
}

/* Decodes one chunk into r->chunk as float, whatever the file's pixel type
 * (OpenEXR's unpackers convert HALF and UINT). */
static exr_result_t decode_chunk(exr_const_context_t ctxt, exr_reader *r, const exr_chunk_info_t *cinfo)
{
    exr_result_t rv = r->started ? exr_decoding_update(ctxt, 0, cinfo, &r->dec)
                                 : exr_decoding_initialize(ctxt, 0, cinfo, &r->dec);
    r->started = 1; /* so the pipeline is destroyed even after a failed start */
    if (rv != EXR_ERR_SUCCESS)
        return rv;
    size_t n = (size_t)cinfo->width * (size_t)cinfo->height;
    size_t needed = n * (size_t)r->dec.channel_count;
    if (needed > r->chunk_floats) {
        float *grown = realloc(r->chunk, sizeof(float) * needed);
        if (!grown)
            return EXR_ERR_OUT_OF_MEMORY;
        r->chunk = grown;
        r->chunk_floats = needed;
    }
    for (int c = 0; c < r->dec.channel_count; ++c) {
        exr_coding_channel_info_t *ch = &r->dec.channels[c];
        ch->decode_to_ptr = (uint8_t *)(r->chunk + (size_t)c * n);
        ch->user_bytes_per_element = sizeof(float);
        ch->user_data_type = EXR_PIXEL_FLOAT;
        ch->user_pixel_stride = sizeof(float);
        ch->user_line_stride = (int32_t)sizeof(float) * cinfo->width;
    }
    rv = exr_decoding_choose_default_routines(ctxt, 0, &r->dec);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_decoding_run(ctxt, 0, &r->dec);
    return rv;
}

static exr_result_t read_scanlines(exr_const_context_t ctxt, exr_reader *r, const exr_attr_box2i_t *dw)
{
    int32_t lines = 0;
    exr_result_t rv = exr_get_scanlines_per_chunk(ctxt, 0, &lines);
    if (rv == EXR_ERR_SUCCESS && lines <= 0)
        rv = EXR_ERR_FILE_BAD_HEADER;
    for (int64_t y = dw->min.y; rv == EXR_ERR_SUCCESS && y <= dw->max.y; y += lines) {
        exr_chunk_info_t cinfo;
        rv = exr_read_scanline_chunk_info(ctxt, 0, (int)y, &cinfo);
        if (rv == EXR_ERR_SUCCESS)
            rv = decode_chunk(ctxt, r, &cinfo);
        if (rv == EXR_ERR_SUCCESS)
            place_chunk(r, dw->min.x, cinfo.start_y, cinfo.width, cinfo.height);
    }
    return rv;
}

/* Level (0, 0) of a tiled part: the full-resolution image. */
static exr_result_t read_tiles(exr_const_context_t ctxt, exr_reader *r, const exr_attr_box2i_t *dw)
{
    int32_t tile_w = 0, tile_h = 0, level_w = 0, level_h = 0;
    exr_result_t rv = exr_get_tile_sizes(ctxt, 0, 0, 0, &tile_w, &tile_h);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_get_level_sizes(ctxt, 0, 0, 0, &level_w, &level_h);
    if (rv == EXR_ERR_SUCCESS && (tile_w <= 0 || tile_h <= 0))
        rv = EXR_ERR_FILE_BAD_HEADER;
    int tiles_x = rv == EXR_ERR_SUCCESS ? (level_w + tile_w - 1) / tile_w : 0;
    int tiles_y = rv == EXR_ERR_SUCCESS ? (level_h + tile_h - 1) / tile_h : 0;
    for (int ty = 0; rv == EXR_ERR_SUCCESS && ty < tiles_y; ++ty) {
        for (int tx = 0; rv == EXR_ERR_SUCCESS && tx < tiles_x; ++tx) {
            exr_chunk_info_t cinfo;
            rv = exr_read_tile_chunk_info(ctxt, 0, tx, ty, 0, 0, &cinfo);
            if (rv == EXR_ERR_SUCCESS)
                rv = decode_chunk(ctxt, r, &cinfo);
            if (rv == EXR_ERR_SUCCESS)
                place_chunk(r, dw->min.x + tx * tile_w, dw->min.y + ty * tile_h, cinfo.width, cinfo.height);
        }
    }
    return rv;
}

/* The part attributes of the multi-part layout that OpenEXR may also write
 * into single-part files: they describe the file, not the image. */
static int is_structural_attribute(const char *name)
{
    return strcmp(name, "type") == 0 || strcmp(name, "name") == 0;
}

/* Every string attribute of the part, in file order. */
static int read_string_attributes(exr_const_context_t ctxt, image *img, const char *path, gt_error *e)
{
    int32_t count = 0;
    if (exr_get_attribute_count(ctxt, 0, &count) != EXR_ERR_SUCCESS)
        return exr_error(e, path, "cannot read EXR header", EXR_ERR_FILE_BAD_HEADER);
    for (int32_t i = 0; i < count; ++i) {
        const exr_attribute_t *attr = NULL;
        if (exr_get_attribute_by_index(ctxt, 0, EXR_ATTR_LIST_FILE_ORDER, i, &attr) != EXR_ERR_SUCCESS || !attr)
            return exr_error(e, path, "cannot read EXR header", EXR_ERR_FILE_BAD_HEADER);
        if (attr->type != EXR_ATTR_STRING || !attr->string || is_structural_attribute(attr->name))
            continue;
        /* EXR strings carry a length and need not be NUL-terminated. */
        size_t len = attr->string->length > 0 ? (size_t)attr->string->length : 0;
        char *value = malloc(len + 1);
        if (!value)
            return gt_error_set(e, path, "out of memory");
        if (len)
            memcpy(value, attr->string->str, len);
        value[len] = '\0';
        int ok = image_set_attribute(img, attr->name, value) == 0;
        free(value);
        if (!ok)
            return gt_error_set(e, path, "out of memory");
    }
    return 0;
}

static int add_channels(exr_const_context_t ctxt, image *img, const char *path, gt_error *e)
{
    const exr_attr_chlist_t *list = NULL;
    if (exr_get_channels(ctxt, 0, &list) != EXR_ERR_SUCCESS || !list || list->num_channels <= 0)
        return gt_error_set(e, path, "EXR file has no channels");
    for (int c = 0; c < list->num_channels; ++c) {
        const exr_attr_chlist_entry_t *entry = &list->entries[c];
        gt_quoted q;
        if (entry->x_sampling != 1 || entry->y_sampling != 1)
            return gt_error_set(e, path, "channel %s is subsampled, which is not supported",
                                gt_quote(entry->name.str, &q));
        if (strlen(entry->name.str) >= IMAGE_NAME_MAX)
            return gt_error_set(e, path, "channel name %.40s... is too long (at most %d characters)",
                                entry->name.str, IMAGE_NAME_MAX - 1);
        if (!image_add_channel(img, entry->name.str))
            return gt_error_set(e, path, "out of memory");
    }
    return 0;
}

/* The number of channels of part 0 (0 when the list cannot be read). */
static int64_t channel_count(exr_const_context_t ctxt)
{
    const exr_attr_chlist_t *list = NULL;
    return exr_get_channels(ctxt, 0, &list) == EXR_ERR_SUCCESS && list ? list->num_channels : 0;
}

/* The bytes one pixel takes in the file before compression: 2 per HALF
 * channel, 4 per FLOAT or UINT. */
static int64_t stored_bytes_per_pixel(exr_const_context_t ctxt)
{
    const exr_attr_chlist_t *list = NULL;
    int64_t bytes = 0;
    if (exr_get_channels(ctxt, 0, &list) == EXR_ERR_SUCCESS && list)
        for (int c = 0; c < list->num_channels; ++c)
            bytes += list->entries[c].pixel_type == EXR_PIXEL_HALF ? 2 : 4;
    return bytes;
}

/* The header's windows against what a file of file_size bytes can hold
 * (exr_max_expansion): 0, or -1 with e. */
static int check_against_file_size(exr_const_context_t ctxt, const char *path, int64_t file_size, int64_t pixels,
                                   int64_t data_pixels, gt_error *e)
{
    exr_compression_t compression = EXR_COMPRESSION_LAST_TYPE;
    exr_get_compression(ctxt, 0, &compression);
    const double per_pixel = (double)stored_bytes_per_pixel(ctxt), stored = (double)file_size;
    const double ratio = exr_max_expansion(compression);
    if ((double)data_pixels * per_pixel > stored * ratio)
        return gt_error_set(e, path, "the header claims a data window of %lld pixels of %g bytes, more than a file of "
                            "%lld bytes can hold (at most %g:1 for its compression): truncated or crafted",
                            (long long)data_pixels, per_pixel, (long long)file_size, ratio);
    if ((double)pixels * per_pixel > stored * EXR_MAX_EXPANSION_ANY)
        return gt_error_set(e, path, "the header claims a display window of %lld pixels of %g bytes, more than a file "
                            "of %lld bytes can describe: truncated or crafted", (long long)pixels, per_pixel,
                            (long long)file_size);
    return 0;
}

/* Reads part 0 of an open file of file_size bytes into img (which it
 * initialises). */
static int read_part(exr_const_context_t ctxt, const char *path, int64_t file_size, image *img, gt_error *e)
{
    int parts = 0;
    exr_storage_t storage = EXR_STORAGE_LAST_TYPE;
    exr_attr_box2i_t dw, disp;
    if (exr_get_count(ctxt, &parts) != EXR_ERR_SUCCESS || parts < 1 ||
        exr_get_storage(ctxt, 0, &storage) != EXR_ERR_SUCCESS ||
        exr_get_data_window(ctxt, 0, &dw) != EXR_ERR_SUCCESS ||
        exr_get_display_window(ctxt, 0, &disp) != EXR_ERR_SUCCESS)
        return exr_error(e, path, "cannot read EXR header", EXR_ERR_FILE_BAD_HEADER);
    if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED)
        return gt_error_set(e, path, "deep EXR images are not supported");
    int64_t width = (int64_t)disp.max.x - disp.min.x + 1, height = (int64_t)disp.max.y - disp.min.y + 1;
    int64_t data_width = (int64_t)dw.max.x - dw.min.x + 1, data_height = (int64_t)dw.max.y - dw.min.y + 1;
    if (width <= 0 || height <= 0 || width * height > EXR_MAX_PIXELS)
        return gt_error_set(e, path, "unsupported EXR display window of %lld x %lld pixels", (long long)width,
                            (long long)height);
    if (data_width <= 0 || data_height <= 0 || data_width * data_height > EXR_MAX_PIXELS)
        return gt_error_set(e, path, "unsupported EXR data window of %lld x %lld pixels", (long long)data_width,
                            (long long)data_height);
    /* The image, and the largest decoded chunk (within the data window). */
    const int64_t channels = channel_count(ctxt);
    if (channels * width * height > EXR_MAX_FLOATS || channels * data_width * data_height > EXR_MAX_FLOATS)
        return gt_error_set(e, path, "EXR image of %lld x %lld pixels (data window %lld x %lld) and %lld channels "
                            "is larger than gtlab reads (%lld floats)", (long long)width, (long long)height,
                            (long long)data_width, (long long)data_height, (long long)channels,
                            (long long)EXR_MAX_FLOATS);
    if (check_against_file_size(ctxt, path, file_size, width * height, data_width * data_height, e) != 0)
        return -1;
    if (image_init(img, (int)width, (int)height) != 0)
        return gt_error_set(e, path, "out of memory");
    if (add_channels(ctxt, img, path, e) != 0 || read_string_attributes(ctxt, img, path, e) != 0)
        return -1;
    exr_reader r = {.img = img, .origin_x = disp.min.x, .origin_y = disp.min.y};
    exr_result_t rv = storage == EXR_STORAGE_TILED ? read_tiles(ctxt, &r, &dw) : read_scanlines(ctxt, &r, &dw);
    if (r.started)
        exr_decoding_destroy(ctxt, &r.dec);
    free(r.chunk);
    if (rv != EXR_ERR_SUCCESS)
        return exr_error(e, path, "cannot read EXR pixels (truncated or corrupt file?)", rv);
    return 0;
}

/* Reads the file of file_size bytes that init's read functions read into
 * img. */
static int read_with(const exr_context_initializer_t *init, const char *path, int64_t file_size, image *img,
                     gt_error *e)
{
    memset(img, 0, sizeof *img);
    exr_message[0] = '\0';
    exr_context_t ctxt = NULL;
    exr_result_t rv = exr_start_read(&ctxt, path, init);
    if (rv != EXR_ERR_SUCCESS) {
        exr_finish(&ctxt);
        return exr_error(e, path, rv == EXR_ERR_FILE_ACCESS ? "cannot open" : "not a readable EXR file", rv);
    }
    /* The header parser may have reported problems it could live with. */
    exr_message[0] = '\0';
    int result = read_part(ctxt, path, file_size, img, e);
    exr_finish(&ctxt);
    if (result != 0)
        image_free(img);
    return result;
}

/* ------------------------------------------------------- reading a file */

/* The file, opened by gtlab (core/files/input_file.h: a regular file, never a
 * device or a FIFO) and read by OpenEXR through these callbacks. */
typedef struct {
    int fd;
    int64_t size;
} exr_file;

/* OpenEXR's read callback (pread semantics: a short count at the end). */
static int64_t file_read(exr_const_context_t ctxt, void *user_data, void *buffer, uint64_t size, uint64_t offset,
                         exr_stream_error_func_ptr_t error_cb)
{
    const exr_file *f = user_data;
    uint64_t done = 0;
    while (done < size) {
        ssize_t n = pread(f->fd, (char *)buffer + done, (size_t)(size - done), (off_t)(offset + done));
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            if (error_cb)
                error_cb(ctxt, EXR_ERR_READ_IO, "cannot read: %s", strerror(errno));
            return -1;
        }
        if (n == 0)
            break;
        done += (uint64_t)n;
    }
    return (int64_t)done;
}

static int64_t file_size(exr_const_context_t ctxt, void *user_data)
{
    (void)ctxt;
    return ((const exr_file *)user_data)->size;
}

int exr_read(const char *path, image *img, gt_error *e)
{
    memset(img, 0, sizeof *img);
    exr_file f;
    if ((f.fd = input_file_open(path, &f.size, e)) < 0)
        return -1;
    exr_context_initializer_t init = quiet_initializer();
    init.user_data = &f;
    init.read_fn = file_read;
    init.size_fn = file_size;
    int rc = read_with(&init, path, f.size, img, e);
    close(f.fd);
    return rc;
}

/* ------------------------------------------------------- reading memory */

typedef struct {
    const unsigned char *bytes;
    size_t size;
} exr_memory;

/* OpenEXR's read callback (pread semantics): a short count at the end. */
static int64_t memory_read(exr_const_context_t ctxt, void *user_data, void *buffer, uint64_t size, uint64_t offset,
                           exr_stream_error_func_ptr_t error_cb)
{
    (void)ctxt, (void)error_cb;
    const exr_memory *m = user_data;
    if (offset >= m->size)
        return 0;
    const uint64_t n = size < m->size - offset ? size : m->size - offset;
    memcpy(buffer, m->bytes + offset, (size_t)n);
    return (int64_t)n;
}

static int64_t memory_size(exr_const_context_t ctxt, void *user_data)
{
    (void)ctxt;
    return (int64_t)((const exr_memory *)user_data)->size;
}

int exr_read_memory(const void *bytes, size_t size, const char *name, image *img, gt_error *e)
{
    exr_memory m = {bytes, size};
    exr_context_initializer_t init = quiet_initializer();
    init.user_data = &m;
    init.read_fn = memory_read;
    init.size_fn = memory_size;
    return read_with(&init, name, (int64_t)size, img, e);
}
