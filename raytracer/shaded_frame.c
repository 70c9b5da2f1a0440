/* Shaded frames (shaded_frame.h). */
#include "raytracer/shaded_frame.h"

#include <math.h>

#include "scene/material_lookup.h"

frame_lighting frame_lighting_default(void)
{
    frame_lighting l = {v3_normalize(v3(0.45f, 0.77f, 0.45f)), {3.0f, 2.8f, 2.5f}, {0.35f, 0.45f, 0.6f},
                        {0.5f, 0.65f, 0.85f}};
    return l;
}

static int sun_visible(const embree_scene *es, const surface_hit *h, vec3 l)
{
    struct RTCRay ray;
    embree_ray_init(&ray, offset_ray_origin(h->p, h->ng), l, INFINITY);
    embree_unoccluded_stream(es, &ray, 1);
    return ray.tfar >= 0.0f;
}

/* L leaving surface point h towards the camera. */
static void shade_hit(const embree_scene *es, const frame_lighting *light, const surface_hit *h, float out[3])
{
    material_sample m = material_lookup(es->source, h->mesh, h->uv);
    float cos_l = v3_dot(h->ns, light->sun_direction), sky = 0.5f + 0.5f * h->ns.y;
    float sun = cos_l > 0.0f && v3_dot(h->ng, light->sun_direction) > 0.0f && sun_visible(es, h, light->sun_direction)
                    ? cos_l : 0.0f;
    for (int c = 0; c < 3; ++c)
        out[c] = m.base_color[c] * (light->sun[c] * sun + light->sky[c] * sky);
}

int shaded_frame_sample(const embree_scene *es, const camera_view *view, const frame_lighting *light, float x, float y,
                        float out[3], surface_hit *hit)
{
    vec3 o, d;
    camera_ray(view, x, y, &o, &d);
    surface_hit local, *h = hit ? hit : &local;
    if (!embree_closest_hit(es, o, d, INFINITY, h)) {
        for (int c = 0; c < 3; ++c)
            out[c] = light->background[c];
        return 0;
    }
    shade_hit(es, light, h, out);
    return 1;
}

static void shade_sample(const embree_scene *es, const camera_view *view, const frame_lighting *light, float x, float y,
                         float out[3])
{
    shaded_frame_sample(es, view, light, x, y, out, NULL);
}

void shaded_frame_render(const embree_scene *es, const camera *cam, const frame_lighting *light,
                         const float offset[2], int threads, float *rgb)
{
    camera_view view = camera_view_from(cam);
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads)
    for (int j = 0; j < cam->height; ++j)
        for (int i = 0; i < cam->width; ++i)
            shade_sample(es, &view, light, i + 0.5f + offset[0], j + 0.5f + offset[1],
                         rgb + 3 * ((size_t)j * cam->width + i));
}

/* A uniform number in [0, 1) from three integers (SplitMix64 finaliser). */
static float hash_uniform(unsigned long long a, unsigned long long b, unsigned long long c)
{
    unsigned long long x = a * 0x9E3779B97F4A7C15ull ^ (b + 0x632BE59BD9B4E019ull) * 0xBF58476D1CE4E5B9ull ^ c;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return (float)((x ^ (x >> 31)) >> 40) * 0x1.0p-24f;
}

void shaded_frame_render_supersampled(const embree_scene *es, const camera *cam, const frame_lighting *light, int s,
                                      unsigned seed, int threads, float *rgb, float *xy)
{
    camera_view view = camera_view_from(cam);
    int w = cam->width * s, h = cam->height * s;
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads)
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            unsigned long long id = (unsigned long long)j * (unsigned long long)w + (unsigned long long)i;
            float x = (i + hash_uniform(id, seed, 1)) / (float)s, y = (j + hash_uniform(id, seed, 2)) / (float)s;
            shade_sample(es, &view, light, x, y, rgb + 3 * ((size_t)j * w + i));
            if (xy)
                xy[2 * ((size_t)j * w + i)] = x, xy[2 * ((size_t)j * w + i) + 1] = y;
        }
}
