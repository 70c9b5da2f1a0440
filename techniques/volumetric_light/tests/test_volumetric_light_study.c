/* volumetric_light/volumetric_light_study: the volumetric-light section's numbers without its prose,
 * on a small request. The jittered ray-march's error falls with the samples,
 * accumulation lowers it, no noise does not change over frames, 128 uniform
 * steps beat 3, the shadow map's floor falls with its size, the talk's
 * configuration improves with accumulation; Bayer's error spectrum is
 * peaked against white's; at equal cost 24 uniform steps beat 2 by DSSIM
 * and by FLIP (which is scored there only, within [0, 1]) and each gap is
 * the talk's figure minus 2 steps'; the image strip and the plot
 * data are written; results do not depend on the thread count; bad requests
 * are refused. */
#include <math.h>
#include <string.h>

#include "volumetric_light/volumetric_light_study.h"
#include "tests/check.h"
#include "tests/test_files.h"

static volumetric_light_request small_request(void)
{
    volumetric_light_request rq = volumetric_light_default_request(QUALITY_PREVIEW);
    rq.width = rq.height = 32;
    rq.seeds = 2, rq.frames = 6, rq.blue_noise_size = 32;
    rq.cost_width = 64, rq.cost_height = 48;
    rq.spp_count = 3;
    int spp[3] = {1, 3, 16};
    memcpy(rq.spp, spp, sizeof spp);
    return rq;
}

static void check_numbers(const volumetric_light_result *r)
{
    CHECK(r->pixels > 500 && r->reference_mean > 0.0 && r->reference_max_error < 1e-3 * r->reference_mean);
    for (int n = RAYMARCH_NOISE_WHITE; n < RAYMARCH_NOISE_COUNT; ++n) {
        CHECK_MSG(r->single[n][0].rmse > 2.0 * r->single[n][2].rmse, "%s: %.3g at 1 spp, %.3g at 16",
                  raymarch_noise_name((raymarch_noise)n), r->single[n][0].rmse, r->single[n][2].rmse);
        CHECK(r->accumulated[n][1].rmse < r->single[n][1].rmse);
        CHECK(r->spp_needed_accumulated[n] >= 1.0);
    }
    CHECK(r->accumulated[RAYMARCH_NOISE_NONE][1].rmse == r->single[RAYMARCH_NOISE_NONE][1].rmse);
    CHECK(r->uniform128.rmse < r->single[RAYMARCH_NOISE_NONE][1].rmse);
    CHECK_MSG(r->shadow_rmse[0] > r->shadow_rmse[VOLUMETRIC_LIGHT_SHADOW_SIZES - 1], "shadow floor %.3g (128) vs %.3g (1024)",
              r->shadow_rmse[0], r->shadow_rmse[VOLUMETRIC_LIGHT_SHADOW_SIZES - 1]);
    CHECK(r->talk[1].rmse < r->talk_single[1].rmse && r->talk_spp[1] == 6);
    CHECK(r->blue_ratio[RAYMARCH_NOISE_WHITE] > 0.0 && isfinite(r->blue_blurred_ratio[RAYMARCH_NOISE_IGN]));
    CHECK(r->ns_per_pixel_sample > 0.0);
    /* structure: Bayer's 8x8 tile piles its error into a few frequencies, white noise spreads it */
    CHECK_MSG(r->peak_ratio[RAYMARCH_NOISE_BAYER] > 3.0 * r->peak_ratio[RAYMARCH_NOISE_WHITE], "peaks %.3g vs %.3g",
              r->peak_ratio[RAYMARCH_NOISE_BAYER], r->peak_ratio[RAYMARCH_NOISE_WHITE]);
    CHECK(fabs(r->peak_over_blue[RAYMARCH_NOISE_BLUE] - 1.0) < 1e-12);
    CHECK(fabs(r->blue_blurred_gap[RAYMARCH_NOISE_BLUE]) < 1e-12 && isfinite(r->blue_blurred_gap[RAYMARCH_NOISE_WHITE]));
    /* equal cost, on the 64x48 image: 24 uniform steps beat 2; the gap is the talk's DSSIM minus 2 steps' */
    CHECK(r->cost_pixels > 1000 && r->cost_pixels <= 64 * 48);
    CHECK(r->cost_uniform24.dssim < r->cost_uniform2.dssim && r->cost_uniform24.rmse < r->cost_uniform2.rmse);
    CHECK(fabs(r->cost_dssim_gap - (r->cost_talk.dssim - r->cost_uniform2.dssim)) < 1e-12);
    CHECK_MSG(r->cost_uniform24.flip < r->cost_uniform2.flip && r->cost_uniform2.flip <= 1.0 && r->cost_talk.flip > 0.0,
              "FLIP 24 steps %.4f, 2 steps %.4f, talk %.4f", r->cost_uniform24.flip, r->cost_uniform2.flip,
              r->cost_talk.flip);
    CHECK(fabs(r->cost_flip_gap - (r->cost_talk.flip - r->cost_uniform2.flip)) < 1e-12 && r->cost_flip_gap_se > 0.0);
    CHECK(r->uniform128.flip == 0.0 && r->talk[0].flip == 0.0); /* FLIP is scored at equal cost only */
}

int main(void)
{
    char dir[2048], path[4096];
    gt_error e;
    study_context top = {check_tmp_dir(), QUALITY_PREVIEW, 2, NULL, NULL, 0};
    CHECK(study_make_dir(&top, "volumetric_light_study", dir, sizeof dir, &e) == 0);
    study_context two = {dir, QUALITY_PREVIEW, 2, NULL, NULL, 0}, one = {dir, QUALITY_PREVIEW, 1, NULL, NULL, 0};
    volumetric_light_request rq = small_request();
    static volumetric_light_result r2, r1;
    CHECK_MSG(volumetric_light_study(&two, &rq, &r2, &e) == 0, "%s", e.message);
    CHECK_MSG(volumetric_light_study(&one, &rq, &r1, &e) == 0, "%s", e.message);
    check_numbers(&r2);
    CHECK(r1.uniform128.rmse == r2.uniform128.rmse && r1.single[4][1].rmse == r2.single[4][1].rmse &&
          r1.accumulated[1][0].dssim == r2.accumulated[1][0].dssim && r1.talk[0].blurred == r2.talk[0].blurred);
    const char *files[] = {"reference.png", "blue_3.png", "talk_half_blue_6_accumulated.png", "error_vs_spp.dat"};
    for (int i = 0; i < 4; ++i) {
        snprintf(path, sizeof path, "%s/%s/%s", dir, VOLUMETRIC_LIGHT_DIR, files[i]);
        CHECK_MSG(file_exists(path), "%s not written", path);
    }
    CHECK(r1.cost_dssim_gap == r2.cost_dssim_gap && r1.cost_flip_gap == r2.cost_flip_gap && r1.peak_ratio[RAYMARCH_NOISE_IGN] == r2.peak_ratio[RAYMARCH_NOISE_IGN]);
    rq.cost_width = 1;
    CHECK(volumetric_light_study(&two, &rq, &r1, &e) != 0);
    rq = small_request(), rq.seeds = 0;
    CHECK(volumetric_light_study(&two, &rq, &r1, &e) != 0);
    return check_report("volumetric_light_study");
}
