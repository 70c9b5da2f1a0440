/* Writes a 32^2 DFG LUT in every format to the folder argv[1] (for
 * test_dfg_lut_writers.sh), and checks the EXR reads back bit-identical. */
#include <string.h>

#include "core/files/exr_io.h"
#include "dfg/dfg_lut_writers.h"
#include "tests/check.h"

static void check_exr_round_trip(const char *dir, const dfg_lut *lut)
{
    char path[4096];
    image img;
    gt_error e;
    snprintf(path, sizeof path, "%s/dfg.exr", dir);
    CHECK(exr_read(path, &img, &e) == 0);
    const char *names[DFG_CHANNELS] = {"dfg.A", "dfg.B", "dfg.E"};
    int mismatches = 0;
    for (int c = 0; c < DFG_CHANNELS; ++c) {
        const float *plane = image_channel_data(&img, names[c]);
        CHECK(plane != NULL);
        for (int t = 0; plane && t < lut->size * lut->size; ++t)
            mismatches += memcmp(&plane[t], &lut->data[t * 3 + c], sizeof(float)) != 0;
    }
    CHECK_MSG(mismatches == 0, "%d values differ after the EXR round trip", mismatches);
    CHECK(image_get_attribute(&img, "gtlab.lut") && strstr(image_get_attribute(&img, "gtlab.lut"), "n.v"));
    image_free(&img);
}

int main(int argc, char **argv)
{
    dfg_lut lut;
    gt_error e;
    if (argc != 2 || dfg_lut_build(&lut, 32, 2) != 0)
        return 2;
    int rc = dfg_lut_write_all(argv[1], "dfg", "DFG_LUT", &lut, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    if (rc == 0)
        check_exr_round_trip(argv[1], &lut);
    dfg_lut_free(&lut);
    return check_report("dfg_lut_emit");
}
