/* The volumetric-light study's scene, rays and reference; see volumetric_light_setup.h. */
#include "volumetric_light/volumetric_light_setup.h"

#include <stdlib.h>
#include <string.h>

#include "project/study_context.h"

static int fill_view(volumetric_light_setup *v, gt_error *e)
{
    long n = (long)v->gb.width * v->gb.height;
    v->dir = calloc((size_t)(3 * n), sizeof(float));
    v->distance = calloc((size_t)n, sizeof(float));
    v->mask = calloc((size_t)n, sizeof(float));
    if (!v->dir || !v->distance || !v->mask)
        return gt_error_set(e, VLIGHT_SCENE, "out of memory");
    vec3 eye = v->gb.view.origin;
    for (long p = 0; p < n; ++p) {
        if (!v->gb.mask[p])
            continue;
        vec3 d = v3_sub(v->gb.hits[p].p, eye);
        float length = v3_length(d);
        v3_store(&v->dir[3 * p], v3_scale(d, 1.0f / length));
        v->distance[p] = length;
        v->mask[p] = 1.0f;
    }
    v->view = (raymarch_view){v->gb.width, v->gb.height, eye, v->dir, v->distance};
    return 0;
}

static int place_light(volumetric_light_setup *v, gt_error *e)
{
    volumetric_light_settings settings;
    volumetric_light_settings_default(&settings);
    vec3 lo, hi;
    scene_bounds(&v->s, &lo, &hi);
    return volumetric_light_resolve(&settings, lo, hi, &v->light, &v->medium, e);
}

int volumetric_light_setup_init(volumetric_light_setup *v, int width, int height, int threads, gt_error *e)
{
    memset(v, 0, sizeof *v);
    camera cam;
    if (study_load_view(VLIGHT_SCENE, width, height, &v->s, &cam, e) != 0)
        return -1;
    if (embree_scene_build(&v->s, &v->es, e) != 0) {
        scene_free(&v->s);
        return -1;
    }
    if (gbuffer_render(&v->es, &cam, NORMAL_GEOMETRIC, threads, &v->gb, e) != 0) {
        embree_scene_release(&v->es);
        scene_free(&v->s);
        return -1;
    }
    if (fill_view(v, e) != 0 || place_light(v, e) != 0) {
        volumetric_light_setup_free(v);
        return -1;
    }
    return 0;
}

void volumetric_light_setup_free(volumetric_light_setup *v)
{
    free(v->dir), free(v->distance), free(v->mask);
    gbuffer_free(&v->gb);
    embree_scene_release(&v->es);
    scene_free(&v->s);
    memset(v, 0, sizeof *v);
}

long volumetric_light_reference(const volumetric_light_setup *v, double rel_tol, int threads, float *reference, float *error)
{
    volumetric_lighting l = {&v->light, &v->medium, &v->es};
    long n = (long)v->gb.width * v->gb.height, rays = 0;
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads > 0 ? threads : 1) reduction(+ : rays)
    for (long p = 0; p < n; ++p) {
        volumetric_ray_estimate q = {{0.0}, {0.0}, 0};
        if (v->mask[p] != 0.0f)
            volumetric_light_quadrature(&l, v->view.eye, v3_load(&v->dir[3 * p]), v->distance[p], rel_tol, &q);
        if (reference)
            reference[p] = (float)(q.radiance[0] / v->light.intensity[0]);
        if (error)
            error[p] = (float)(q.error[0] / v->light.intensity[0]);
        rays += q.rays;
    }
    return rays;
}
