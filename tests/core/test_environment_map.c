/* Equirectangular environments (core/optics/environment_map.h): the documented
 * direction <-> (u, v) convention at the axes and round trips, texel solid
 * angles summing to 4 pi, the rotation moving a texel where the header says,
 * procedural texels against closed-form texel means, the synthetic sun's
 * rasterised solid angle against 2 pi (1 - cos r), files read back as
 * written by an independent writer (OIIO), Blender's DWAB-compressed studio
 * light read through OIIO, and bad files refused in one line naming them. */
#define _POSIX_C_SOURCE 200809L
#include <string.h>

#include "core/optics/environment_map.h"
#include "tests/check.h"
#include "tests/core/oiio_test_helpers.h"

#define BLENDER_SUNSET "/usr/share/blender/datafiles/studiolights/world/sunset.exr"

static const char *in_tmp(const char *name)
{
    static char path[1200];
    snprintf(path, sizeof path, "%s/%s", check_tmp_dir(), name);
    return path;
}

static void check_uv(vec3 w, float u_expected, float v_expected)
{
    float u, v;
    environment_direction_to_uv(w, &u, &v);
    CHECK_NEAR(u, u_expected, 1e-6);
    CHECK_NEAR(v, v_expected, 1e-6);
}

static void test_axes_and_round_trip(void)
{
    check_uv(v3(1, 0, 0), 0.5f, 0.5f);   /* +X: image centre */
    check_uv(v3(0, 0, -1), 0.25f, 0.5f); /* -Z: a quarter from the left */
    check_uv(v3(0, 0, 1), 0.75f, 0.5f);  /* +Z: three quarters */
    check_uv(v3(-1, 0, -1e-7f), 0.0f, 0.5f);
    check_uv(v3(0, 1, 0), 0.5f, 0.0f); /* zenith: top row */
    float u, v;
    environment_direction_to_uv(v3(0, -1, 0), &u, &v);
    CHECK_NEAR(v, 1.0, 1e-6);
    for (int i = 1; i < 200; ++i) { /* i = 0 would sit on the seam u = 0 = 1 */
        float uu = (i * 0.618034f) - floorf(i * 0.618034f), vv = 0.02f + 0.96f * (float)i / 200.0f;
        vec3 w = environment_uv_to_direction(uu, vv);
        CHECK_NEAR(v3_length(w), 1.0, 1e-6);
        environment_direction_to_uv(w, &u, &v);
        CHECK_NEAR(u, uu, 2e-6);
        CHECK_NEAR(v, vv, 2e-6);
    }
}

static void test_row_solid_angles(void)
{
    double sum = 0.0;
    for (int r = 0; r < 64; ++r)
        sum += 128 * environment_row_solid_angle(r, 128, 64);
    CHECK_NEAR(sum, 4.0 * M_PI, 1e-12);
}

/* An 8 x 4 map whose texel i holds (i, 2 i, 3 i). */
static void make_ramp(float *rgb)
{
    for (int i = 0; i < 32; ++i)
        for (int c = 0; c < 3; ++c)
            rgb[3 * i + c] = (float)(i * (c + 1));
}

static void test_lookup_and_rotation(void)
{
    float rgb[96], out[3];
    make_ramp(rgb);
    environment_map env;
    gt_error e;
    if (environment_map_from_pixels(&env, "ramp", 8, 4, rgb, &e) != 0) {
        CHECK_MSG(0, "%s", e.message);
        return;
    }
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) {
            vec3 w = environment_uv_to_direction((x + 0.5f) / 8.0f, (y + 0.5f) / 4.0f);
            CHECK(environment_texel_of(&env, w) == y * 8 + x);
            environment_map_radiance(&env, w, out);
            CHECK(out[2] == rgb[3 * (y * 8 + x) + 2]);
        }
    /* Turned 90 degrees: what the file shows at +Z (u = 3/4, texel column 6
     * of row 1) appears at world +X; intensity 2 doubles it. */
    CHECK(environment_map_transform(&env, 90.0f, 2.0f, &e) == 0);
    vec3 plus_x = v3(0.999f, 0.04f, 0.1f); /* just past +Z in the map: column 6 */
    environment_map_radiance(&env, v3_normalize(plus_x), out);
    CHECK_MSG(out[0] == 2.0f * rgb[3 * (1 * 8 + 6)], "rotated lookup %g", (double)out[0]);
    vec3 back = environment_world_to_map(&env, environment_map_to_world(&env, v3(0.3f, 0.4f, -0.866f)));
    CHECK_NEAR(back.x, 0.3, 1e-6);
    CHECK_NEAR(back.z, -0.866, 1e-6);
    CHECK(environment_map_transform(&env, NAN, 1.0f, &e) == -1);
    CHECK(environment_map_transform(&env, 0.0f, -1.0f, &e) == -1);
    environment_map_free(&env);
}

static void height_radiance(vec3 w, void *ctx, float rgb[3])
{
    (void)ctx;
    rgb[0] = 1.0f + w.y, rgb[1] = 1.0f, rgb[2] = w.y * w.y;
}

/* The texel mean of 1 + y (y = cos theta) over a band is 1 + the midpoint of its cos
 * range (the stratified midpoint rule is exact for a linear function), and
 * the mean of y^2 is (a^2 + ab + b^2) / 3 to O(1/s^2). */
static void test_procedural(void)
{
    environment_map env;
    gt_error e;
    if (environment_map_procedural(&env, "height", 16, 8, 8, height_radiance, NULL, &e) != 0) {
        CHECK_MSG(0, "%s", e.message);
        return;
    }
    for (int r = 0; r < 8; ++r) {
        double a = cos(M_PI * r / 8), b = cos(M_PI * (r + 1) / 8);
        const float *texel = env.rgb + 3 * (r * 16 + 5);
        CHECK_NEAR(texel[0], 1.0 + (a + b) / 2, 1e-6);
        CHECK(texel[1] == 1.0f);
        CHECK_NEAR(texel[2], (a * a + a * b + b * b) / 3, (a - b) * (a - b) / (12.0 * 64) + 1e-6);
    }
    environment_map_free(&env);
    float white[3] = {1, 1, 1}, out[3];
    CHECK(environment_map_constant(&env, "white", white, &e) == 0);
    CHECK(environment_map_is_constant(&env));
    environment_map_radiance(&env, v3(0, -1, 0), out);
    CHECK(out[0] == 1.0f && out[1] == 1.0f && out[2] == 1.0f);
    float negative[3] = {1, -1, 1};
    CHECK(environment_map_constant(&env, "bad", negative, &e) == -1);
}

/* The rasterised disc covers 2 pi (1 - cos r) of solid angle to within the
 * partial coverage of its edge texels (8 x 8 points each). */
static void test_sun(void)
{
    environment_sun sun = environment_sun_default();
    CHECK_NEAR(sun.radiance * 2.0 * M_PI * (1.0 - cos(sun.radius)), M_PI, 1e-9);
    environment_map env;
    gt_error e;
    if (environment_map_sun(&env, &sun, &e) != 0) {
        CHECK_MSG(0, "%s", e.message);
        return;
    }
    double covered = 0.0; /* (\int L - 4 pi sky) / (radiance - sky) */
    for (int y = 0; y < env.height; ++y)
        for (int x = 0; x < env.width; ++x) {
            double value = env.rgb[3 * ((size_t)y * env.width + x)];
            covered += (value - (float)sun.sky) / (sun.radiance - sun.sky) * env.row_solid_angle[y];
        }
    double nominal = 2.0 * M_PI * (1.0 - cos(sun.radius));
    printf("  sun: rasterised solid angle %.6g sr, nominal %.6g sr\n", covered, nominal);
    CHECK_NEAR(covered / nominal, 1.0, 0.02);
    float out[3];
    environment_map_radiance(&env, sun.direction, out);
    CHECK_NEAR(out[0], sun.radiance, 1e-3 * sun.radiance);
    environment_map_free(&env);
}

static int write_float_exr(const char *path, int width, int height, const float *rgb)
{
    oiio_test_image img;
    memset(&img, 0, sizeof img);
    img.width = img.full_width = width, img.height = img.full_height = height, img.channels = 3;
    strcpy(img.channel_names[0], "R"), strcpy(img.channel_names[1], "G"), strcpy(img.channel_names[2], "B");
    img.pixels = (float *)rgb;
    return oiio_test_write_exr(path, &img, "float", 0, "environment");
}

static void check_refused(const char *path, const char *expected, const char *what)
{
    environment_map env;
    gt_error e;
    CHECK_MSG(environment_map_load(&env, path, &e) == -1, "%s: loaded", what);
    CHECK_MSG(strstr(e.message, path) == e.message, "%s: message does not start with the file: %s", what, e.message);
    CHECK_MSG(strstr(e.message, expected) != NULL, "%s: message lacks '%s': %s", what, expected, e.message);
    CHECK_MSG(strchr(e.message, '\n') == NULL, "%s: message is not one line", what);
    CHECK(env.rgb == NULL);
    printf("  %s -> %s\n", what, e.message);
}

static void test_files(void)
{
    float rgb[96];
    make_ramp(rgb);
    const char *path = in_tmp("env_ramp.exr");
    CHECK(write_float_exr(path, 8, 4, rgb) == 0);
    environment_map env;
    gt_error e;
    CHECK_MSG(environment_map_load(&env, path, &e) == 0, "%s", e.message);
    CHECK(env.width == 8 && env.height == 4 && memcmp(env.rgb, rgb, sizeof rgb) == 0);
    environment_map_free(&env);
    check_refused(in_tmp("no_such_environment.exr"), "no_such_environment", "missing file");
    CHECK(write_float_exr(in_tmp("env_square.exr"), 4, 4, rgb) == 0);
    check_refused(in_tmp("env_square.exr"), "2:1", "square image");
    /* Mean luminance about 15.5 x (0.2126 + 2 0.7152 + 3 0.0722): ringing down
     * to -0.05 times that (-1.42) reads as 0; -2 is refused. */
    rgb[3 * 9 + 1] = -1.4f;
    CHECK(write_float_exr(path, 8, 4, rgb) == 0);
    CHECK_MSG(environment_map_load(&env, path, &e) == 0, "%s", e.message);
    CHECK(env.clamped_values == 1 && env.rgb && env.rgb[3 * 9 + 1] == 0.0f);
    environment_map_free(&env);
    rgb[3 * 9 + 1] = -2.0f;
    CHECK(write_float_exr(in_tmp("env_negative.exr"), 8, 4, rgb) == 0);
    check_refused(in_tmp("env_negative.exr"), "pixel (1, 1) channel G is -2", "negative pixel");
    rgb[3 * 9 + 1] = NAN;
    CHECK(write_float_exr(in_tmp("env_nan.exr"), 8, 4, rgb) == 0);
    check_refused(in_tmp("env_nan.exr"), "is nan", "NaN pixel");
}

/* Blender's studio lights are DWAB-compressed, which OpenEXR's C API cannot
 * decode: read through OIIO they match OIIO's own reading. */
static void test_blender_dwab(void)
{
    environment_map env;
    gt_error e;
    CHECK_MSG(environment_map_load(&env, BLENDER_SUNSET, &e) == 0, "%s (is blender-data installed?)", e.message);
    if (env.rgb == NULL)
        return;
    oiio_test_image img;
    CHECK(oiio_test_read(BLENDER_SUNSET, &img) == 0);
    CHECK_MSG(strcmp(img.compression, "dwab") == 0, "compression %s", img.compression);
    CHECK(env.width == 1024 && env.height == 512 && img.channels == 3);
    long same = 0, clamped = 0;
    for (size_t i = 0; i < 3 * 1024 * 512; ++i) {
        same += env.rgb[i] == img.pixels[i];
        clamped += img.pixels[i] < 0.0f && env.rgb[i] == 0.0f;
    }
    printf("  sunset.exr: %ld ringing values below 0 read as 0\n", clamped);
    CHECK(clamped == env.clamped_values && clamped > 0);
    CHECK(same + clamped == 3 * 1024 * 512);
    oiio_test_image_free(&img);
    environment_map_free(&env);
    static const char *const names[] = {"city", "courtyard", "forest", "interior", "night", "studio", "sunrise"};
    for (int i = 0; i < 7; ++i) {
        char path[256];
        snprintf(path, sizeof path, "/usr/share/blender/datafiles/studiolights/world/%s.exr", names[i]);
        CHECK_MSG(environment_map_load(&env, path, &e) == 0, "%s", e.message);
        printf("  %s.exr: %ld ringing values read as 0\n", names[i], env.clamped_values);
        environment_map_free(&env);
    }
}

int main(void)
{
    test_axes_and_round_trip();
    test_row_solid_angles();
    test_lookup_and_rotation();
    test_procedural();
    test_sun();
    test_files();
    test_blender_dwab();
    return check_report("test_environment_map");
}
