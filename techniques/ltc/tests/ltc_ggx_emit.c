/* Fits an 8^2 GGX LTC table (ltc/ltc_fit.h) and writes it in every
 * format to the folder argv[1] (for test_ltc_ggx_writers.sh); checks that
 * the EXR reads back bit-identical, channels and attributes included. */
#include <string.h>

#include "core/files/exr_io.h"
#include "core/reference_schema.h"
#include "ltc/ltc_fit.h"
#include "ltc/ltc_ggx_writers.h"
#include "tests/check.h"

static int plane_mismatches(const float *plane, const ltc_table *t, int c)
{
    int n = 0;
    for (int k = 0; plane && k < t->size * t->size; ++k) {
        const float *want = c < LTC_CHANNELS ? &t->data[k * LTC_CHANNELS + c] : &t->error[k];
        n += memcmp(&plane[k], want, sizeof(float)) != 0;
    }
    return n;
}

static void check_exr_round_trip(const char *dir, const ltc_table *t)
{
    char path[4096];
    image img;
    gt_error e;
    snprintf(path, sizeof path, "%s/ltc.exr", dir);
    CHECK(exr_read(path, &img, &e) == 0);
    const char *names[LTC_CHANNELS] = CH_LTC_NAMES;
    int mismatches = 0;
    for (int c = 0; c <= LTC_CHANNELS; ++c) {
        const float *plane = image_channel_data(&img, c < LTC_CHANNELS ? names[c] : CH_LTC_ERROR);
        CHECK(plane != NULL);
        mismatches += plane_mismatches(plane, t, c);
    }
    CHECK_MSG(mismatches == 0, "%d values differ after the EXR round trip", mismatches);
    CHECK(image_get_attribute(&img, ATTR_LUT) && strstr(image_get_attribute(&img, ATTR_LUT), "M^-1"));
    image_free(&img);
}

int main(int argc, char **argv)
{
    ltc_table t;
    gt_error e;
    if (argc != 2 || ltc_fit_table(&t, 8, 2, &e) != 0)
        return 2;
    int rc = ltc_ggx_write_all(argv[1], "ltc", "LTC_GGX", &t, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    if (rc == 0)
        check_exr_round_trip(argv[1], &t);
    ltc_table_free(&t);
    return check_report("ltc_ggx_emit");
}
