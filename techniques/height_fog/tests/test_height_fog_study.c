/* The height fog study's numbers (height_fog/height_fog_study.h), no prose: on the
 * terrain every view ray goes down by far more than H/100, so the published
 * HeightFog() equals the single-scattering quadrature under its own
 * assumptions (sun unattenuated, no shadows) to float rounding; the regime
 * table shows the clamp's departures (upward rays lose most of their optical
 * depth, horizontal ones 0.5 %) and none beyond float rounding for the
 * corrected model; errors and
 * timings are finite and positive. */
#include <math.h>
#include <stdio.h>

#include "core/files/exr_io.h"
#include "core/reference_schema.h"
#include "height_fog/height_fog_study.h"
#include "tests/check.h"

int main(void)
{
    height_fog_request rq = height_fog_default_request(QUALITY_PREVIEW);
    rq.width = 32, rq.height = 24, rq.spp = 16;
    rq.aerial.width = 24, rq.aerial.height = 16, rq.aerial.fisheye = 16, rq.aerial.sun_count = 1;
    rq.aerial.sizes.inscatter[3] = rq.aerial.sizes.sun[3] = rq.aerial.sizes.sky[3] = 2; /* t = 0, 1 */
    study_context ctx = {check_tmp_dir(), QUALITY_PREVIEW, 2, NULL, NULL, 0};
    static height_fog_result r;
    gt_error e;
    CHECK_MSG(height_fog_study(&ctx, &rq, &r, &e) == 0, "%s", e.message);
    for (int i = 0; i < HEIGHT_FOG_CASES; ++i) {
        const height_fog_case *c = &r.cases[i];
        CHECK_MSG(c->pixels > 200 && c->published_max_rel_single < 1e-3, "%s %g: %d pixels, %g", c->weather,
                  c->sun_elevation_deg, c->pixels, c->published_max_rel_single);
        CHECK(c->reference_mean_l > 0.0 && c->reference_mean_stderr > 0.0 && c->single_mean_l > 0.0);
        for (int m = 0; m < HEIGHT_FOG_MODELS; ++m)
            CHECK(isfinite(c->rmse_l[m]) && c->rmse_l[m] > 0.0 && isfinite(c->dssim_l[m]) && c->rmse_t[m] < 1e-4);
        /* The ambient through the fog is the correction that matters in dense fog (techniques/height_fog/README.md). */
        CHECK(c->reference_noise_rms > 0.0 && c->reference_noise_rms < c->rmse_l[HEIGHT_FOG_MODEL_PUBLISHED]);
        if (i >= HEIGHT_FOG_SUNS)
            CHECK_MSG(c->rmse_l[HEIGHT_FOG_MODEL_SKY_ATTENUATED] < 0.5 * c->rmse_l[HEIGHT_FOG_MODEL_SUN_ATTENUATED], "%g vs %g",
                      c->rmse_l[HEIGHT_FOG_MODEL_SKY_ATTENUATED], c->rmse_l[HEIGHT_FOG_MODEL_SUN_ATTENUATED]);
    }
    for (int g = 0; g < HEIGHT_FOG_REGIMES; ++g) {
        const height_fog_regime *x = &r.regimes[g];
        CHECK_MSG(x->corrected_depth_error < 1e-3 && x->corrected_l_error < 1e-3, "%s: %g %g", x->regime,
                  x->corrected_depth_error, x->corrected_l_error);
        printf("%-45s published depth %.3g L %.3g | corrected %.3g %.3g\n", x->regime, x->published_depth_error,
               x->published_l_error, x->corrected_depth_error, x->corrected_l_error);
    }
    CHECK(r.regimes[0].published_depth_error < 0.0051); /* down: exact, or the clamp's f(1e-2) where |dy| < H/100 */
    CHECK(fabs(r.regimes[3].published_depth_error - 0.005) < 1e-4); /* horizontal: f(1e-2) */
    CHECK(r.regimes[4].published_depth_error > 0.9);                /* up: most of the depth lost */
    CHECK(r.aerial.case_count == 2); /* the combination images ran (techniques/height_fog/tests/test_aerial_perspective_study.c) */
    for (int m = 0; m < HEIGHT_FOG_MODELS; ++m)
        CHECK(r.analytic_cost.ns_per_pixel[m] > 0.0 && r.analytic_cost.ns_per_pixel[m] < 1e4);
    CHECK(r.analytic_cost.published_batch_ns_per_pixel > 0.0 && r.analytic_cost.published_batch_ns_per_pixel < 1e4);
    /* The error map of the dense, low-sun case is the published model minus the reference. */
    char path[4096];
    snprintf(path, sizeof path, "%s/%s/dense_sun05.exr", check_tmp_dir(), HEIGHT_FOG_DIR);
    image img;
    CHECK_MSG(exr_read(path, &img, &e) == 0, "%s", e.message);
    const float *err = image_channel_data(&img, CH_FOG_PUBLISHED_ERROR), *mask = image_channel_data(&img, CH_MASK);
    CHECK(err && mask && image_channel_data(&img, CH_FOG_CORRECTED_ERROR));
    double nonzero = 0.0;
    for (size_t i = 0; err && i < image_pixel_count(&img); ++i)
        nonzero += mask[i] > 0.5f && err[i] != 0.0f;
    CHECK(nonzero > 200);
    image_free(&img);
    return check_report("test_height_fog_study");
}
