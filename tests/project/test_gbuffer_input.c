/* project/gbuffer_input.c: a G-buffer with a NaN or infinite depth or normal
 * on a surface pixel is refused with that pixel's coordinates and channel;
 * the same values where mask.A = 0 (no surface) are accepted. */
#include "project/gbuffer_input.h"
#include "tests/check.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/files/exr_io.h"
#include "core/reference_schema.h"

enum { W = 8, H = 6 };

/* A plane facing the camera; mask.A = 0 on the first row. */
static int write_gbuffer(const char *path, int x, int y, const char *channel, float value)
{
    image img;
    gt_error e;
    if (image_init(&img, W, H) != 0)
        return -1;
    const char *names[5] = {CH_DEPTH, CH_N_X, CH_N_Y, CH_N_Z, CH_MASK};
    const float fill[5] = {5.0f, 0.0f, 0.0f, 1.0f, 1.0f};
    for (int k = 0; k < 5; ++k) {
        float *c = image_add_channel(&img, names[k]);
        for (int i = 0; c && i < W * H; ++i)
            c[i] = k == 4 && i < W ? 0.0f : fill[k];
        if (c && channel && strcmp(channel, names[k]) == 0)
            c[y * W + x] = value;
    }
    image_set_attribute(&img, ATTR_CAMERA,
                        "{\"position\":[0,0,5],\"target\":[0,0,0],\"up\":[0,1,0],\"yfov_deg\":45,\"width\":8,"
                        "\"height\":6}");
    int rc = exr_write(path, &img, &e);
    image_free(&img);
    return rc;
}

/* Loads the G-buffer with value at (x, y) of channel; the error ("" if it loaded). */
static const char *load_with(int x, int y, const char *channel, float value)
{
    static gt_error e;
    char path[2048];
    snprintf(path, sizeof path, "%s/gbuffer_input_test.exr", check_tmp_dir());
    e.message[0] = '\0';
    CHECK(write_gbuffer(path, x, y, channel, value) == 0);
    approx_input in;
    if (approx_load(path, NULL, &in, &e) == 0) {
        approx_input_free(&in);
        e.message[0] = '\0';
    }
    return e.message;
}

int main(void)
{
    CHECK(strcmp(load_with(0, 0, NULL, 0), "") == 0);
    const char *m = load_with(3, 4, CH_DEPTH, NAN);
    CHECK_MSG(strstr(m, "pixel (3, 4): depth.Z is nan"), "%s", m);
    m = load_with(7, 5, CH_N_Y, INFINITY);
    CHECK_MSG(strstr(m, "pixel (7, 5): N.Y is inf"), "%s", m);
    m = load_with(2, 1, CH_MASK, NAN);
    CHECK_MSG(strstr(m, "pixel (2, 1): mask.A is nan"), "%s", m);
    /* No surface there: nothing reads it. */
    CHECK(strcmp(load_with(2, 0, CH_DEPTH, NAN), "") == 0);
    return check_report("test_gbuffer_input");
}
