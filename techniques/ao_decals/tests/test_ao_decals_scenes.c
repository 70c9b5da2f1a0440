/* The AO decal scenes (scene/builtin_scene_ao_decals.h) against the exact
 * forms of ao_decals/ao_decals.h, with gtlab's AO reference (32^2 pixels,
 * 512 spp, fixed seed) as the independent estimator:
 *  - builtin:box-on-plane: 1 - the exact box (Lambert's polygon formula) within
 *    4 of the render's standard errors on every floor pixel; the floor points
 *    beside the crate face one to three of its faces;
 *  - builtin:corner: 1 - the sum of the walls' form factors (every ray from
 *    inside the open cube leaves it through one face, so the sum is the union)
 *    within 4 standard errors on every pixel of all three walls;
 *  - the decal's unit space keeps the normal perpendicular to the surface:
 *    a tangent t (t.n = 0) maps to t / half, and (t / half).norm = 0;
 *  - the scene table describes the same occluders the meshes hold (bounds). */
#include <math.h>

#include "ao/ao_quantity.h"
#include "ao_decals/ao_decals.h"
#include "core/reference_schema.h"
#include "raytracer/reference_render.h"
#include "scene/builtin_scene_ao_decals.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

enum { SIZE = 32, SPP = 512 };

typedef double (*exact_fn)(vec3 p, vec3 n);

static double box_on_plane(vec3 p, vec3 n)
{
    const ao_occluder *o = &ao_decal_scene_find("box-on-plane")->occluders[0];
    return ao_box_exact(p, n, v3_sub(o->centre, o->half), v3_add(o->centre, o->half));
}

static double corner_walls(vec3 p, vec3 n)
{
    const vec3 walls[3][4] = {{v3(0, 0, 0), v3(10, 0, 0), v3(10, 0, 10), v3(0, 0, 10)},
                              {v3(0, 0, 0), v3(0, 10, 0), v3(0, 10, 10), v3(0, 0, 10)},
                              {v3(0, 0, 0), v3(10, 0, 0), v3(10, 10, 0), v3(0, 10, 0)}};
    double a = 0.0;
    for (int w = 0; w < 3; ++w)
        a += ao_polygon_form_factor(p, n, walls[w], 4);
    return a;
}

/* Every covered pixel with P.Y == 0 (floor_only) or any covered pixel, compared with 1 - exact. */
static void check_against_reference(const char *spec, exact_fn exact, int floor_only, int min_pixels)
{
    gt_error e;
    scene s;
    camera cam;
    image img;
    render_stats stats;
    CHECK_MSG(scene_load(spec, &s, &e) == 0, "%s", e.message);
    CHECK(scene_choose_camera(&s, NULL, SIZE, SIZE, &cam, &e) == 0);
    reference_request req = {.quantity = QUANTITY_AO, .sampling = {.spp = SPP, .seed = 5, .threads = 2},
                             .normals = NORMAL_SHADING};
    CHECK_MSG(reference_render(&s, spec, &cam, &req, &img, &stats, &e) == 0, "%s", e.message);
    const float *mask = image_channel_data(&img, CH_MASK), *v = image_channel_data(&img, CH_AO);
    const float *ve = image_channel_data(&img, CH_AO_STDERR);
    const float *p[3] = {image_channel_data(&img, CH_P_X), image_channel_data(&img, CH_P_Y),
                         image_channel_data(&img, CH_P_Z)};
    const float *n[3] = {image_channel_data(&img, CH_N_X), image_channel_data(&img, CH_N_Y),
                         image_channel_data(&img, CH_N_Z)};
    int compared = 0, outliers = 0;
    for (size_t i = 0; i < image_pixel_count(&img); ++i) {
        if (mask[i] == 0.0f || (floor_only && p[1][i] != 0.0f))
            continue;
        double expected = 1.0 - exact(v3(p[0][i], p[1][i], p[2][i]), v3(n[0][i], n[1][i], n[2][i]));
        double se = fmax(ve[i], sqrt(fmax(expected * (1 - expected), 0) / SPP));
        outliers += fabs(v[i] - expected) > 4 * fmax(se, 1e-7);
        ++compared;
    }
    CHECK_MSG(compared > min_pixels && outliers == 0, "%s: %d of %d pixels beyond 4 stderr", spec, outliers, compared);
    image_free(&img);
    scene_free(&s);
}

static void check_unit_space(void)
{
    ao_decal_volume vol = {v3(0.3f, 0.8f, -0.2f), v3(1.6f, 0.5f, 0.5f)};
    vec3 n = v3_normalize(v3(0.3f, 1.0f, 0.4f)), t = v3_normalize(v3_cross(n, v3(1, 0, 0))), pos, norm;
    ao_decal_unit_space(v3(1.0f, 0.0f, 2.0f), n, &vol, &pos, &norm);
    vec3 mapped = v3(t.x / vol.half.x, t.y / vol.half.y, t.z / vol.half.z);
    CHECK_NEAR(v3_dot(mapped, norm), 0.0, 1e-6);
    CHECK_NEAR(v3_length(norm), 1.0, 1e-6);
    CHECK_NEAR(pos.x, (1.0 - 0.3) / 1.6, 1e-6);
    CHECK_NEAR(pos.y, -0.8 / 0.5, 1e-6);
}

static void check_table_matches_meshes(void)
{
    for (int i = 0; i < ao_decal_scene_count(); ++i) {
        const ao_decal_scene *d = ao_decal_scene_at(i);
        scene s;
        gt_error e;
        char spec[64];
        snprintf(spec, sizeof spec, "builtin:%s", d->name);
        CHECK_MSG(scene_load(spec, &s, &e) == 0, "%s", e.message);
        float top = d->corner ? 10.0f : 0.0f;
        for (int k = 0; k < d->occluder_count; ++k)
            top = fmaxf(top, d->occluders[k].centre.y + d->occluders[k].half.y);
        vec3 lo, hi;
        scene_bounds(&s, &lo, &hi);
        CHECK_NEAR(hi.y, top, 1e-5);
        scene_free(&s);
    }
}

int main(void)
{
    check_unit_space();
    check_table_matches_meshes();
    check_against_reference("builtin:box-on-plane", box_on_plane, 1, 200);
    check_against_reference("builtin:corner", corner_walls, 0, 500);
    return check_report("test_ao_decals_scenes");
}
