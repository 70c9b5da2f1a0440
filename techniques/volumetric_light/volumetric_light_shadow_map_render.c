/* A spot light's shadow map by Embree; see volumetric_light_shadow_map_render.h. */
#include "volumetric_light/volumetric_light_shadow_map_render.h"

#include <math.h>
#include <string.h>

/* The closest hits of the map's texel rays. */
static void fill_map(const embree_scene *es, int threads, shadow_map *m)
{
    int size = m->size;
#pragma omp parallel for schedule(static) num_threads(threads > 0 ? threads : 1)
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            surface_hit hit;
            vec3 d = shadow_map_direction(m, i + 0.5, j + 0.5);
            if (embree_closest_hit(es, m->position, d, INFINITY, &hit))
                m->distance[(long)j * size + i] = hit.t;
        }
}

int shadow_map_render(const embree_scene *es, const volumetric_light *spot, int size, double bias, int threads,
                      shadow_map *m, gt_error *e)
{
    if (spot->kind != VOLUMETRIC_SPOT_LIGHT)
        return gt_error_set(e, "shadow map", "only a spot light has a single-frustum shadow map");
    double half_deg = acos(spot->cos_outer) * 180.0 / M_PI;
    if (shadow_map_alloc(m, size, spot->position, spot->axis, half_deg, bias, e) != 0)
        return -1;
    fill_map(es, threads, m);
    return 0;
}

int shadow_cube_render(const embree_scene *es, const volumetric_light *light, int size, double bias, int threads,
                       shadow_cube *c, gt_error *e)
{
    memset(c, 0, sizeof *c);
    for (int k = 0; k < 6; ++k) {
        if (shadow_map_alloc(&c->face[k], size, light->position, shadow_cube_axis(k), 45.0, bias, e) != 0) {
            shadow_cube_free(c);
            return -1;
        }
        fill_map(es, threads, &c->face[k]);
    }
    return 0;
}
