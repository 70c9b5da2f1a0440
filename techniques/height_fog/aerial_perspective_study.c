/* The combination images of the Decima height fog; see aerial_perspective.h. */
#include "height_fog/aerial_perspective_study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/progress.h"
#include "raytracer/embree_scene.h"
#include "raytracer/gbuffer.h"
#include "height_fog/aerial_perspective_parts.h"
#include "height_fog/height_fog_quality.h"

static const char *const weathers[2] = {"sunny", "dense"};

aerial_perspective_request aerial_perspective_default_request(study_quality quality)
{
    const height_fog_quality *q = height_fog_quality_of(quality);
    atmosphere_method method = q->reference_transmittances ? ATMOSPHERE_REFERENCE : ATMOSPHERE_ADAPTIVE;
    aerial_perspective_request rq = {q->aerial_width, q->aerial_height, q->fisheye_size, AERIAL_SUNS, {5.0, 20.0, 60.0},
                                     q->reference_tolerance, method, atmosphere_lut_sizes_talk(),
                                     {{32, 128, 8, 2}, {64, 1, 1, 2}, {64, 1, 1, 2}}};
    return rq;
}

/* ---- The atmosphere: one precomputation per blend of the LUTs' t axes ---- */

typedef struct {
    int count;
    atmosphere_solution *solutions;
    atmosphere_luts luts, fine;
} aerial_atmosphere;

static void atmosphere_free(aerial_atmosphere *a)
{
    for (int k = 0; k < a->count; ++k)
        atmosphere_solution_free(&a->solutions[k]);
    free(a->solutions);
    atmosphere_luts_free(&a->luts);
    atmosphere_luts_free(&a->fine);
    memset(a, 0, sizeof *a);
}

static int atmosphere_prepare(const aerial_perspective_request *rq, int threads, aerial_atmosphere *a, gt_error *e)
{
    double t[3 * ATMOSPHERE_LUT_MAX_AXIS];
    char msg[256];
    memset(a, 0, sizeof *a);
    if (atmosphere_lut_sizes_check(&rq->sizes, msg, sizeof msg) != 0 ||
        atmosphere_lut_sizes_check(&rq->fine, msg, sizeof msg) != 0)
        return gt_error_set(e, "aerial perspective", "%s", msg);
    int n = atmosphere_lut_blends(&rq->sizes, t);
    atmosphere_model m = atmosphere_model_default();
    a->solutions = calloc((size_t)n, sizeof *a->solutions);
    for (int k = 0; a->solutions && k < n; ++k, ++a->count)
        if (atmosphere_solve(&m, t[k], threads, &a->solutions[k]) != 0)
            break;
    if (!a->solutions || a->count < n) {
        atmosphere_free(a);
        return gt_error_set(e, "aerial perspective", "out of memory");
    }
    if (atmosphere_luts_build_from(&a->luts, a->solutions, n, &rq->sizes, threads, msg, sizeof msg) != 0 ||
        atmosphere_luts_build_from(&a->fine, a->solutions, n, &rq->fine, threads, msg, sizeof msg) != 0) {
        atmosphere_free(a);
        return gt_error_set(e, "aerial perspective", "%s", msg);
    }
    return 0;
}

/* ---- The terrain's rays -------------------------------------------------- */

static void fill_view_rays(const gbuffer *gb, aerial_rays *rays)
{
    rays->camera_y = gb->view.origin.y;
    for (int j = 0; j < gb->height; ++j)
        for (int i = 0; i < gb->width; ++i) {
            size_t k = (size_t)j * gb->width + i;
            vec3 o, d;
            camera_ray(&gb->view, i + 0.5f, j + 0.5f, &o, &d);
            v3_store(&rays->dir[3 * k], d);
            rays->inside[k] = 1.0f;
            rays->terrain[k] = gb->mask[k] ? 1.0f : 0.0f;
            rays->length[k] = gb->mask[k] ? gb->hits[k].t : 0.0f;
            rays->surface_y[k] = gb->mask[k] ? gb->hits[k].p.y : 0.0f;
        }
}

static int terrain_rays(const aerial_perspective_request *rq, int threads, aerial_rays *rays, gt_error *e)
{
    scene s;
    camera cam;
    embree_scene es;
    gbuffer gb;
    if (study_load_view("builtin:terrain", rq->width, rq->height, &s, &cam, e) != 0)
        return -1;
    if (embree_scene_build(&s, &es, e) != 0) {
        scene_free(&s);
        return -1;
    }
    int rc = gbuffer_render(&es, &cam, NORMAL_GEOMETRIC, threads, &gb, e);
    if (rc == 0) {
        if ((rc = aerial_rays_alloc(rays, rq->width, rq->height)) != 0)
            gt_error_set(e, "aerial perspective", "out of memory");
        else
            fill_view_rays(&gb, rays);
        gbuffer_free(&gb);
    }
    embree_scene_release(&es);
    scene_free(&s);
    return rc == 0 ? 0 : -1;
}

/* ---- The cases ------------------------------------------------------------ */

/* One image of a case: render, score (view: is_view), write. */
static int run_image(const aerial_light *light, const aerial_rays *rays, const aerial_perspective_request *rq,
                     int threads, const char *dir, const char *kind, aerial_case *c, gt_error *e)
{
    aerial_planes planes;
    if (aerial_planes_alloc(&planes, (size_t)rays->width * rays->height) != 0)
        return gt_error_set(e, "aerial perspective", "out of memory");
    aerial_render(light, rays, rq, threads, &planes);
    c->reference_error = fmax(c->reference_error, planes.reference_error);
    int is_view = strcmp(kind, "aerial") == 0, rc = aerial_score(rays, &planes, is_view, c, e);
    if (rc == 0)
        rc = aerial_write(dir, kind, rays, &planes, c, e);
    if (rc == 0 && !is_view) { /* the sky again from the finer tables */
        aerial_light fine = *light;
        fine.luts = light->fine;
        aerial_render_models(&fine, rays, threads, &planes);
        rc = aerial_score_fine(rays, &planes, c, e);
    }
    aerial_planes_free(&planes);
    return rc;
}

static int run_case(const aerial_atmosphere *a, const aerial_rays *view, const aerial_rays *fisheye,
                    const aerial_perspective_request *rq, int threads, const char *dir, int weather, int sun,
                    aerial_case *c, gt_error *e)
{
    height_fog_param p;
    height_fog_weather(weathers[weather], rq->sun_elevations[sun], &p); /* the fog study's sun direction */
    memset(c, 0, sizeof *c);
    snprintf(c->weather, sizeof c->weather, "%s", weathers[weather]);
    c->sun_elevation_deg = rq->sun_elevations[sun];
    c->fog_scale_height = aerial_fog_scale_height(&a->luts.model, weather, view->camera_y);
    aerial_light light = {atmosphere_solution_find(a->solutions, a->count, weather), &a->luts, &a->fine, weather,
                          p.sun_direction};
    if (!light.solution)
        return gt_error_set(e, "aerial perspective", "the LUTs' t axes do not hold t = %d", weather);
    if (run_image(&light, view, rq, threads, dir, "aerial", c, e) != 0)
        return -1;
    return run_image(&light, fisheye, rq, threads, dir, "fisheye", c, e);
}

static int request_check(const aerial_perspective_request *rq, gt_error *e)
{
    int ok = rq->width >= 11 && rq->height >= 11 && rq->fisheye >= 11 && rq->sun_count >= 1 &&
             rq->sun_count <= AERIAL_SUNS && rq->tolerance > 0.0;
    for (int k = 0; ok && k < rq->sun_count; ++k)
        ok = rq->sun_elevations[k] > 0.0 && rq->sun_elevations[k] <= 90.0;
    ok = ok && rq->sizes.inscatter[3] >= 2 && rq->sizes.sun[3] >= 2 && rq->sizes.sky[3] >= 2;
    return ok ? 0
              : gt_error_set(e, "aerial perspective", "images at least 11 pixels, 1..%d suns in (0, 90] degrees, "
                                                      "a positive tolerance and t axes of 2 or more points",
                             AERIAL_SUNS);
}

static int run_cases(const aerial_atmosphere *a, const aerial_rays *view, const aerial_rays *fisheye,
                     const aerial_perspective_request *rq, int threads, const char *dir, aerial_perspective_result *out,
                     gt_error *e)
{
    for (int w = 0; w < 2; ++w)
        for (int k = 0; k < rq->sun_count; ++k)
            if (run_case(a, view, fisheye, rq, threads, dir, w, k, &out->cases[out->case_count++], e) != 0)
                return -1;
    return 0;
}

int aerial_perspective_study(const study_context *ctx, const char *dir, const aerial_perspective_request *rq,
                             aerial_perspective_result *out, gt_error *e)
{
    double start = seconds_now();
    memset(out, 0, sizeof *out);
    out->request = *rq;
    aerial_atmosphere a;
    aerial_rays view, fisheye;
    if (request_check(rq, e) != 0 || atmosphere_prepare(rq, ctx->threads, &a, e) != 0)
        return -1;
    int rc = terrain_rays(rq, ctx->threads, &view, e);
    if (rc == 0 && aerial_rays_alloc(&fisheye, rq->fisheye, rq->fisheye) != 0)
        rc = gt_error_set(e, "aerial perspective", "out of memory"), aerial_rays_free(&view);
    if (rc == 0) {
        aerial_fisheye_rays(&fisheye);
        rc = run_cases(&a, &view, &fisheye, rq, ctx->threads, dir, out, e);
        aerial_rays_free(&view), aerial_rays_free(&fisheye);
    }
    atmosphere_free(&a);
    out->seconds = seconds_now() - start;
    return rc == 0 ? 0 : -1;
}
