/* Bit-identical renders whatever the thread count; partial renders over
 * disjoint sample blocks merge into exactly the full render (also through
 * EXR files); the stop rule stops only at powers of two >= 64 with the target
 * met;
 * overlapping blocks are refused. */
#include <math.h>
#include <string.h>

#include "ao/ao_quantity.h"
#include "core/files/exr_io.h"
#include "raytracer/reference_merge.h"
#include "raytracer/reference_render.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"
#include "core/reference_schema.h"

static scene test_scene;
static camera test_camera;

static image render(int spp, uint32_t offset, int threads, double target_stderr)
{
    gt_error e;
    image img = {0};
    reference_request req = {.quantity = QUANTITY_AO,
                             .sampling = {.spp = spp, .sample_offset = offset, .seed = 11,
                                          .target_stderr = target_stderr, .threads = threads},
                             .normals = NORMAL_SHADING};
    render_stats stats;
    if (reference_render(&test_scene, "builtin:boxes", &test_camera, &req, &img, &stats, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        CHECK(0);
    }
    return img;
}

static int channels_identical(const image *a, const image *b, const char *name)
{
    const float *x = image_channel_data(a, name), *y = image_channel_data(b, name);
    return x && y && memcmp(x, y, sizeof(float) * image_pixel_count(a)) == 0;
}

static int all_channels_identical(const image *a, const image *b)
{
    if (a->channel_count != b->channel_count)
        return 0;
    for (int c = 0; c < a->channel_count; ++c)
        if (!channels_identical(a, b, a->channels[c].name)) {
            fprintf(stderr, "channel %s differs\n", a->channels[c].name);
            return 0;
        }
    return 1;
}

static void test_threads(void)
{
    image one = render(32, 0, 1, 0.0), two = render(32, 0, 2, 0.0);
    CHECK(all_channels_identical(&one, &two));
    image_free(&one);
    image_free(&two);
}

static void test_merge(void)
{
    image full = render(64, 0, 2, 0.0);
    image halves[2] = {render(32, 0, 2, 0.0), render(32, 32, 2, 0.0)};
    const char *names[2] = {"first half", "second half"};
    image merged;
    gt_error e;
    CHECK(reference_merge(&REFERENCE_REGISTRY_OF(QUANTITY_AO), halves, names, 2, &merged, &e) == 0);
    static const char *const quantities[] = {"ao.V", "ao.Vuniform", "bent.X", "bent.Y", "bent.Z"};
    for (int q = 0; q < 5; ++q) {
        char err_name[64];
        snprintf(err_name, sizeof err_name, "%s.stderr", quantities[q]);
        CHECK_MSG(channels_identical(&full, &merged, quantities[q]), "%s", quantities[q]);
        CHECK_MSG(channels_identical(&full, &merged, err_name), "%s", err_name);
    }
    CHECK(strcmp(image_get_attribute(&merged, ATTR_SPP), "64") == 0);

    /* Through files: write the halves, read them back, merge again. */
    image reread[2];
    for (int h = 0; h < 2; ++h) {
        char path[512];
        snprintf(path, sizeof path, "%s/determinism_half%d.exr", check_tmp_dir(), h);
        CHECK(exr_write(path, &halves[h], &e) == 0);
        CHECK(exr_read(path, &reread[h], &e) == 0);
    }
    image merged_files;
    CHECK(reference_merge(&REFERENCE_REGISTRY_OF(QUANTITY_AO), reread, names, 2, &merged_files, &e) == 0);
    CHECK(channels_identical(&full, &merged_files, "ao.V"));
    CHECK(channels_identical(&full, &merged_files, "bent.Y"));

    /* The same block twice would count samples twice. */
    image same[2] = {halves[0], halves[0]};
    image refused;
    CHECK(reference_merge(&REFERENCE_REGISTRY_OF(QUANTITY_AO), same, names, 2, &refused, &e) != 0);
    CHECK(strstr(e.message, "counted twice") != NULL);

    for (int h = 0; h < 2; ++h) {
        image_free(&halves[h]);
        image_free(&reread[h]);
    }
    image_free(&merged);
    image_free(&merged_files);
    image_free(&full);
}

static void test_stop_rule(void)
{
    const double target = 0.02;
    image img = render(1024, 0, 2, target);
    const float *mask = image_channel_data(&img, "mask.A"), *n = image_channel_data(&img, "spp.N");
    const float *err = image_channel_data(&img, "ao.V.stderr");
    int bad = 0, stopped_early = 0;
    for (size_t i = 0; i < image_pixel_count(&img); ++i) {
        if (mask[i] == 0.0f)
            continue;
        int count = (int)n[i];
        int power_of_two = count >= 64 && (count & (count - 1)) == 0;
        if (count < 1024) {
            stopped_early++;
            bad += !power_of_two || !(err[i] <= target);
        }
    }
    CHECK_MSG(bad == 0, "%d pixels stopped without meeting the rule", bad);
    CHECK_MSG(stopped_early > 0, "no pixel stopped early");
    image_free(&img);
}

int main(void)
{
    gt_error e;
    if (scene_load("builtin:boxes", &test_scene, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        return 1;
    }
    CHECK(scene_choose_camera(&test_scene, NULL, 40, 32, &test_camera, &e) == 0);
    test_threads();
    test_merge();
    test_stop_rule();
    scene_free(&test_scene);
    return check_report("test_render_determinism");
}
