/* The combination images (height_fog/aerial_perspective_study.h), no prose:
 *  - the fog's fitted scale height: exactly H_R for an atmosphere without
 *    Mie (one species: the fit's equation has that root), and between the
 *    species' scale heights otherwise (the column of a sum of exponentials
 *    lies between those of its extremes);
 *  - the study at a small size: every pixel is terrain or sky, the fisheye's
 *    circle holds about pi/4 of its square, the scores are finite, the
 *    reference's own quadrature estimate is small, and 1 and 2 threads give
 *    the same numbers and the same bits in the files. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/files/exr_io.h"
#include "core/reference_schema.h"
#include "height_fog/aerial_perspective_study.h"
#include "tests/check.h"

static void test_scale_height(void)
{
    atmosphere_model m = atmosphere_model_default();
    for (int w = 0; w < 2; ++w) {
        double H = aerial_fog_scale_height(&m, w, 1500.0), hm = m.weathers[w].mie_scale_height;
        CHECK_MSG(H > hm && H < m.weathers[w].rayleigh_scale_height, "weather %d: H %g", w, H);
    }
    for (int w = 0; w < 2; ++w)
        for (int c = 0; c < 3; ++c)
            m.weathers[w].mie_scattering[c] = m.weathers[w].mie_extinction[c] = 0.0;
    CHECK_NEAR(aerial_fog_scale_height(&m, 0.4, 1500.0), m.weathers[0].rayleigh_scale_height, 1e-6 * 8000.0);
}

static int run(int threads, const char *sub, aerial_perspective_result *r)
{
    aerial_perspective_request rq = aerial_perspective_default_request(QUALITY_PREVIEW);
    rq.width = 24, rq.height = 16, rq.fisheye = 16, rq.sun_count = 1, rq.sun_elevations[0] = 20.0;
    rq.sizes.inscatter[3] = rq.sizes.sun[3] = rq.sizes.sky[3] = 2; /* two precomputations: t = 0, 1 */
    study_context ctx = {check_tmp_dir(), QUALITY_PREVIEW, threads, NULL, NULL, 0};
    char dir[4096];
    gt_error e;
    int rc = study_make_dir(&ctx, sub, dir, sizeof dir, &e);
    if (rc == 0)
        rc = aerial_perspective_study(&ctx, dir, &rq, r, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    r->seconds = 0.0;
    return rc;
}

/* The same bits in <sub>/<name> for both runs. */
static void same_file(const char *name)
{
    char a[4096], b[4096];
    snprintf(a, sizeof a, "%s/t1/%s", check_tmp_dir(), name);
    snprintf(b, sizeof b, "%s/t2/%s", check_tmp_dir(), name);
    image x, y;
    gt_error e;
    CHECK_MSG(exr_read(a, &x, &e) == 0 && exr_read(b, &y, &e) == 0, "%s", e.message);
    static const char *const names[3] = CH_AERIAL_REFERENCE_RGB, *const model[3] = CH_AERIAL_MODEL_RGB;
    for (int c = 0; c < 3; ++c) {
        CHECK(memcmp(image_channel_data(&x, names[c]), image_channel_data(&y, names[c]),
                     image_pixel_count(&x) * sizeof(float)) == 0);
        CHECK(memcmp(image_channel_data(&x, model[c]), image_channel_data(&y, model[c]),
                     image_pixel_count(&x) * sizeof(float)) == 0);
    }
    image_free(&x), image_free(&y);
}

int main(void)
{
    test_scale_height();
    static aerial_perspective_result one, two;
    if (run(1, "t1", &one) != 0 || run(2, "t2", &two) != 0)
        return check_report("test_aerial_perspective_study");
    CHECK(one.case_count == 2 && memcmp(one.cases, two.cases, sizeof one.cases[0] * one.case_count) == 0);
    for (int i = 0; i < one.case_count; ++i) {
        const aerial_case *c = &one.cases[i];
        CHECK(c->terrain_pixels > 0 && c->sky_pixels > 0 && c->terrain_pixels + c->sky_pixels == 24 * 16);
        CHECK(abs(c->fisheye_pixels - 201) <= 8); /* pi/4 x 256 */
        CHECK(c->reference_mean_terrain > 0.0 && c->reference_mean_sky > c->reference_mean_terrain);
        CHECK(c->reference_error < 1e-3);
        for (int m = 0; m < AERIAL_MODELS; ++m)
            CHECK(isfinite(c->rmse_view[m]) && c->rmse_view[m] > 0.0 && isfinite(c->dssim_view[m]));
        CHECK(isfinite(c->rmse_fisheye) && c->rmse_fisheye > 0.0 && isfinite(c->dssim_fisheye));
        CHECK(isfinite(c->rmse_fisheye_fine) && c->rmse_fisheye_fine > 0.0 && c->rmse_fisheye_fine != c->rmse_fisheye);
        printf("%s sun %g: H %.0f m, view rel. RMSE %.3f / %.3f, fisheye %.3f\n", c->weather, c->sun_elevation_deg,
               c->fog_scale_height, c->relative_rmse_view[0], c->relative_rmse_view[1], c->relative_rmse_fisheye);
    }
    same_file("aerial_dense_sun20.exr");
    same_file("fisheye_sunny_sun20.exr");
    return check_report("test_aerial_perspective_study");
}
