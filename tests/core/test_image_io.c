/* Previews and heatmaps (core/files/image_io.cpp), read back by OpenImageIO:
 * 8-bit sRGB values against the IEC 61966-2-1 formula and known values,
 * heatmap colours against OIIO's colour map evaluated on its own and
 * against matplotlib's published end colours, masked pixels black, errors
 * naming the file and leaving nothing behind, a write that fails (a file
 * size limit, as a full disk) among them. */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/files/image_io.h"
#include "tests/check.h"
#include "tests/test_files.h"
#include "tests/core/oiio_test_helpers.h"

static char test_dir[1024];

static const char *in_test_dir(const char *name)
{
    static char path[1200];
    snprintf(path, sizeof path, "%s/%s", test_dir, name);
    return path;
}

/* The sRGB encoding (IEC 61966-2-1) of a linear value in [0, 1], as 8 bits. */
static int srgb8(double linear)
{
    double v = linear <= 0.0031308 ? 12.92 * linear : 1.055 * pow(linear, 1.0 / 2.4) - 0.055;
    return (int)floor(v * 255.0 + 0.5);
}

/* Pixel (x, y) channel c of an 8-bit file read as float, back in 0..255. */
static int byte_at(const oiio_test_image *img, int x, int y, int c)
{
    return (int)lrintf(img->pixels[((size_t)y * (size_t)img->width + (size_t)x) * (size_t)img->channels + (size_t)c] *
                       255.0f);
}

static void check_error(int rc, const gt_error *e, const char *path, const char *what)
{
    CHECK_MSG(rc == -1, "%s: expected failure", what);
    CHECK_MSG(strstr(e->message, path) == e->message, "%s: message does not start with the path: %s", what,
              e->message);
    CHECK_MSG(strchr(e->message, '\n') == NULL, "%s: message is not one line", what);
    CHECK_MSG(!file_exists(path), "%s: %s was written", what, path);
    printf("  %s -> %s\n", what, e->message);
}

static void test_grey_preview(void)
{
    /* 0 -> 0, 0.5 -> 188 and 1 -> 255 are the known sRGB values; above 1 and
     * below 0 clamp, NaN shows as black. */
    const float values[] = {0.0f, 0.5f, 1.0f, 4.0f, -1.0f, NAN, 0.001f, 0.01f, 0.2f, 0.8f};
    const int n = (int)(sizeof values / sizeof values[0]);
    const float *planes[1] = {values};
    const char *path = in_test_dir("grey.png");
    gt_error e;
    CHECK_MSG(image_write_preview(path, planes, 1, n, 1, 1.0f, &e) == 0, "%s", e.message);
    oiio_test_image img;
    if (oiio_test_read(path, &img) != 0) {
        CHECK_MSG(0, "cannot read %s", path);
        return;
    }
    CHECK(img.width == n && img.height == 1 && img.channels == 1);
    CHECK_MSG(strcmp(img.format, "uint8") == 0, "format %s", img.format);
    CHECK(byte_at(&img, 0, 0, 0) == 0);
    CHECK(byte_at(&img, 1, 0, 0) == 188);
    CHECK(byte_at(&img, 2, 0, 0) == 255);
    CHECK(byte_at(&img, 3, 0, 0) == 255);
    CHECK(byte_at(&img, 4, 0, 0) == 0);
    CHECK(byte_at(&img, 5, 0, 0) == 0);
    for (int i = 6; i < n; ++i)
        CHECK_MSG(abs(byte_at(&img, i, 0, 0) - srgb8(values[i])) <= 1, "%g -> %d, expected %d", (double)values[i],
                  byte_at(&img, i, 0, 0), srgb8(values[i]));
    oiio_test_image_free(&img);
}

static void test_rgb_preview(void)
{
    /* 3x2, distinct per channel and pixel, exposure 2: checks the channel
     * order, the row order and the exposure. */
    float r[6], g[6], b[6];
    for (int i = 0; i < 6; ++i) {
        r[i] = 0.25f;          /* x2 = 0.5 -> 188 */
        g[i] = 0.05f * (float)i; /* x2 = 0 .. 0.5 */
        b[i] = i == 4 ? 0.5f : 0.0f;
    }
    const float *planes[3] = {r, g, b};
    const char *path = in_test_dir("rgb.png");
    gt_error e;
    CHECK_MSG(image_write_preview(path, planes, 3, 3, 2, 2.0f, &e) == 0, "%s", e.message);
    oiio_test_image img;
    if (oiio_test_read(path, &img) != 0) {
        CHECK_MSG(0, "cannot read %s", path);
        return;
    }
    CHECK(img.width == 3 && img.height == 2 && img.channels == 3);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x) {
            int i = y * 3 + x;
            CHECK(byte_at(&img, x, y, 0) == 188);
            CHECK_MSG(abs(byte_at(&img, x, y, 1) - srgb8(2.0 * g[i])) <= 1, "G at %d,%d", x, y);
            CHECK(byte_at(&img, x, y, 2) == (i == 4 ? 255 : 0));
        }
    oiio_test_image_free(&img);
}

/* Heatmap of 0, vmax/2, vmax, 3 vmax (clamps), a masked pixel holding vmax,
 * and NaN. */
static void test_heatmap(const char *map, const int first[3], const int last[3])
{
    const float vmax = 0.25f;
    const float values[] = {0.0f, 0.125f, 0.25f, 0.75f, 0.25f, NAN};
    const float mask[] = {1, 1, 1, 1, 0, 1};
    const int n = 6;
    char name[64];
    snprintf(name, sizeof name, "heat_%s.png", map);
    const char *path = in_test_dir(name);
    gt_error e;
    CHECK_MSG(image_write_heatmap(path, values, mask, n, 1, vmax, map, &e) == 0, "%s", e.message);
    oiio_test_image img;
    if (oiio_test_read(path, &img) != 0) {
        CHECK_MSG(0, "cannot read %s", path);
        return;
    }
    CHECK(img.width == n && img.height == 1 && img.channels == 3);
    const float at[] = {0.0f, 0.5f, 1.0f, 1.0f, -1.0f, 0.0f}; /* where each pixel should sit on the map */
    for (int i = 0; i < n; ++i) {
        float linear[3] = {0, 0, 0};
        if (at[i] >= 0.0f)
            CHECK(oiio_test_color_map(map, at[i], linear) == 0);
        for (int c = 0; c < 3; ++c) {
            int got = byte_at(&img, i, 0, c), expected = srgb8(linear[c]);
            CHECK_MSG(abs(got - expected) <= 1, "%s pixel %d channel %d: %d, expected %d", map, i, c, got, expected);
        }
    }
    /* The file records its scale, and the colour bar's colours at 0, 1/2
     * and 1 (image_colour_map_srgb) are the pixels holding 0, vmax/2, vmax. */
    char description[128], expected_description[128];
    snprintf(expected_description, sizeof expected_description, "gtlab heatmap: %s, 0 to 0.25", map);
    CHECK(image_read_description(path, description, sizeof description) == 0 &&
          strcmp(description, expected_description) == 0);
    unsigned char bar[9];
    CHECK(image_colour_map_srgb(map, 3, bar) == 0);
    for (int k = 0; k < 9; ++k)
        CHECK_MSG(abs(bar[k] - byte_at(&img, k / 3, 0, k % 3)) <= 1, "%s bar stop %d channel %d: %d vs %d", map,
                  k / 3, k % 3, bar[k], byte_at(&img, k / 3, 0, k % 3));
    /* matplotlib's own 8-bit end colours (OIIO stores its maps linearised
     * and decimated, so within 1 level). */
    for (int c = 0; c < 3; ++c) {
        CHECK_MSG(abs(byte_at(&img, 0, 0, c) - first[c]) <= 1, "%s(0) channel %d: %d vs %d", map, c,
                  byte_at(&img, 0, 0, c), first[c]);
        CHECK_MSG(abs(byte_at(&img, 2, 0, c) - last[c]) <= 1, "%s(1) channel %d: %d vs %d", map, c,
                  byte_at(&img, 2, 0, c), last[c]);
        CHECK(byte_at(&img, 4, 0, c) == 0); /* masked */
    }
    oiio_test_image_free(&img);
}

/* The colour bar: the heatmap's pixels unchanged above, then black rows,
 * then rows whose left pixel is map(0) and right pixel map(1), ramping
 * monotonically in the map's lightness between (magma, FLIP's map). */
static void test_heatmap_bar(void)
{
    printf("colour bar\n");
    enum { BW = 40, BH = 8 };
    float values[BW * BH], mask[BW * BH];
    for (int i = 0; i < BW * BH; ++i)
        values[i] = (float)(i % BW) / BW, mask[i] = i % 5 != 0;
    const char *plain = in_test_dir("bar_plain.png");
    char plain_path[1200];
    snprintf(plain_path, sizeof plain_path, "%s", plain);
    const char *path = in_test_dir("bar.png");
    gt_error e;
    CHECK(image_write_heatmap(plain_path, values, mask, BW, BH, 0.5f, "magma", &e) == 0);
    CHECK_MSG(image_write_heatmap_with_bar(path, values, mask, BW, BH, 0.5f, "magma", &e) == 0, "%s", e.message);
    oiio_test_image a, b;
    if (oiio_test_read(plain_path, &a) != 0 || oiio_test_read(path, &b) != 0) {
        CHECK_MSG(0, "cannot read the bar heatmaps");
        return;
    }
    int bar = image_heatmap_bar_rows(BH);
    CHECK(bar == 4 && b.width == BW && b.height == BH + 2 * bar);
    for (int y = 0; y < BH; ++y)
        for (int x = 0; x < BW; ++x)
            for (int c = 0; c < 3; ++c)
                CHECK(byte_at(&a, x, y, c) == byte_at(&b, x, y, c));
    float first[3], last[3];
    CHECK(oiio_test_color_map("magma", 0.0f, first) == 0 && oiio_test_color_map("magma", 1.0f, last) == 0);
    for (int c = 0; c < 3; ++c) {
        CHECK(byte_at(&b, 3, BH, c) == 0);
        CHECK(abs(byte_at(&b, 0, BH + bar, c) - srgb8(first[c])) <= 1);
        CHECK(abs(byte_at(&b, BW - 1, b.height - 1, c) - srgb8(last[c])) <= 1);
    }
    int rising = 1;
    for (int x = 1; x < BW; ++x)
        rising &= byte_at(&b, x, BH + bar, 0) + byte_at(&b, x, BH + bar, 1) >=
                  byte_at(&b, x - 1, BH + bar, 0) + byte_at(&b, x - 1, BH + bar, 1) - 1;
    CHECK_MSG(rising, "the bar does not ramp from the map's dark end to its light end");
    oiio_test_image_free(&a);
    oiio_test_image_free(&b);
}

static void test_errors(void)
{
    printf("errors\n");
    const float v[4] = {0.1f, 0.2f, 0.3f, 0.4f};
    const float *planes[3] = {v, v, v};
    gt_error e;
    const char *p;
    p = in_test_dir("no-such-folder/out.png");
    check_error(image_write_preview(p, planes, 1, 2, 2, 1.0f, &e), &e, p, "missing folder");
    p = in_test_dir("unknown.notaformat");
    check_error(image_write_preview(p, planes, 1, 2, 2, 1.0f, &e), &e, p, "unknown extension");
    p = in_test_dir("noextension");
    check_error(image_write_preview(p, planes, 1, 2, 2, 1.0f, &e), &e, p, "no extension");
    p = in_test_dir("two.png");
    check_error(image_write_preview(p, planes, 2, 2, 2, 1.0f, &e), &e, p, "two channels");
    p = in_test_dir("empty.png");
    check_error(image_write_preview(p, planes, 3, 0, 2, 1.0f, &e), &e, p, "zero width");
    p = in_test_dir("badmap.png");
    check_error(image_write_heatmap(p, v, NULL, 2, 2, 1.0f, "no-such-map", &e), &e, p, "unknown colour map");
    unsigned char rgb[6];
    CHECK(image_colour_map_srgb("no-such-map", 2, rgb) == -1 && image_colour_map_srgb("inferno", 1, rgb) == -1);
    char text[16];
    CHECK(image_read_description(p, text, sizeof text) == -1); /* no such file */
    p = in_test_dir("badrange.png");
    check_error(image_write_heatmap(p, v, NULL, 2, 2, 0.0f, "inferno", &e), &e, p, "vmax 0");
    check_error(image_write_heatmap(p, v, NULL, 2, 2, NAN, "inferno", &e), &e, p, "vmax NaN");
}

/* Noise in [0, 1] (it does not compress: every file below is larger than
 * the limit). */
#define WRITE_FAILURES_CHILD "--write-failures-child"

static void fill_noise(float *v, size_t n)
{
    unsigned state = 12345u;
    for (size_t i = 0; i < n; ++i)
        v[i] = (float)((state = state * 1664525u + 1013904223u) >> 8) / 16777216.0f;
}

/* Every writer under a file size limit of 4 KiB with SIGXFSZ ignored (a
 * write past it fails with EFBIG, as on a full disk): -1, one line naming
 * the file and the system's reason, nothing under the name. In a child
 * process, which the limit would otherwise outlive the test in; the child
 * runs this program afresh (exec), since a forked copy of a process whose
 * OpenImageIO thread pool has started can spin forever in that pool's
 * bookkeeping (its workers are not copied by fork). */
static int write_failures_child(void)
{
    enum { SIDE = 64 };
    static float v[SIDE * SIDE];
    fill_noise(v, SIDE * SIDE);
    const float *planes[3] = {v, v, v};
    gt_error e;
    const char *p;
    p = in_test_dir("limit_preview.png");
    check_error(image_write_preview(p, planes, 3, SIDE, SIDE, 1.0f, &e), &e, p, "preview past the limit");
    CHECK_MSG(strstr(e.message, "File too large") != NULL, "%s", e.message);
    p = in_test_dir("limit_heatmap.png");
    check_error(image_write_heatmap(p, v, NULL, SIDE, SIDE, 1.0f, "inferno", &e), &e, p, "heatmap past the limit");
    p = in_test_dir("limit_bar.png");
    check_error(image_write_heatmap_with_bar(p, v, NULL, SIDE, SIDE, 1.0f, "turbo", &e), &e, p,
                "heatmap with bar past the limit");
    p = in_test_dir("limit_data8.png");
    check_error(image_write_data8(p, v, SIDE, SIDE, "noise", &e), &e, p, "8-bit data past the limit");
    p = in_test_dir("limit_data16.tif");
    check_error(image_write_data16(p, planes, 2, SIDE, SIDE, "noise", &e), &e, p, "16-bit data past the limit");
    fflush(stdout);
    return check_failures == 0 ? 0 : 1;
}

static void test_write_failures(void)
{
    printf("write failures\n");
    fflush(stdout);
    static const char *const names[] = {"limit_preview.png", "limit_heatmap.png", "limit_bar.png",
                                        "limit_data8.png", "limit_data16.tif"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; ++k)
        remove(in_test_dir(names[k])); /* an earlier run's */
    pid_t child = fork();
    if (child == 0) {
        signal(SIGXFSZ, SIG_IGN); /* kept across exec */
        setrlimit(RLIMIT_FSIZE, &(struct rlimit){4096, 4096});
        execl("/proc/self/exe", "test_image_io", WRITE_FAILURES_CHILD, (char *)NULL);
        _exit(127);
    }
    int status = 1;
    CHECK(child > 0 && waitpid(child, &status, 0) == child);
    CHECK_MSG(WIFEXITED(status) && WEXITSTATUS(status) == 0, "a writer past the file size limit did not fail cleanly");
    const float v[4] = {0.1f, 0.2f, 0.3f, 0.4f};
    gt_error e;
    const char *p = in_test_dir("unchecked.sgi");
    remove(p);
    check_error(image_write_data8(p, v, 2, 2, NULL, &e), &e, p, "a format that cannot be written to memory");
}

int main(int argc, char **argv)
{
    snprintf(test_dir, sizeof test_dir, "%s/image_io", check_tmp_dir());
    mkdir(test_dir, 0755);
    if (argc == 2 && strcmp(argv[1], WRITE_FAILURES_CHILD) == 0)
        return write_failures_child();

    test_grey_preview();
    test_rgb_preview();
    /* matplotlib's _cm_listed.py: inferno 0 = (0.001462, 0.000466, 0.013866),
     * 1 = (0.988362, 0.998364, 0.644924); viridis 0 = (0.267004, 0.004874,
     * 0.329415), 1 = (0.993248, 0.906157, 0.143936); times 255. */
    test_heatmap("inferno", (const int[3]){0, 0, 4}, (const int[3]){252, 255, 164});
    test_heatmap("viridis", (const int[3]){68, 1, 84}, (const int[3]){253, 231, 37});
    test_heatmap_bar();
    test_errors();
    test_write_failures();

    CHECK_MSG(leftover_temp_files_in(test_dir) == 0, "temporary files left in %s", test_dir);
    return check_report("test_image_io");
}
