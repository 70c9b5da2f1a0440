/* Writes small atmosphere LUTs in every format to the folder argv[1] (for
 * test_atmosphere_luts_writers.sh), and checks each EXR reads back
 * bit-identical with its sizes and parametrization ("linear") attributes. */
#include <string.h>

#include "core/files/exr_io.h"
#include "core/reference_schema.h"
#include "atmosphere/atmosphere_luts_writers.h"
#include "tests/check.h"

static void check_exr_round_trip(const char *dir, const atmosphere_luts *luts, const char *file, const float *data,
                                 int per_texel, size_t texels, const char *first_channel, const char *sizes)
{
    char path[4096];
    image img;
    gt_error e;
    snprintf(path, sizeof path, "%s/%s", dir, file);
    CHECK(exr_read(path, &img, &e) == 0);
    const float *plane = image_channel_data(&img, first_channel);
    int mismatches = plane ? 0 : 1;
    for (size_t t = 0; plane && t < texels; ++t)
        mismatches += memcmp(&plane[t], &data[t * per_texel], sizeof(float)) != 0;
    CHECK_MSG(mismatches == 0, "%s: %d values differ after the EXR round trip", file, mismatches);
    CHECK(image_get_attribute(&img, "gtlab.lut.sizes") && strcmp(image_get_attribute(&img, "gtlab.lut.sizes"), sizes) == 0);
    CHECK(image_get_attribute(&img, ATTR_LUT_PARAMETRIZATION) &&
          strcmp(image_get_attribute(&img, ATTR_LUT_PARAMETRIZATION), "linear") == 0);
    (void)luts;
    image_free(&img);
}

int main(int argc, char **argv)
{
    atmosphere_model m = atmosphere_model_default();
    atmosphere_lut_sizes sizes = {{3, 5, 2, 2}, {4, 1, 2, 2}, {3, 1, 1, 2}};
    atmosphere_luts luts;
    char msg[256];
    gt_error e;
    if (argc != 2 || atmosphere_luts_build(&luts, &m, &sizes, 2, msg, sizeof msg) != 0)
        return 2;
    int rc = atmosphere_luts_write_all(argv[1], &luts, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    if (rc == 0) {
        check_exr_round_trip(argv[1], &luts, "atmosphere_inscatter.exr", luts.table[0], 6, 60, "inscatter.rayleigh.R",
                             "3 5 2 2");
        check_exr_round_trip(argv[1], &luts, "atmosphere_inscatter.exr", luts.table[0] + 5, 6, 60, "inscatter.mie.B",
                             "3 5 2 2");
        check_exr_round_trip(argv[1], &luts, "atmosphere_sun.exr", luts.table[1] + 1, 3, 16, "sun.G", "4 1 2 2");
        check_exr_round_trip(argv[1], &luts, "atmosphere_sky.exr", luts.table[2] + 2, 3, 6, "sky.B", "3 1 1 2");
    }
    atmosphere_luts_free(&luts);
    return check_report("atmosphere_luts_emit");
}
