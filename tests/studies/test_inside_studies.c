/* studies/bloom and studies/ao_decals: the INSIDE sections' numbers without
 * their prose, at small sizes (dithering's: techniques/dither/tests/).
 * Bloom: the 13-tap fits end inside their bounds, the held fit keeps a total
 * weight of 1 and the free one does not, the Gaussian is met to 1e-9; off
 * half resolution is worse than at it; the pyramid's levels are halved
 * sizes with exact_half set only where both sides halve; the shaders exist;
 * 1 and 2 threads give the same numbers.
 * AO decals: the exact sphere within 4 s.e. of the reference on the floor
 * (equal to Quilez's there), the refit better than the light's sign, which
 * is better than the published sign; the refit inside its bounds, with
 * standard errors, better than the published decal on held-out scenes. */
#include <stdlib.h>
#include <string.h>

#include "studies/ao_decals.h"
#include "studies/bloom.h"
#include "tests/check.h"
#include "tests/test_files.h"

static void check_bloom(const char *dir, bloom_result *r, int threads)
{
    study_context ctx = {dir, QUALITY_PREVIEW, threads, NULL, NULL};
    bloom_request rq = {96, 54, 2, 3, 1};
    gt_error e;
    char path[4096];
    CHECK_MSG(bloom_study(&ctx, &rq, r, &e) == 0, "%s", e.message);
    double total[BLOOM_FITS] = {0};
    for (int f = 0; f < BLOOM_FITS; ++f) {
        CHECK(r->targets[f].fit.at_bound == 0);
        for (int k = 0; k < BLOOM_FIT_TAPS; ++k)
            total[f] += r->targets[f].fit.taps[k].w;
        CHECK(r->targets[f].worst_odd_mip > r->targets[f].fit.worst_error);
    }
    CHECK(total[0] < 0.995 && fabs(total[1] - 1.0) < 1e-12);
    CHECK(r->targets[2].fit.worst_error < 1e-9);
    CHECK(r->exact_levels_1080 == 3 && r->exact_levels_1088 == 6);
    CHECK(r->level_count == 2 && r->levels[0].width == 48 && r->levels[0].height == 27 && r->levels[0].exact_half);
    CHECK(r->levels[1].width == 24 && r->levels[1].height == 13 && !r->levels[1].exact_half);
    snprintf(path, sizeof path, "%s/%s/bloom_9tap.glsl", dir, BLOOM_DIR);
    CHECK(file_exists(path));
}

static void check_ao_decals(const char *dir)
{
    study_context ctx = {dir, QUALITY_PREVIEW, 2, NULL, NULL};
    ao_decals_request rq = {24, 128, 3, 24};
    static ao_decals_result r;
    gt_error e;
    CHECK_MSG(ao_decals_study(&ctx, &rq, &r, &e) == 0, "%s", e.message);
    CHECK(r.floor_pixels[0] > 200 && r.floor_pixels[1] > 100);
    for (int v = 0; v < AO_DECAL_VIEWS; ++v) {
        CHECK_MSG(r.rows[0].outlier_share[v] <= 0.01, "exact sphere, view %d: %g", v, r.rows[0].outlier_share[v]);
        CHECK_NEAR(r.rows[0].rmse[v], r.rows[1].rmse[v], 1e-6); /* the sphere is above every floor point's horizon */
        CHECK_MSG(r.quilez_exact_worst[v] < 1e-5, "Quilez vs exact %.3g", r.quilez_exact_worst[v]); /* pointwise */
        CHECK(r.rows[4].rmse[v] < r.rows[3].rmse[v] && r.rows[3].rmse[v] < r.rows[2].rmse[v]);
    }
    /* the refit is identified (inside its bounds, with standard errors) and beats the published decal held out */
    CHECK(r.fit.at_bound == 0 && r.fit.has_covariance && r.held_out_count > 500);
    CHECK(r.held_out_rmse[AO_DECAL_REFIT_FREE] < r.held_out_rmse[AO_DECAL_PUBLISHED]);
}

int main(void)
{
    char dir[2048];
    gt_error e;
    study_context top = {check_tmp_dir(), QUALITY_PREVIEW, 2, NULL, NULL};
    CHECK(study_make_dir(&top, "inside_studies", dir, sizeof dir, &e) == 0);
    check_ao_decals(dir);
    static bloom_result one, two;
    check_bloom(dir, &two, 2);
    check_bloom(dir, &one, 1);
    CHECK(memcmp(one.levels, two.levels, sizeof one.levels) == 0);
    return check_report("test_inside_studies");
}
