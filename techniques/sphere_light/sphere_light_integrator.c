#include "sphere_light/sphere_light_integrator.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/optics/fresnel.h"
#include "core/optics/ggx.h"
#include "sphere_light/sphere_light_reference.h"
#include "scene/material_lookup.h"
#include "core/reference_schema.h"

int sphere_light_plan_init(sphere_light_plan *plan, const sphere_light_settings *light, const scene *s, vec3 eye,
                           gt_error *e)
{
    if (!v3_is_finite(light->position))
        return gt_error_set(e, "sphere-light", "the light's position is not finite");
    if (!(light->radius > 0.0f) || !isfinite(light->radius))
        return gt_error_set(e, "sphere-light", "the light's radius must be positive");
    if (!(light->radiance > 0.0f) || !isfinite(light->radiance))
        return gt_error_set(e, "sphere-light", "the light's radiance must be positive");
    plan->light = *light;
    plan->eye = eye;
    /* Samples are of the order of the normal illuminance pi sin^2(sigma) L_e
     * at the closest point of the scene; 4x that bounds the diffuse ones
     * and keeps the grid of the means fine (larger specular samples take the
     * film's exact scalar path). The grid rounds a mean by 2^(E-25) at most,
     * absolutely; the standard errors do not depend on it (core/statistics/mc_film.h). */
    vec3 lo, hi;
    scene_bounds(s, &lo, &hi);
    vec3 nearest = v3_min(v3_max(light->position, lo), hi);
    float d = v3_length(v3_sub(nearest, light->position));
    double sin2 = d > light->radius ? (double)light->radius * light->radius / ((double)d * d) : 1.0;
    int exponent = (int)ceil(log2(4.0 * M_PI * sin2 * light->radiance));
    const char *names[3] = {CH_SPHERE_R, CH_SPHERE_G, CH_SPHERE_B};
    for (int c = 0; c < 3; ++c) {
        snprintf(plan->quantities[c].name, sizeof plan->quantities[c].name, "%s", names[c]);
        plan->quantities[c].scale_exponent = exponent;
    }
    return 0;
}

void sphere_light_settings_text(const sphere_light_settings *light, char *text, size_t size)
{
    snprintf(text, size, "light_position=%.9g,%.9g,%.9g light_radius=%.9g light_radiance=%.9g shadows=%s",
             light->position.x, light->position.y, light->position.z, light->radius, light->radiance,
             light->shadows ? "traced" : "none");
}

/* What a pixel's samples share: the configuration in the shading frame and
 * the material's lobes. */
typedef struct {
    sphere_light_config config;
    float diffuse[3], f0[3];
    int lit; /* 0: the view or the whole light is below the surface, or the point is inside the light */
} pixel_setup;

static pixel_setup setup_pixel(const sphere_light_plan *plan, const scene *s, const pixel_context *px)
{
    pixel_setup ps;
    memset(&ps, 0, sizeof ps);
    const surface_hit *h = px->surface;
    vec3 to_light = v3_sub(plan->light.position, h->p);
    float d = v3_length(to_light);
    vec3 v = frame_to_local(&px->shading, v3_normalize(v3_sub(plan->eye, h->p)));
    if (!(d > plan->light.radius) || !(v.z > 0.0f))
        return ps;
    material_sample m = material_lookup(s, h->mesh, h->uv);
    for (int c = 0; c < 3; ++c) {
        ps.diffuse[c] = m.base_color[c] * (1.0f - m.metallic);
        ps.f0[c] = 0.04f + (m.base_color[c] - 0.04f) * m.metallic;
    }
    ps.config.v = v;
    ps.config.lc = frame_to_local(&px->shading, v3_scale(to_light, 1.0f / d));
    ps.config.sin_sigma = plan->light.radius / d;
    ps.config.alpha = ggx_alpha(m.roughness);
    ps.lit = 1;
    return ps;
}

/* 1 when the local direction l also lies above the geometric surface. */
static int above_geometry(const pixel_context *px, vec3 l)
{
    return v3_dot(frame_to_world(&px->shading, l), px->surface->ng) > 0.0f;
}

/* The directions of one MIS sample and the RGB each carries. */
enum { DIRECTION_CAP, DIRECTION_GGX, DIRECTION_COSINE, DIRECTIONS };
typedef struct {
    vec3 l[DIRECTIONS]; /* local */
    float rgb[DIRECTIONS][3];
} light_sample;

static light_sample evaluate_sample(const pixel_setup *ps, const pixel_context *px, float le, const float u_cap[2],
                                    const float u_brdf[2])
{
    sphere_light_mis_terms t;
    sphere_light_mis_sample(&ps->config, u_cap, u_brdf, &t);
    double spec_cap = above_geometry(px, t.l_cap) ? t.spec_cap : 0.0;
    double spec_brdf = t.spec_brdf > 0.0 && above_geometry(px, t.l_brdf) ? t.spec_brdf : 0.0;
    /* Fresnel at v.h of each direction (only where it counts: a missed BRDF
     * direction may be -v, with no half vector). */
    float vh_cap = spec_cap > 0.0 ? v3_dot(ps->config.v, v3_normalize(v3_add(ps->config.v, t.l_cap))) : 1.0f;
    float vh_brdf = spec_brdf > 0.0 ? v3_dot(ps->config.v, v3_normalize(v3_add(ps->config.v, t.l_brdf))) : 1.0f;
    light_sample s = {{t.l_cap, t.l_brdf, t.l_diff}, {{0}}};
    for (int c = 0; c < 3; ++c) {
        s.rgb[DIRECTION_CAP][c] = (float)(le * (ps->diffuse[c] * t.diff_cap + fresnel_schlick(vh_cap, ps->f0[c]) * spec_cap));
        s.rgb[DIRECTION_GGX][c] = (float)(le * fresnel_schlick(vh_brdf, ps->f0[c]) * spec_brdf);
        s.rgb[DIRECTION_COSINE][c] = (float)(le * ps->diffuse[c] * t.diff_brdf);
    }
    return s;
}

/* Distance along the unit direction d from o to the light's sphere (d points
 * into its cone, so the ray meets it; rounding is clamped). */
static float distance_to_light(const sphere_light_settings *light, vec3 o, vec3 d)
{
    vec3 oc = v3_sub(light->position, o);
    float b = v3_dot(d, oc), c = v3_dot(oc, oc) - light->radius * light->radius;
    return b - sqrtf(fmaxf(b * b - c, 0.0f));
}

/* With --shadows: one occlusion ray per direction that carries light, from
 * the lifted surface point to the light's surface; visible[k][j] = 1 when
 * nothing blocks it. Returns the rays traced. */
static int trace_shadows(const integrator *self, const pixel_context *px, const light_sample *samples, int count,
                         float visible[][DIRECTIONS])
{
    const sphere_light_plan *plan = self->settings;
    _Alignas(16) struct RTCRay rays[DIRECTIONS * SAMPLE_BATCH];
    int traced = 0;
    for (int k = 0; k < count; ++k)
        for (int j = 0; j < DIRECTIONS; ++j) {
            const float *rgb = samples[k].rgb[j];
            int carries = rgb[0] > 0.0f || rgb[1] > 0.0f || rgb[2] > 0.0f;
            vec3 d = frame_to_world(&px->shading, samples[k].l[j]);
            float t_max = carries ? distance_to_light(&plan->light, px->ray_origin, d) : -1.0f;
            embree_ray_init(&rays[k * DIRECTIONS + j], px->ray_origin, d, t_max);
            traced += carries;
        }
    embree_unoccluded_stream(self->scene, rays, (unsigned)(DIRECTIONS * count));
    for (int k = 0; k < count; ++k)
        for (int j = 0; j < DIRECTIONS; ++j)
            visible[k][j] = rays[k * DIRECTIONS + j].tfar >= 0.0f ? 1.0f : 0.0f;
    return traced;
}

static int sphere_light_sample_batch(const integrator *self, const pixel_context *px, uint32_t first_index, int count,
                                     float *values)
{
    const sphere_light_plan *plan = self->settings;
    pixel_setup ps = setup_pixel(plan, self->scene->source, px);
    const sample_pair_seeds cap_pair = sample_pair_seeds_for(px, 0), brdf_pair = sample_pair_seeds_for(px, 1);
    float cu0[SAMPLE_BATCH], cu1[SAMPLE_BATCH], bu0[SAMPLE_BATCH], bu1[SAMPLE_BATCH];
    sample_pair_points(&cap_pair, first_index, count, cu0, cu1);
    sample_pair_points(&brdf_pair, first_index, count, bu0, bu1);
    static const light_sample unlit;
    light_sample samples[SAMPLE_BATCH];
    float visible[SAMPLE_BATCH][DIRECTIONS];
    for (int k = 0; k < count; ++k) {
        const float u_cap[2] = {cu0[k], cu1[k]}, u_brdf[2] = {bu0[k], bu1[k]};
        samples[k] = ps.lit ? evaluate_sample(&ps, px, plan->light.radiance, u_cap, u_brdf) : unlit;
        for (int j = 0; j < DIRECTIONS; ++j)
            visible[k][j] = 1.0f;
    }
    int traced = plan->light.shadows && ps.lit ? trace_shadows(self, px, samples, count, visible) : 0;
    for (int k = 0; k < count; ++k)
        for (int c = 0; c < 3; ++c)
            values[c * SAMPLE_BATCH + k] = visible[k][DIRECTION_CAP] * samples[k].rgb[DIRECTION_CAP][c] +
                                           visible[k][DIRECTION_GGX] * samples[k].rgb[DIRECTION_GGX][c] +
                                           visible[k][DIRECTION_COSINE] * samples[k].rgb[DIRECTION_COSINE][c];
    return traced;
}

integrator sphere_light_integrator(const embree_scene *es, const sphere_light_plan *plan)
{
    integrator it = {"sphere-light", 3, plan->quantities, NULL, sphere_light_sample_batch, es, plan, 0};
    return it;
}
