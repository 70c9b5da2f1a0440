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

static ao_decals_result r;

/* The study on 24x24 views and decal scenes, seed 3, into r; whether the exact sphere sits
 * within 4 s.e. of the reference on both views. */
static int run_study(const char *dir, int spp, double noise_budget)
{
    study_context ctx = {dir, QUALITY_PREVIEW, 2, NULL, NULL, 0};
    ao_decals_request rq = {24, spp, 3, 24, noise_budget};
    gt_error e;
    CHECK_MSG(ao_decals_study(&ctx, &rq, &r, &e) == 0, "%s", e.message);
    int within = 1;
    for (int v = 0; v < AO_DECAL_VIEWS; ++v)
        within &= r.rows[0].outlier_share[v] <= 0.01;
    return within;
}

static void check_ao_decals(const char *dir)
{
    CHECK_MSG(run_study(dir, 128, 0.0), "exact sphere: %g, %g beyond 4 s.e.", r.rows[0].outlier_share[0],
              r.rows[0].outlier_share[1]);
    CHECK(r.floor_pixels[0] > 200 && r.floor_pixels[1] > 100);
    for (int v = 0; v < AO_DECAL_VIEWS; ++v) {
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

/* With a noise budget (issue 46 item 1) the references stop pixel by pixel, and the exact
 * sphere still sits within 4 s.e. of them: the binomial floor of the outlier test is each
 * pixel's own sample count, not the cap (with the cap, a pixel that stopped at 64 agreeing
 * samples would get too small a floor and count as an outlier). */
static void check_budgeted(const char *dir)
{
    CHECK_MSG(run_study(dir, 4096, 0.01), "exact sphere: %g, %g beyond 4 s.e.", r.rows[0].outlier_share[0],
              r.rows[0].outlier_share[1]);
    CHECK(r.held_out_noise_rmse > 0.0 && r.held_out_noise_rmse <= 0.01);
}

int main(void)
{
    char dir[2048];
    gt_error e;
    study_context top = {check_tmp_dir(), QUALITY_PREVIEW, 2, NULL, NULL, 0};
    CHECK(study_make_dir(&top, "ao_decals_study", dir, sizeof dir, &e) == 0);
    check_ao_decals(dir);
    check_budgeted(dir);
    return check_report("test_ao_decals_study");
}
