/* The anti-aliasing study on a small frame of the boxes scene:
 * - the truth converges: 16 against 64 samples per pixel within RMSE 0.01
 *   of display values, with both filters (the bound the report states);
 * - 2 x 2 supersampling is closer to the truth than one sample per pixel
 *   (RMSE and DSSIM), with both filters;
 * - every score is finite and non-negative. */
#include <math.h>
#include <string.h>

#include "anti_aliasing/anti_aliasing_study.h"
#include "tests/check.h"

int main(void)
{
    study_context ctx = {.output_dir = check_tmp_dir(), .quality = QUALITY_PREVIEW, .threads = 2};
    aa_request rq = aa_default_request(QUALITY_PREVIEW);
    rq.width = 96, rq.height = 72, rq.scene_count = 1;
    rq.temporal.frames = 0; /* the temporal part: test_aa_temporal_study */
    static aa_result r;
    gt_error e;
    int rc = aa_study(&ctx, &rq, &r, &e);
    CHECK_MSG(rc == 0, "%s", rc ? e.message : "");
    CHECK(r.truth_count == PIXEL_FILTER_COUNT && r.row_count == PIXEL_FILTER_COUNT * AA_TECHNIQUES);
    for (int f = 0; f < r.truth_count; ++f)
        CHECK_MSG(r.truth[f].truth16_rmse < 0.01, "%s: %g", r.truth[f].filter, r.truth[f].truth16_rmse);
    for (int f = 0; f < PIXEL_FILTER_COUNT; ++f) {
        const aa_row *none = &r.rows[f * AA_TECHNIQUES], *ssaa = &r.rows[f * AA_TECHNIQUES + 2];
        CHECK(strcmp(ssaa->technique, "SSAA 2x2 (box)") == 0);
        CHECK_MSG(ssaa->rmse < none->rmse && ssaa->dssim < none->dssim, "%s: %g %g / %g %g", none->filter,
                  ssaa->rmse, none->rmse, ssaa->dssim, none->dssim);
    }
    for (int i = 0; i < r.row_count; ++i)
        CHECK(isfinite(r.rows[i].rmse) && r.rows[i].rmse >= 0.0 && r.rows[i].dssim >= 0.0);
    return check_report("test_anti_aliasing_study");
}
