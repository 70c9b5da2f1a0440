/* The multi-bounce integrator's wavefront (one Embree stream per depth,
 * occlusion queries at the last depth, hits reading only the surface parts
 * they need) against the per-ray loop it replaced, kept here as the
 * reference: one rtcIntersect1 per ray through embree_closest_hit (every
 * part of the hit), one Sobol' point and one direction at a time, each path
 * carrying its own throughputs. Both must give the same bits for every
 * sample of every quantity, and the same ray count, in every pixel: grey
 * albedo lists and the scene's (a textured material included), fixed depths
 * 0, 1, 4 and Russian roulette, shading and geometric normals, batches that
 * start at odd sequence indices. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/sampling/hemisphere_sampling.h"
#include "multibounce/multibounce_integrator.h"
#include "scene/material_lookup.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

/* ---- The reference: the per-ray loop --------------------------------------------------- */

typedef struct {
    vec3 origin, ng;
    frame shading;
    float throughput[MULTIBOUNCE_MAX_ALBEDOS];
    int sample;
} reference_path;

static int reference_weights(const multibounce_plan *plan)
{
    return plan->settings.scene_albedo ? 3 : plan->settings.albedo_count;
}

static void reference_albedos(const multibounce_plan *plan, const scene *s, const surface_hit *hit, float *rho)
{
    if (!plan->settings.scene_albedo) {
        memcpy(rho, plan->settings.albedos, sizeof(float) * (size_t)plan->settings.albedo_count);
        return;
    }
    material_sample m = material_lookup(s, hit->mesh, hit->uv);
    for (int c = 0; c < 3; ++c)
        rho[c] = fminf(fmaxf(m.base_color[c], 0.0f), 1.0f);
}

static int reference_survives(const multibounce_plan *plan, const float *rho, float u, reference_path *p)
{
    int weights = reference_weights(plan);
    if (plan->settings.bounces != MULTIBOUNCE_UNLIMITED) {
        for (int w = 0; w < weights; ++w)
            p->throughput[w] *= rho[w];
        return 1;
    }
    float q = 0.0f;
    for (int w = 0; w < weights; ++w)
        q = fmaxf(q, rho[w]);
    if (!(u < q))
        return 0;
    for (int w = 0; w < weights; ++w)
        p->throughput[w] *= rho[w] / q;
    return 1;
}

/* One path of the reference from its current vertex at `depth`: returns 1
 * and moves it to its next vertex if it goes on. */
static int reference_step(const integrator *self, const pixel_context *px, uint32_t first_index, int depth,
                          reference_path *p, float *values, int *rays)
{
    const multibounce_plan *plan = self->settings;
    const int weights = reference_weights(plan), unlimited = plan->settings.bounces == MULTIBOUNCE_UNLIMITED;
    const sample_pair_seeds directions = sample_pair_seeds_for(px, (uint32_t)depth);
    const sample_pair_seeds roulette = sample_pair_seeds_for(px, MULTIBOUNCE_ROULETTE_PAIRS + (uint32_t)depth + 1);
    uint32_t index = first_index + (uint32_t)p->sample;
    float u[2], r[2] = {0.0f, 0.0f};
    sample_pair_point(&directions, index, u);
    vec3 d = frame_to_world(&p->shading, sample_cosine_hemisphere(u));
    if (v3_dot(d, p->ng) <= 0.0f)
        return 0;
    surface_hit hit;
    ++*rays;
    if (!embree_closest_hit(self->scene, p->origin, d, INFINITY, &hit)) {
        for (int w = 0; w < weights; ++w)
            values[w * SAMPLE_BATCH + p->sample] = p->throughput[w];
        values[weights * SAMPLE_BATCH + p->sample] = depth == 0 ? 1.0f : 0.0f;
        return 0;
    }
    if (depth == (unlimited ? MULTIBOUNCE_PATH_LIMIT : plan->settings.bounces))
        return 0;
    float rho[MULTIBOUNCE_MAX_ALBEDOS];
    reference_albedos(plan, self->scene->source, &hit, rho);
    if (unlimited)
        sample_pair_point(&roulette, index, r);
    if (!reference_survives(plan, rho, r[0], p))
        return 0;
    p->origin = offset_ray_origin(hit.p, hit.ng);
    p->ng = hit.ng;
    p->shading = frame_from_normal(plan->normals == NORMAL_GEOMETRIC ? hit.ng : hit.ns);
    return 1;
}

static int reference_sample_batch(const integrator *self, const pixel_context *px, uint32_t first_index, int count,
                                  float *values)
{
    const multibounce_plan *plan = self->settings;
    reference_path paths[SAMPLE_BATCH];
    memset(values, 0, sizeof(float) * (size_t)plan->quantity_count * SAMPLE_BATCH);
    for (int k = 0; k < count; ++k) {
        paths[k] = (reference_path){px->ray_origin, px->surface->ng, px->shading, {0}, k};
        for (int w = 0; w < reference_weights(plan); ++w)
            paths[k].throughput[w] = 1.0f;
    }
    int live = count, rays = 0;
    for (int depth = 0; live > 0; ++depth) {
        int kept = 0;
        for (int i = 0; i < live; ++i)
            if (reference_step(self, px, first_index, depth, &paths[i], values, &rays))
                paths[kept++] = paths[i];
        live = kept;
    }
    return rays;
}

/* ---- The comparison ---------------------------------------------------------------- */

/* Every covered pixel of a size x size view: the batches [0, 64) and
 * [37, 64) (an odd first index, a short batch), value for value. */
static void compare_view(const scene *s, const camera *cam, multibounce_settings mb, normal_mode normals,
                         const char *label)
{
    gt_error e;
    embree_scene es;
    gbuffer gb;
    multibounce_plan plan;
    if (multibounce_plan_init(&plan, &mb, normals, &e) != 0 || embree_scene_build(s, &es, &e) != 0) {
        CHECK_MSG(0, "%s: %s", label, e.message);
        return;
    }
    CHECK(gbuffer_render(&es, cam, normals, 1, &gb, &e) == 0);
    integrator wavefront = multibounce_integrator(&es, &plan), reference = wavefront;
    reference.sample_batch = reference_sample_batch;
    static float a[SAMPLE_BATCH * MULTIBOUNCE_MAX_QUANTITIES], b[SAMPLE_BATCH * MULTIBOUNCE_MAX_QUANTITIES];
    const size_t bytes = sizeof(float) * SAMPLE_BATCH * (size_t)plan.quantity_count;
    int pixels = 0, differing = 0;
    long rays = 0;
    for (int i = 0; i < gb.width * gb.height; ++i) {
        if (!gb.mask[i])
            continue;
        pixel_context px = pixel_context_at(&gb, i, 5u);
        for (uint32_t first = 0; first < 64; first += 37) {
            int count = 64 - (int)first;
            int rays_a = wavefront.sample_batch(&wavefront, &px, first, count, a);
            int rays_b = reference.sample_batch(&reference, &px, first, count, b);
            differing += rays_a != rays_b || memcmp(a, b, bytes) != 0;
            rays += rays_b;
        }
        ++pixels;
    }
    CHECK_MSG(pixels > 50 && rays > 64L * pixels, "%s: too little compared (%d pixels, %ld rays)", label,
              pixels, rays);
    CHECK_MSG(differing == 0, "%s: %d batches differ from the per-ray loop", label, differing);
    gbuffer_free(&gb);
    embree_scene_release(&es);
}

static multibounce_settings settings_of(const char *albedos, int bounces)
{
    multibounce_settings s = {0};
    gt_error e;
    CHECK(multibounce_parse_albedos(albedos, &s, &e) == 0);
    s.bounces = bounces;
    return s;
}

/* A 2 x 2 texture of distinct colours on mesh 0's material, with texcoords
 * from the positions (wrapping), so the scene albedo varies within faces. */
static void add_texture(scene *s)
{
    scene_mesh *m = &s->meshes[0];
    unsigned char *rgba = malloc(16);
    scene_texture *t = realloc(s->textures, sizeof *t * (size_t)(s->texture_count + 1));
    m->texcoords = malloc(sizeof(float) * 2 * m->vertex_count);
    CHECK(rgba && t && m->texcoords);
    static const unsigned char texels[16] = {250, 40, 40, 255, 40, 250, 40, 255, 40, 40, 250, 255, 200, 200, 90, 255};
    memcpy(rgba, texels, sizeof texels);
    s->textures = t;
    s->textures[s->texture_count] = (scene_texture){2, 2, rgba};
    for (uint32_t v = 0; v < m->vertex_count; ++v) {
        m->texcoords[2 * v] = 0.37f * (m->positions[3 * v] + m->positions[3 * v + 1]);
        m->texcoords[2 * v + 1] = 0.29f * (m->positions[3 * v + 2] - m->positions[3 * v + 1]);
    }
    s->materials[m->material].base_color_texture = s->texture_count++;
}

static void load(const char *spec, int size, scene *s, camera *cam)
{
    gt_error e;
    if (scene_load(spec, s, &e) != 0 || scene_choose_camera(s, NULL, size, size, cam, &e) != 0)
        CHECK_MSG(0, "%s", e.message);
}

int main(void)
{
    scene s;
    camera cam;
    load("builtin:cornell", 16, &s, &cam);
    const int depths[4] = {0, 1, 4, MULTIBOUNCE_UNLIMITED};
    for (int d = 0; d < 4; ++d) {
        compare_view(&s, &cam, settings_of("0.1,0.5,0.9", depths[d]), NORMAL_SHADING, "cornell grey");
        compare_view(&s, &cam, settings_of("scene", depths[d]), NORMAL_SHADING, "cornell scene");
    }
    compare_view(&s, &cam, settings_of("1", MULTIBOUNCE_UNLIMITED), NORMAL_GEOMETRIC, "cornell albedo 1 geometric");
    CHECK(s.meshes[0].material >= 0);
    if (s.meshes[0].material >= 0) {
        add_texture(&s);
        compare_view(&s, &cam, settings_of("scene", 4), NORMAL_SHADING, "cornell textured");
        compare_view(&s, &cam, settings_of("scene", MULTIBOUNCE_UNLIMITED), NORMAL_GEOMETRIC, "cornell textured");
    }
    scene_free(&s);
    load("builtin:sphere-on-plane", 16, &s, &cam);
    compare_view(&s, &cam, settings_of("0.3,0.8", MULTIBOUNCE_UNLIMITED), NORMAL_SHADING, "sphere-on-plane");
    scene_free(&s);
    load("builtin:menger", 16, &s, &cam);
    compare_view(&s, &cam, settings_of("0.7", 4), NORMAL_GEOMETRIC, "menger");
    scene_free(&s);
    return check_report("test_multibounce_wavefront");
}
