/* The diffuse paths' wavefront: see the header. */
#include "raytracer/diffuse_path_wavefront.h"

#include <math.h>
#include <string.h>

#include "scene/material_lookup.h"

void path_wavefront_start(path_wavefront *wf, const embree_scene *scene, const pixel_context *px, uint32_t first_index,
                          int count, const multibounce_settings *albedo, normal_mode normals)
{
    wf->scene = scene;
    wf->px = px;
    wf->albedo = albedo;
    wf->normals = normals;
    wf->first_index = first_index;
    wf->count = wf->live = count;
    wf->weights = albedo->scene_albedo ? 3 : albedo->albedo_count;
    wf->unlimited = albedo->bounces == MULTIBOUNCE_UNLIMITED;
    wf->max_bounces = wf->unlimited ? MULTIBOUNCE_PATH_LIMIT : albedo->bounces;
    wf->surface_parts = (normals == NORMAL_SHADING ? SURFACE_SHADING_NORMAL : 0u) |
                        (albedo->scene_albedo ? SURFACE_TEXCOORDS : 0u);
    for (int k = 0; k < count; ++k) {
        path_vertex *p = &wf->paths[k];
        p->origin = px->ray_origin;
        p->ng = px->surface->ng;
        p->shading = px->shading; /* already on the geometric normal under NORMAL_GEOMETRIC (gbuffer.h) */
        p->sample = k;
    }
    for (int w = 0; w < wf->weights; ++w)
        for (int k = 0; k < count; ++k)
            wf->throughput[w][k] = 1.0f;
}

void path_wavefront_live_points(const path_wavefront *wf, uint32_t pair, float *u0, float *u1)
{
    const sample_pair_seeds seeds = sample_pair_seeds_for(wf->px, pair);
    if (4 * wf->live < wf->count) {
        for (int i = 0; i < wf->live; ++i) {
            float u[2];
            sample_pair_point(&seeds, wf->first_index + (uint32_t)wf->paths[i].sample, u);
            u0[i] = u[0], u1[i] = u[1];
        }
        return;
    }
    float all0[SAMPLE_BATCH], all1[SAMPLE_BATCH];
    sample_pair_points(&seeds, wf->first_index, wf->count, all0, all1);
    for (int i = 0; i < wf->live; ++i)
        u0[i] = all0[wf->paths[i].sample], u1[i] = all1[wf->paths[i].sample];
}

void path_wavefront_roulette(const path_wavefront *wf, int depth, float *u)
{
    float unused[SAMPLE_BATCH];
    path_wavefront_live_points(wf, MULTIBOUNCE_ROULETTE_PAIRS + (uint32_t)depth + 1, u, unused);
}

/* The albedos of a surface point, per weight. */
static void vertex_albedos(const path_wavefront *wf, const surface_hit *hit, float *rho)
{
    if (!wf->albedo->scene_albedo) {
        memcpy(rho, wf->albedo->albedos, sizeof(float) * (size_t)wf->albedo->albedo_count);
        return;
    }
    material_sample m = material_lookup(wf->scene->source, hit->mesh, hit->uv);
    for (int c = 0; c < 3; ++c)
        rho[c] = fminf(fmaxf(m.base_color[c], 0.0f), 1.0f);
}

/* Takes sample k's path through a new vertex of albedos rho: at fixed depth
 * the throughput is multiplied by rho; unlimited, the path survives Russian
 * roulette with probability q = max rho (u uniform in [0, 1)) and is
 * multiplied by rho / q. Returns 0 if the path ends here. */
static int path_survives(path_wavefront *wf, const float *rho, float u, int k)
{
    if (!wf->unlimited) {
        for (int w = 0; w < wf->weights; ++w)
            wf->throughput[w][k] *= rho[w];
        return 1;
    }
    float q = 0.0f;
    for (int w = 0; w < wf->weights; ++w)
        q = fmaxf(q, rho[w]);
    if (!(u < q))
        return 0;
    for (int w = 0; w < wf->weights; ++w)
        wf->throughput[w][k] *= rho[w] / q;
    return 1;
}

int path_wavefront_continue(path_wavefront *wf, const surface_hit *hit, float u, path_vertex *p)
{
    float rho[MULTIBOUNCE_MAX_ALBEDOS];
    vertex_albedos(wf, hit, rho);
    if (!path_survives(wf, rho, u, p->sample))
        return 0;
    p->origin = offset_ray_origin(hit->p, hit->ng);
    p->ng = hit->ng;
    p->shading = frame_from_normal(wf->normals == NORMAL_GEOMETRIC ? hit->ng : hit->ns);
    return 1;
}
