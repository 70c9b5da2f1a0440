/* Fuzz target "exr": an EXR file (the input is its bytes) read as gtlab
 * reads every EXR (core/files/exr_io.h), then each gtlab header attribute read as
 * its reader reads it: the typed numbers (core/reference_schema.h), the
 * camera JSON (scene/camera.h), the sample blocks
 * (raytracer/sample_blocks.h), the quantity, and the exact accumulators with
 * their scale exponents and normalised layers (core/statistics/mc_film.h). */
#include "ao/ao_quantity.h"
#include "core/files/exr_io.h"
#include "core/statistics/mc_film.h"
#include "core/reference_schema.h"
#include "fuzz_target.h"
#include "multibounce/multibounce_quantity.h"
#include "raytracer/reference_render.h"
#include "raytracer/sample_blocks.h"
#include "scene/camera.h"

static void read_attributes(const image *img)
{
    gt_error e;
    long whole;
    double real;
    (void)schema_get_int(img, ATTR_SPP, "fuzz.exr", &whole, &e);
    (void)schema_get_int(img, ATTR_SEED, "fuzz.exr", &whole, &e);
    (void)schema_get_real(img, ATTR_ROUGHNESS, "fuzz.exr", &real, &e);
    (void)schema_get_real(img, ATTR_LUT_ERROR, "fuzz.exr", &real, &e);
    const char *camera_json = image_get_attribute(img, ATTR_CAMERA);
    camera cam;
    if (camera_json)
        (void)camera_parse_json(camera_json, "fuzz.exr", &cam, &e);
    static sample_block blocks[SAMPLE_BLOCKS_MAX];
    int count;
    if (sample_blocks_parse(image_get_attribute(img, ATTR_BLOCKS), "fuzz.exr", blocks, SAMPLE_BLOCKS_MAX, &count,
                            &e) == 0)
        FUZZ_REQUIRE(count >= 1 && count <= SAMPLE_BLOCKS_MAX);
    const char *quantity = image_get_attribute(img, ATTR_QUANTITY);
    if (quantity)
        (void)reference_quantity_find(&REFERENCE_REGISTRY_OF(QUANTITY_GBUFFER, QUANTITY_AO, QUANTITY_MULTIBOUNCE),
                                      quantity);
    mc_film film;
    if (mc_film_read_channels(img, "fuzz.exr", &film, &e) == 0)
        mc_film_free(&film);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    image img;
    gt_error e;
    if (exr_read_memory(data, size, "fuzz.exr", &img, &e) != 0)
        return 0;
    FUZZ_REQUIRE(img.width > 0 && img.height > 0);
    read_attributes(&img);
    image_free(&img);
    return 0;
}
