/* ao_decals/ao_decals_scenes on the decal scenes at 32^2 pixels, 256 spp:
 *  - the exact box is within the reference's noise on box-on-plane (at most
 *    1% of floor pixels beyond 4 standard errors, RMSE below 0.01);
 *  - multiplying exact forms over-occludes the union: on overlap-on-plane their
 *    mean error is negative and the overlap region's RMSE exceeds the
 *    single-occluder region's by a factor above 2;
 *  - where the sphere sunk into the floor is the only occluder, the exact
 *    horizon-clipped sphere beats Quilez's (which ignores the horizon): RMSE below 0.8x;
 *  - in the corner the product of the walls and the exact crate over-occludes
 *    (mean error < 0);
 *  - the light's sign of the point decal beats the talk's wherever both are
 *    scored; every row's DSSIM map is written. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "ao_decals/ao_decals_scenes.h"
#include "ao_decals/ao_decals_study.h"
#include "tests/check.h"
#include "tests/test_files.h"

static const ao_decal_scene_row *row_of(const ao_decals_scenes_result *r, const char *scene, const char *prefix)
{
    for (int k = 0; k < r->row_count; ++k)
        if (strcmp(r->rows[k].scene, scene) == 0 && strncmp(r->rows[k].decal, prefix, strlen(prefix)) == 0)
            return &r->rows[k];
    return NULL;
}

int main(void)
{
    char dir[2048], path[4096];
    gt_error e;
    study_context top = {check_tmp_dir(), QUALITY_PREVIEW, 2, NULL, NULL, 0};
    CHECK(study_make_dir(&top, "ao_decals_scenes", dir, sizeof dir, &e) == 0);
    study_context ctx = {dir, QUALITY_PREVIEW, 2, NULL, NULL, 0};
    static ao_decals_scenes_result r;
    CHECK_MSG(ao_decals_scenes_study(&ctx, 32, 256, 0.0, 3, &r, &e) == 0, "%s", e.message);
    const ao_decal_scene_row *box = row_of(&r, "box-on-plane", "exact");
    CHECK(box && box->pixels > 500 && box->outlier_share <= 0.01 && box->rmse < 0.01);
    const ao_decal_scene_row *overlap = row_of(&r, "overlap-on-plane", "exact");
    CHECK(overlap && overlap->bias < 0.0);
    CHECK(overlap && overlap->region_rmse[AO_REGION_OVERLAP] > 2.0 * overlap->region_rmse[AO_REGION_SINGLE]);
    const ao_decal_scene_row *engine = row_of(&r, "overlap-on-plane", "engine");
    CHECK(overlap && engine && overlap->region_pixels[AO_REGION_CLIPPED] > 20);
    CHECK_MSG(overlap && engine && overlap->region_rmse[AO_REGION_CLIPPED] < 0.8 * engine->region_rmse[AO_REGION_CLIPPED],
              "clipped: exact %g, Quilez %g", overlap->region_rmse[AO_REGION_CLIPPED], engine->region_rmse[AO_REGION_CLIPPED]);
    const ao_decal_scene_row *corner = row_of(&r, "box-in-corner", "exact");
    CHECK(corner && corner->bias < 0.0);
    const char *scenes[] = {"pill-on-plane", "box-on-plane", "box-in-corner", "overlap-on-plane"};
    for (int s = 0; s < 4; ++s) {
        const ao_decal_scene_row *talk = row_of(&r, scenes[s], "point decal, talk"),
                                 *light = row_of(&r, scenes[s], "point decal, light");
        CHECK_MSG(talk && light && light->rmse < talk->rmse, "%s", scenes[s]);
        snprintf(path, sizeof path, "%s/%s/dssim_%s_point_light.png", dir, AO_DECALS_DIR, scenes[s]);
        CHECK_MSG(file_exists(path), "%s", path);
    }
    ao_decals_scenes_free(&r);
    return check_report("test_ao_decals_scenes_study");
}
