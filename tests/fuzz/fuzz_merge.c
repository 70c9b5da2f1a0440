/* Fuzz target "merge": `gtlab merge` of two partial renders
 * (raytracer/reference_merge.h). The two inputs start as the two halves
 * (samples 0-3 and 4-7 of one seed) of an AO render of builtin:boxes at
 * 4x4 pixels, made once; the fuzz input, text, edits them line by line:
 *
 *   key=value      sets header attribute `key` of the input
 *   -key           removes header attribute `key`
 *   !channel       removes the channel
 *   @channel=i:v   sets pixel i (modulo the pixel count) of the channel to v
 *   --             the lines after it edit the second input
 *
 * so the merge meets what a crafted or broken file could hold: any header
 * (issue 21's 53 KB gtlab.sample_blocks among them), missing or foreign
 * channels, any sums and counts. A merge that succeeds must have a header
 * that reads back: its sample blocks parse and add up to its gtlab.spp. */
#define _POSIX_C_SOURCE 200809L
#include <inttypes.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ao/ao_quantity.h"
#include "core/reference_schema.h"
#include "fuzz_target.h"
#include "raytracer/reference_merge.h"
#include "raytracer/reference_render.h"
#include "raytracer/sample_blocks.h"
#include "scene/scene_loaders.h"

static image halves[2];

static image render_half(const scene *s, const camera *cam, uint32_t offset)
{
    reference_request req = {.quantity = QUANTITY_AO,
                             .sampling = {.spp = 4, .sample_offset = offset, .seed = 7, .threads = 1},
                             .normals = NORMAL_SHADING};
    image img;
    render_stats stats;
    gt_error e;
    FUZZ_REQUIRE(reference_render(s, "builtin:boxes", cam, &req, &img, &stats, &e) == 0);
    return img;
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    scene s;
    gt_error e;
    FUZZ_REQUIRE(scene_load("builtin:boxes", &s, &e) == 0);
    camera cam = s.camera;
    cam.width = cam.height = 4;
    halves[0] = render_half(&s, &cam, 0);
    halves[1] = render_half(&s, &cam, 4);
    scene_free(&s);
    return 0;
}

static int copy_image(const image *from, image *to)
{
    int rc = image_init(to, from->width, from->height);
    for (int c = 0; rc == 0 && c < from->channel_count; ++c) {
        float *data = image_add_channel(to, from->channels[c].name);
        rc = data ? 0 : -1;
        if (data)
            memcpy(data, from->channels[c].data, sizeof(float) * image_pixel_count(from));
    }
    for (int a = 0; rc == 0 && a < from->attribute_count; ++a)
        rc = image_set_attribute(to, from->attributes[a].key, from->attributes[a].value);
    return rc;
}

static void remove_attribute(image *img, const char *key)
{
    for (int a = 0; a < img->attribute_count; ++a)
        if (strcmp(img->attributes[a].key, key) == 0) {
            free(img->attributes[a].key);
            free(img->attributes[a].value);
            img->attributes[a] = img->attributes[--img->attribute_count];
            return;
        }
}

static void remove_channel(image *img, const char *name)
{
    for (int c = 0; c < img->channel_count; ++c)
        if (strcmp(img->channels[c].name, name) == 0) {
            free(img->channels[c].data);
            img->channels[c] = img->channels[--img->channel_count];
            return;
        }
}

/* "@channel=i:v" (line without the '@'). */
static void set_pixel(image *img, char *line)
{
    char *eq = strrchr(line, '='), *colon = eq ? strchr(eq, ':') : NULL;
    if (!colon)
        return;
    *eq = '\0';
    float *data = image_channel_data(img, line);
    const unsigned long long i = strtoull(eq + 1, NULL, 10);
    if (data)
        data[i % image_pixel_count(img)] = strtof(colon + 1, NULL);
}

static void edit(image *img, char *line)
{
    char *eq = strchr(line, '=');
    if (line[0] == '-')
        remove_attribute(img, line + 1);
    else if (line[0] == '!')
        remove_channel(img, line + 1);
    else if (line[0] == '@')
        set_pixel(img, line + 1);
    else if (eq) {
        *eq = '\0';
        (void)image_set_attribute(img, line, eq + 1);
    }
}

/* The merged header reads back and agrees with itself. */
static void check_merged(const image *merged)
{
    static sample_block blocks[SAMPLE_BLOCKS_MAX];
    int count = 0;
    gt_error e;
    FUZZ_REQUIRE(sample_blocks_parse(image_get_attribute(merged, ATTR_BLOCKS), "merged", blocks, SAMPLE_BLOCKS_MAX,
                                     &count, &e) == 0);
    uint64_t total = 0;
    for (int i = 0; i < count; ++i)
        total += blocks[i].end - blocks[i].begin;
    char text[32];
    snprintf(text, sizeof text, "%" PRIu64, total);
    FUZZ_REQUIRE(strcmp(image_get_attribute(merged, ATTR_SPP), text) == 0);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    image inputs[2];
    if (copy_image(&halves[0], &inputs[0]) != 0 || copy_image(&halves[1], &inputs[1]) != 0)
        abort();
    char *text = malloc(size + 1);
    memcpy(text, data, size);
    text[size] = '\0';
    int which = 0;
    for (char *line = text, *next; line; line = next) {
        next = strchr(line, '\n');
        if (next)
            *next++ = '\0';
        if (strcmp(line, "--") == 0)
            which = 1;
        else
            edit(&inputs[which], line);
    }
    free(text);
    const char *names[2] = {"a.exr", "b.exr"};
    image merged;
    gt_error e;
    if (reference_merge(&REFERENCE_REGISTRY_OF(QUANTITY_AO), inputs, names, 2, &merged, &e) == 0) {
        check_merged(&merged);
        image_free(&merged);
    }
    image_free(&inputs[0]);
    image_free(&inputs[1]);
    return 0;
}
