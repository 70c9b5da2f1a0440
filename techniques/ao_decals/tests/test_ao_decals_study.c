/* The AO decals study's numbers without the report's prose, at small sizes:
 * the exact sphere within 4 s.e. of the reference on the floor
 * (equal to Quilez's there), the refit better than the light's sign, which
 * is better than the published sign; the refit inside its bounds, with
 * standard errors, better than the published decal on held-out scenes. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ao_decals/ao_decals_study.h"
#include "tests/check.h"
#include "tests/test_files.h"

static void check_ao_decals(const char *dir)
{
    study_context ctx = {dir, QUALITY_PREVIEW, 2, NULL, NULL, 0};
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
    /* The held-out references' noise, which the At-a-glance row states: some receivers are
     * occluded, and a cosine-sampled V_d is a 0/1 sample of variance at most 1/4, so with 128
     * samples (sample variance over n - 1) no pixel's standard error exceeds 0.5 / sqrt(127). */
    CHECK(r.held_out_noise_rmse > 0.0 && r.held_out_noise_rmse <= 0.5 / sqrt(127.0));
}

int main(void)
{
    char dir[2048];
    gt_error e;
    study_context top = {check_tmp_dir(), QUALITY_PREVIEW, 2, NULL, NULL, 0};
    CHECK(study_make_dir(&top, "ao_decals_study", dir, sizeof dir, &e) == 0);
    check_ao_decals(dir);
    return check_report("test_ao_decals_study");
}
