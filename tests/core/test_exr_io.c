/* EXR I/O (core/files/exr_io.c): bit-exact round trips checked both by our reader
 * and by an independent one (OpenImageIO over the OpenEXR C++ library);
 * files of kinds gtlab never writes (tiled, HALF, UINT, offset data and
 * display windows) made by OpenImageIO and read back; bad files and failed
 * writes give one-line errors naming the file and leave nothing behind. */
#define _POSIX_C_SOURCE 200809L
#include <float.h>
#include <stdint.h>
#include <string.h>
#include <unistd.h>

#include "core/files/exr_io.h"
#include "tests/check.h"
#include "tests/test_files.h"
#include "tests/core/oiio_test_helpers.h"

static char test_dir[1024];

static const char *in_test_dir(const char *name)
{
    static char paths[8][1200];
    static int next = 0;
    char *p = paths[next++ % 8];
    snprintf(p, sizeof paths[0], "%s/%s", test_dir, name);
    return p;
}

static size_t read_bytes(const char *path, unsigned char **data)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return 0;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    *data = malloc((size_t)n);
    size_t got = *data ? fread(*data, 1, (size_t)n, f) : 0;
    fclose(f);
    return got;
}

static void write_bytes(const char *path, const void *data, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return;
    fwrite(data, 1, n, f);
    fclose(f);
}

static uint32_t xorshift(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

static int same_bits(const float *a, const float *b, size_t n) { return memcmp(a, b, n * sizeof(float)) == 0; }

/* An error result: -1, one line, naming the file. */
static void check_error(int rc, const gt_error *e, const char *path, const char *what)
{
    CHECK_MSG(rc == -1, "%s: expected failure, got %d", what, rc);
    CHECK_MSG(strstr(e->message, path) == e->message, "%s: message does not start with the path: %s", what,
              e->message);
    CHECK_MSG(strchr(e->message, '\n') == NULL, "%s: message is not one line: %s", what, e->message);
    printf("  %s -> %s\n", what, e->message);
}

/* Channels in no particular order (the EXR stores them sorted), one name
 * longer than EXR's 31-character short names; values that stress a float
 * codec: signed zeros, denormals, extremes, infinities, NaN, and random bit
 * patterns (NaN payloads included). */
static const char *const round_trip_channels[] = {"zeta.Z", "ao.V", "N.X", "albedo.R", "ao.V.stderr", "A",
                                                  "a.channel.name.longer.than.31.characters"};
#define ROUND_TRIP_CHANNELS (int)(sizeof round_trip_channels / sizeof round_trip_channels[0])

static void fill_round_trip_image(image *img, int width, int height)
{
    static const float specials[] = {0.0f,     -0.0f,    -1.5f,     1e-45f, FLT_MIN, -1e-30f, FLT_MAX,
                                     -FLT_MAX, INFINITY, -INFINITY, NAN,    3.1415927f, 1e30f, 0.1f};
    image_init(img, width, height);
    uint32_t state = 0x12345678u;
    for (int c = 0; c < ROUND_TRIP_CHANNELS; ++c) {
        float *p = image_add_channel(img, round_trip_channels[c]);
        for (size_t i = 0; i < image_pixel_count(img); ++i) {
            if (c == 1) {
                p[i] = specials[i % (sizeof specials / sizeof specials[0])];
            } else {
                uint32_t bits = xorshift(&state);
                memcpy(&p[i], &bits, sizeof bits);
            }
        }
    }
    char long_value[2001];
    memset(long_value, 'v', 2000);
    long_value[2000] = '\0';
    image_set_attribute(img, "gtlab.spp", "256");
    image_set_attribute(img, "gtlab.scene", "builtin:sphere-on-plane");
    image_set_attribute(img, "gtlab.camera", "{\"position\":[0,1,5],\"yfov_deg\":45.0}");
    image_set_attribute(img, "gtlab.empty", "");
    image_set_attribute(img, "gtlab.an.attribute.key.beyond.31.characters", "long key");
    image_set_attribute(img, "gtlab.utf8", "na\xc3\xafve \xe2\x80\x93 \xc3\xbc");
    image_set_attribute(img, "gtlab.long", long_value);
}

static void test_round_trip(int width, int height)
{
    printf("round trip %dx%d\n", width, height);
    char name[64];
    snprintf(name, sizeof name, "round_trip_%dx%d.exr", width, height);
    const char *path = in_test_dir(name);
    image img;
    fill_round_trip_image(&img, width, height);
    gt_error e = {{0}};
    CHECK_MSG(exr_write(path, &img, &e) == 0, "%s", e.message);

    image back;
    CHECK_MSG(exr_read(path, &back, &e) == 0, "%s", e.message);
    CHECK(back.width == width && back.height == height);
    CHECK(back.channel_count == img.channel_count);
    for (int c = 0; c < img.channel_count; ++c) {
        const float *got = image_channel_data(&back, img.channels[c].name);
        CHECK_MSG(got && same_bits(got, img.channels[c].data, image_pixel_count(&img)), "channel %s differs",
                  img.channels[c].name);
    }
    /* The EXR holds its channels sorted by name, whatever order we gave. */
    for (int c = 1; c < back.channel_count; ++c)
        CHECK(strcmp(back.channels[c - 1].name, back.channels[c].name) < 0);
    CHECK(back.attribute_count == img.attribute_count);
    for (int a = 0; a < img.attribute_count; ++a) {
        const char *got = image_get_attribute(&back, img.attributes[a].key);
        CHECK_MSG(got && strcmp(got, img.attributes[a].value) == 0, "attribute %s", img.attributes[a].key);
    }

    /* A second implementation reads the same pixels from a standard file:
     * scanline, ZIP, FLOAT. */
    oiio_test_image other;
    if (oiio_test_read(path, &other) == 0) {
        CHECK(other.width == width && other.height == height && other.channels == img.channel_count);
        CHECK(other.tile_width == 0);
        CHECK_MSG(strcmp(other.format, "float") == 0, "format %s", other.format);
        CHECK_MSG(strcmp(other.compression, "zip") == 0, "compression %s", other.compression);
        for (int c = 0; c < other.channels; ++c) {
            const float *ours = image_channel_data(&img, other.channel_names[c]);
            CHECK_MSG(ours != NULL, "OpenImageIO sees an unknown channel %s", other.channel_names[c]);
            int equal = ours != NULL;
            for (size_t i = 0; equal && i < image_pixel_count(&img); ++i)
                equal = memcmp(&ours[i], &other.pixels[i * (size_t)other.channels + (size_t)c], sizeof(float)) == 0;
            CHECK_MSG(equal, "OpenImageIO reads channel %s differently", other.channel_names[c]);
        }
        oiio_test_image_free(&other);
    } else {
        CHECK_MSG(0, "OpenImageIO cannot read %s", path);
    }
    image_free(&back);
    image_free(&img);
}

/* A value exactly representable in HALF (and in float and as an integer). */
static float test_value(int channel, int x, int y) { return (float)(channel * 64 + y * 8 + x) - 20.0f; }

/* Writes with OpenImageIO a file whose data window is (x, y, w, h) and display
 * window (fx, fy, fw, fh), reads it with exr_read, and checks every pixel of
 * the display window: the data where the windows overlap, 0 elsewhere. */
static void test_foreign_file(const char *name, const char *pixel_type, int tile_size, int x, int y, int w, int h,
                              int fx, int fy, int fw, int fh)
{
    printf("foreign file %s\n", name);
    static const char *const channels[] = {"B", "G", "R", "ao.V"};
    oiio_test_image src = {.width = w, .height = h, .channels = 4, .x = x, .y = y,
                           .full_x = fx, .full_y = fy, .full_width = fw, .full_height = fh};
    for (int c = 0; c < 4; ++c)
        snprintf(src.channel_names[c], sizeof src.channel_names[c], "%s", channels[c]);
    int is_uint = strcmp(pixel_type, "uint") == 0;
    src.pixels = malloc(sizeof(float) * (size_t)(w * h * 4));
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            for (int c = 0; c < 4; ++c) {
                float v = test_value(c, i, j);
                src.pixels[(j * w + i) * 4 + c] = is_uint ? v + 20.0f + (c == 3 ? 4.0e9f : 0.0f) : v;
            }
    const char *path = in_test_dir(name);
    if (oiio_test_write_exr(path, &src, pixel_type, tile_size, "from OpenImageIO") != 0) {
        CHECK_MSG(0, "OpenImageIO could not write %s", path);
        free(src.pixels);
        return;
    }
    image img;
    gt_error e = {{0}};
    CHECK_MSG(exr_read(path, &img, &e) == 0, "%s", e.message);
    CHECK_MSG(img.width == fw && img.height == fh, "%s: %dx%d", name, img.width, img.height);
    CHECK(img.channel_count == 4);
    int wrong = 0;
    for (int c = 0; c < 4 && img.channel_count == 4; ++c) {
        const float *p = image_channel_data(&img, channels[c]);
        CHECK_MSG(p != NULL, "%s: channel %s missing", name, channels[c]);
        for (int iy = 0; p && iy < img.height; ++iy)
            for (int ix = 0; ix < img.width; ++ix) {
                int dx = fx + ix - x, dy = fy + iy - y; /* position in the data window */
                float expected = dx >= 0 && dx < w && dy >= 0 && dy < h ? src.pixels[(dy * w + dx) * 4 + c] : 0.0f;
                if (p[iy * img.width + ix] != expected && wrong++ < 5)
                    fprintf(stderr, "%s: %s(%d,%d) = %g, expected %g\n", name, channels[c], ix, iy,
                            p[iy * img.width + ix], expected);
            }
    }
    CHECK_MSG(wrong == 0, "%s: %d wrong pixels", name, wrong);
    const char *s = image_get_attribute(&img, "test.string");
    CHECK(s && strcmp(s, "from OpenImageIO") == 0);
    CHECK(image_get_attribute(&img, "test.int") == NULL); /* only string attributes are loaded */
    image_free(&img);
    free(src.pixels);
}

static void test_bad_files(void)
{
    printf("bad files\n");
    gt_error e;
    image img;
    const char *missing = in_test_dir("no-such-file.exr");
    check_error(exr_read(missing, &img, &e), &e, missing, "missing file");
    CHECK(img.channel_count == 0 && img.channels == NULL && img.attributes == NULL);

    const char *text = in_test_dir("not-an-exr.exr");
    write_bytes(text, "this is not an EXR file\n", 24);
    check_error(exr_read(text, &img, &e), &e, text, "text file");

    const char *empty = in_test_dir("empty.exr");
    write_bytes(empty, "", 0);
    check_error(exr_read(empty, &img, &e), &e, empty, "empty file");

    const char *folder = in_test_dir("");
    check_error(exr_read(folder, &img, &e), &e, folder, "a folder");

    /* A real EXR cut short at several places: in the magic number, in the
     * header, in the offset table, in the pixels, one byte short. */
    unsigned char *bytes = NULL;
    size_t size = read_bytes(in_test_dir("round_trip_13x37.exr"), &bytes);
    CHECK(size > 1000);
    const size_t cuts[] = {3, 100, 400, size / 2, size - 100, size - 1};
    for (size_t k = 0; size > 1000 && k < sizeof cuts / sizeof cuts[0]; ++k) {
        char what[64];
        snprintf(what, sizeof what, "truncated to %zu of %zu bytes", cuts[k], size);
        const char *cut = in_test_dir("truncated.exr");
        write_bytes(cut, bytes, cuts[k]);
        check_error(exr_read(cut, &img, &e), &e, cut, what);
        CHECK(img.channels == NULL);
    }
    /* Garbage over the header or the pixels: an error or a successful read
     * (the data may not be checked), never a crash. */
    const size_t spots[] = {8, 60, size / 2, size - 64};
    for (size_t k = 0; size > 1000 && k < sizeof spots / sizeof spots[0]; ++k) {
        unsigned char *copy = malloc(size);
        memcpy(copy, bytes, size);
        for (size_t i = spots[k]; i < spots[k] + 48 && i < size; ++i)
            copy[i] ^= 0xa5u;
        const char *bad = in_test_dir("corrupt.exr");
        write_bytes(bad, copy, size);
        int rc = exr_read(bad, &img, &e);
        if (rc == 0)
            image_free(&img);
        else
            check_error(rc, &e, bad, "corrupt bytes");
        free(copy);
    }
    free(bytes);
}

static void test_failed_writes(void)
{
    printf("failed writes\n");
    image img;
    image_init(&img, 4, 3);
    float *v = image_add_channel(&img, "ao.V");
    for (int i = 0; i < 12; ++i)
        v[i] = (float)i;
    gt_error e;

    const char *no_folder = in_test_dir("no-such-folder/out.exr");
    check_error(exr_write(no_folder, &img, &e), &e, no_folder, "missing folder");
    CHECK(!file_exists(in_test_dir("no-such-folder")));

    /* A good file, then a write that OpenEXR refuses half-way (a string
     * attribute where the format has a compression attribute): the good file
     * must survive untouched. */
    const char *path = in_test_dir("kept.exr");
    CHECK_MSG(exr_write(path, &img, &e) == 0, "%s", e.message);
    image bad;
    image_init(&bad, 4, 3);
    float *b = image_add_channel(&bad, "ao.V");
    for (int i = 0; i < 12; ++i)
        b[i] = -1.0f;
    image_set_attribute(&bad, "compression", "none");
    check_error(exr_write(path, &bad, &e), &e, path, "refused header");
    image back;
    CHECK_MSG(exr_read(path, &back, &e) == 0, "%s", e.message);
    CHECK(back.channel_count == 1 && same_bits(image_channel_data(&back, "ao.V"), v, 12));
    image_free(&back);

    const char *fresh = in_test_dir("never-written.exr");
    check_error(exr_write(fresh, &bad, &e), &e, fresh, "refused header, new file");
    CHECK(!file_exists(fresh));
    image_free(&bad);

    image no_channels;
    image_init(&no_channels, 4, 3);
    check_error(exr_write(fresh, &no_channels, &e), &e, fresh, "no channels");
    CHECK(!file_exists(fresh));
    image_free(&no_channels);

    /* Overwriting an existing file replaces it. */
    v[0] = 42.0f;
    CHECK_MSG(exr_write(path, &img, &e) == 0, "%s", e.message);
    CHECK(exr_read(path, &back, &e) == 0 && image_channel_data(&back, "ao.V")[0] == 42.0f);
    image_free(&back);
    image_free(&img);
}

int main(void)
{
    snprintf(test_dir, sizeof test_dir, "%s/exr_io", check_tmp_dir());
    mkdir(test_dir, 0755);

    test_round_trip(7, 5);
    test_round_trip(13, 37); /* several ZIP chunks of 16 lines, the last one short */
    test_round_trip(1, 1);

    /* data window inside the display window, HALF, tiles 4x4 (edge tiles partial) */
    test_foreign_file("half_tiled_window.exr", "half", 4, 2, 1, 5, 3, 0, 0, 9, 6);
    /* UINT scanlines, including a value beyond float's 24-bit integers */
    test_foreign_file("uint_scanline.exr", "uint", 0, 0, 0, 6, 19, 0, 0, 6, 19);
    /* data window sticking out of the display window on the left and below */
    test_foreign_file("float_overhang.exr", "float", 0, -2, 3, 6, 5, 0, 0, 4, 5);
    /* display window not at the origin, tiled 2x2 */
    test_foreign_file("float_offset_display.exr", "float", 2, 10, 20, 3, 5, 10, 20, 3, 5);

    test_bad_files();
    test_failed_writes();

    CHECK_MSG(leftover_temp_files_in(test_dir) == 0, "temporary files left in %s", test_dir);
    return check_report("test_exr_io");
}
