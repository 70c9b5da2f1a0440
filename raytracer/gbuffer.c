#include "raytracer/gbuffer.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene/material_lookup.h"
#include "core/reference_schema.h"

int gbuffer_render(const embree_scene *es, const camera *cam, normal_mode normals, int threads, gbuffer *gb,
                   gt_error *e)
{
    memset(gb, 0, sizeof *gb);
    gb->width = cam->width;
    gb->height = cam->height;
    gb->view = camera_view_from(cam);
    size_t n = (size_t)cam->width * (size_t)cam->height;
    gb->hits = calloc(n, sizeof *gb->hits);
    gb->mask = calloc(n, 1);
    if (!gb->hits || !gb->mask) {
        gbuffer_free(gb);
        return gt_error_set(e, "gbuffer", "out of memory for %dx%d pixels", cam->width, cam->height);
    }
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads)
    for (int y = 0; y < gb->height; ++y) {
        for (int x = 0; x < gb->width; ++x) {
            size_t i = (size_t)y * (size_t)gb->width + (size_t)x;
            vec3 o, d;
            camera_ray(&gb->view, (float)x + 0.5f, (float)y + 0.5f, &o, &d);
            gb->mask[i] = (unsigned char)embree_closest_hit(es, o, d, INFINITY, &gb->hits[i]);
            if (!gb->mask[i])
                gb->hits[i] = (surface_hit){.t = INFINITY, .mesh = -1, .triangle = -1};
            if (gb->mask[i] && normals == NORMAL_GEOMETRIC)
                gb->hits[i].ns = gb->hits[i].ng;
        }
    }
    return 0;
}

int gbuffer_write_channels(const gbuffer *gb, const scene *s, image *img)
{
    static const char *const names[] = {CH_DEPTH, CH_N_X, CH_N_Y, CH_N_Z, CH_NG_X, CH_NG_Y, CH_NG_Z, CH_P_X, CH_P_Y,
                                        CH_P_Z, CH_ALBEDO_R, CH_ALBEDO_G, CH_ALBEDO_B, CH_ROUGHNESS, CH_MASK};
    enum { COUNT = sizeof names / sizeof names[0] };
    float *ch[COUNT];
    for (int c = 0; c < COUNT; ++c)
        if (!(ch[c] = image_add_channel(img, names[c])))
            return -1;
    for (size_t i = 0; i < (size_t)gb->width * (size_t)gb->height; ++i) {
        if (!gb->mask[i])
            continue; /* background stays 0, mask.A = 0 */
        const surface_hit *h = &gb->hits[i];
        material_sample m = material_lookup(s, h->mesh, h->uv);
        const float values[COUNT] = {camera_depth(&gb->view, h->p), h->ns.x, h->ns.y, h->ns.z, h->ng.x, h->ng.y,
                                     h->ng.z, h->p.x, h->p.y, h->p.z, m.base_color[0], m.base_color[1],
                                     m.base_color[2], m.roughness, 1.0f};
        for (int c = 0; c < COUNT; ++c)
            ch[c][i] = values[c];
    }
    return 0;
}

long gbuffer_covered_pixels(const gbuffer *gb)
{
    long covered = 0;
    for (int i = 0; i < gb->width * gb->height; ++i)
        covered += gb->mask[i];
    return covered;
}

void gbuffer_free(gbuffer *gb)
{
    free(gb->hits);
    free(gb->mask);
    memset(gb, 0, sizeof *gb);
}
