/* The Kulla-Conty study on a small request: the table it writes reads back
 * as the table (EXR, the lut channel), and a larger table scores better
 * (the lookup's error falls with the size). */
#include <stdio.h>
#include <sys/stat.h>

#include "core/files/exr_io.h"
#include "core/reference_schema.h"
#include "kulla_conty/kulla_conty_study.h"
#include "tests/check.h"

int main(void)
{
    char dir[512], path[700];
    snprintf(dir, sizeof dir, "%s/kulla_conty_study", check_tmp_dir());
    mkdir(dir, 0755);
    study_context ctx = {dir, QUALITY_PREVIEW, 2, NULL, NULL, 0};
    kulla_conty_request rq = {8, {4, 8, 16}, 3, 12, 4};
    static kulla_conty_result r;
    gt_error e = {{0}};
    CHECK_MSG(kulla_conty_study(&ctx, &rq, &r, &e) == 0, "%s", e.message);
    CHECK(r.by_size[0].max_furnace_error > r.by_size[2].max_furnace_error);
    CHECK(r.by_size[2].rms_error < r.by_size[0].rms_error / 4.0);
    for (int i = 0; i < 3; ++i)
        CHECK(r.by_size[i].size == rq.sizes[i] && r.by_size[i].max_error >= r.by_size[i].rms_error);
    CHECK(r.loss[0].energy_lost >= 0.0 && r.loss[KULLA_CONTY_LOSS_ROWS - 1].energy_lost > r.loss[0].energy_lost);

    snprintf(path, sizeof path, "%s/%s/kulla_conty_eavg_8.exr", dir, KULLA_CONTY_DIR);
    image img;
    CHECK_MSG(exr_read(path, &img, &e) == 0, "%s", e.message);
    const float *v = image_channel_data(&img, CH_LUT);
    kulla_conty_lut lut;
    CHECK(kulla_conty_lut_build(&lut, 8, 1) == 0);
    CHECK(img.width == 8 && img.height == 1 && v != NULL);
    for (int j = 0; v && j < 8; ++j)
        CHECK(v[j] == lut.average_albedo[j]);
    kulla_conty_lut_free(&lut);
    image_free(&img);
    snprintf(path, sizeof path, "%s/%s/kulla_conty_eavg_8.h", dir, KULLA_CONTY_DIR);
    struct stat st;
    CHECK(stat(path, &st) == 0 && st.st_size > 0);
    return check_report("test_kulla_conty_study");
}
