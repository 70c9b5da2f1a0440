/* Frames with depth and motion vectors (frames_render.h). */
#include "anti_aliasing/frames_render.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene/camera_path.h"

int frame_buffers_alloc(frame_buffers *f, int width, int height)
{
    size_t px = (size_t)width * height;
    f->rgb = malloc(3 * px * sizeof(float));
    f->depth = malloc(px * sizeof(float));
    f->motion = malloc(2 * px * sizeof(float));
    f->disoccluded = malloc(px);
    if (f->rgb && f->depth && f->motion && f->disoccluded)
        return 0;
    frame_buffers_free(f);
    return -1;
}

void frame_buffers_free(frame_buffers *f)
{
    free(f->rgb), free(f->depth), free(f->motion), free(f->disoccluded);
    memset(f, 0, sizeof *f);
}

/* 1 if nothing lies between the previous camera's origin and p. */
static int seen_from(const embree_scene *es, const camera_view *prev, vec3 p)
{
    vec3 d = v3_sub(p, prev->origin);
    float distance = v3_length(d);
    struct RTCRay ray;
    embree_ray_init(&ray, prev->origin, v3_scale(d, 1.0f / distance), distance * (1.0f - 1e-4f));
    embree_unoccluded_stream(es, &ray, 1);
    return ray.tfar >= 0.0f;
}

/* Motion and disocclusion of the sample at xy that saw hit (or the sky along d). */
static void reproject(const embree_scene *es, const camera_view *prev, const float xy[2], const surface_hit *hit,
                      vec3 d, float motion[2], unsigned char *disoccluded)
{
    float at[2] = {xy[0], xy[1]};
    float depth = hit ? camera_project(prev, hit->p, at) : camera_project_direction(prev, d, at);
    int inside = depth > 0.0f && at[0] >= 0.0f && at[0] <= prev->width && at[1] >= 0.0f && at[1] <= prev->height;
    motion[0] = depth > 0.0f ? at[0] - xy[0] : 0.0f;
    motion[1] = depth > 0.0f ? at[1] - xy[1] : 0.0f;
    *disoccluded = hit && (!inside || !seen_from(es, prev, hit->p));
}

static void render_pixel(const embree_scene *es, const camera_view *view, const camera_view *prev,
                         const frame_lighting *light, const float xy[2], size_t k, frame_buffers *out)
{
    surface_hit hit;
    int seen = shaded_frame_sample(es, view, light, xy[0], xy[1], out->rgb + 3 * k, &hit);
    out->depth[k] = seen ? camera_depth(view, hit.p) : 0.0f;
    out->motion[2 * k] = out->motion[2 * k + 1] = 0.0f, out->disoccluded[k] = 0;
    if (prev) {
        vec3 o, d;
        camera_ray(view, xy[0], xy[1], &o, &d);
        reproject(es, prev, xy, seen ? &hit : NULL, d, out->motion + 2 * k, &out->disoccluded[k]);
    }
}

void frames_render(const embree_scene *es, const camera *cam, const camera *previous, const frame_lighting *light,
                   const float jitter[2], int threads, frame_buffers *out)
{
    camera_view view = camera_view_from(cam), prev = previous ? camera_view_from(previous) : view;
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads)
    for (int j = 0; j < cam->height; ++j)
        for (int i = 0; i < cam->width; ++i) {
            float xy[2] = {i + 0.5f + jitter[0], j + 0.5f + jitter[1]};
            render_pixel(es, &view, previous ? &prev : NULL, light, xy, (size_t)j * cam->width + i, out);
        }
}
