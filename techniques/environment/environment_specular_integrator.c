#include "environment/environment_specular_integrator.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/optics/ggx.h"
#include "core/reference_schema.h"
#include "core/roughness_setting.h"
#include "scene/material_lookup.h"

enum { OCCLUDED = 0, UNOCCLUDED = 3 };

int environment_specular_plan_init(environment_specular_plan *plan, const environment_light *light,
                                   float roughness, float f0, vec3 camera_position, gt_error *e)
{
    memset(plan, 0, sizeof *plan);
    if (!(roughness <= 1.0f) || !(f0 <= 1.0f))
        return gt_error_set(e, "env-specular", "roughness %g or F0 %g above 1", (double)roughness, (double)f0);
    plan->light = light;
    plan->roughness = roughness;
    plan->f0 = f0;
    plan->camera_position = camera_position;
    static const char *const names[2][3] = {CH_ENV_SPECULAR_RGB, CH_ENV_SPECULAR_UNOCCLUDED_RGB};
    for (int q = 0; q < ENVIRONMENT_SPECULAR_QUANTITIES; ++q) {
        snprintf(plan->quantities[q].name, IMAGE_NAME_MAX, "%s", names[q / 3][q % 3]);
        plan->quantities[q].scale_exponent = light->scale_exponent;
    }
    return 0;
}

/* The view direction in the shading frame, never below its horizon (as
 * techniques/specular_occlusion/specular_occlusion_integrator.c). */
static vec3 local_view(const pixel_context *px, vec3 camera_position)
{
    vec3 v = frame_to_local(&px->shading, v3_normalize(v3_sub(camera_position, px->surface->p)));
    if (v.z < 1e-4f) {
        float h = sqrtf(v.x * v.x + v.y * v.y);
        float s = h > 0.0f ? sqrtf(1.0f - 1e-8f) / h : 0.0f;
        v = h > 0.0f ? v3(v.x * s, v.y * s, 1e-4f) : v3(0.0f, 0.0f, 1.0f);
    }
    return v;
}

/* The pixel's GGX alpha (a float, as specular-occlusion's) and F0 (see the header). */
static void pixel_material(const integrator *self, const pixel_context *px, double *alpha, float f0[3])
{
    const environment_specular_plan *plan = self->settings;
    material_sample m = material_lookup(self->scene->source, px->surface->mesh, px->surface->uv);
    *alpha = (float)ggx_alpha_phong_cone(roughness_choose(plan->roughness, m.roughness));
    for (int c = 0; c < 3; ++c)
        f0[c] = plan->f0 >= 0.0f ? plan->f0 : 0.04f * (1.0f - m.metallic) + m.base_color[c] * m.metallic;
}

/* f_r cos / p_mix for local direction l (world w), as the header. */
static double specular_weight(const environment_light *light, vec3 v, vec3 l, vec3 w, double alpha)
{
    double g2_over_g1 = ggx_reflection_weight_brdf(v, l, alpha);
    if (!(g2_over_g1 > 0.0) || light->brdf_fraction == 1.0f)
        return g2_over_g1;
    double p_vndf = ggx_reflection_pdf(v, l, alpha), c = light->brdf_fraction;
    if (!(p_vndf > 0.0))
        return 0.0;
    return g2_over_g1 / (c + (1.0 - c) * environment_sampler_pdf(&light->sampler, w) / p_vndf);
}

/* A direction from the mixture for point u (u[0] chooses, then rescaled):
 * *l in the shading frame and the world direction returned. A visible-
 * normal sample keeps its local direction (as specular-occlusion's does);
 * an environment sample is brought into the frame. */
static vec3 sample_direction(const environment_light *light, const frame *shading, vec3 v, double alpha, float u0,
                             float u1, vec3 *l)
{
    const float c = light->brdf_fraction;
    if (c < 1.0f && !(u0 < c)) {
        float pdf;
        const float u[2] = {fminf((u0 - c) / (1.0f - c), 0x1.fffffep-1f), u1};
        vec3 w = environment_sampler_sample(&light->sampler, u, &pdf);
        *l = frame_to_local(shading, w);
        return w;
    }
    const float u[2] = {c < 1.0f ? fminf(u0 / c, 0x1.fffffep-1f) : u0, u1};
    *l = v3_normalize(ggx_reflect(v, ggx_sample_visible_normal(v, alpha, u)));
    return frame_to_world(shading, *l);
}

/* Schlick's Fresnel for each channel at cos = v.h. */
static void schlick(const float f0[3], double v_dot_h, float f[3])
{
    double m = 1.0 - fmin(fmax(v_dot_h, 0.0), 1.0), m5 = m * m * m * m * m;
    for (int c = 0; c < 3; ++c)
        f[c] = (float)(f0[c] + (1.0 - f0[c]) * m5);
}

static int environment_specular_sample_batch(const integrator *self, const pixel_context *px, uint32_t first_index,
                                             int count, float *values)
{
    const environment_specular_plan *plan = self->settings;
    const environment_light *light = plan->light;
    const sample_pair_seeds pair = sample_pair_seeds_for(px, 0);
    const vec3 v = local_view(px, plan->camera_position);
    double alpha;
    float f0[3], u0[SAMPLE_BATCH], u1[SAMPLE_BATCH], unoccluded[3][SAMPLE_BATCH];
    pixel_material(self, px, &alpha, f0);
    sample_pair_points(&pair, first_index, count, u0, u1);
    _Alignas(16) struct RTCRay rays[SAMPLE_BATCH];
    int traced = 0;
    for (int k = 0; k < count; ++k) {
        vec3 l;
        vec3 w = sample_direction(light, &px->shading, v, alpha, u0[k], u1[k], &l);
        double weight = specular_weight(light, v, l, w, alpha);
        float f[3], radiance[3];
        schlick(f0, v3_dot(v, v3_normalize(v3_add(v, l))), f);
        environment_light_radiance(light, w, radiance);
        for (int c = 0; c < 3; ++c)
            unoccluded[c][k] = weight > 0.0 ? (float)(weight * f[c]) * radiance[c] : 0.0f;
        int above = weight > 0.0 && v3_dot(w, px->surface->ng) > 0.0f;
        embree_ray_init(&rays[k], px->ray_origin, w, above ? INFINITY : -1.0f);
        traced += above;
    }
    embree_unoccluded_stream(self->scene, rays, (unsigned)count);
    for (int k = 0; k < count; ++k)
        for (int c = 0; c < 3; ++c) {
            values[(UNOCCLUDED + c) * SAMPLE_BATCH + k] = unoccluded[c][k];
            values[(OCCLUDED + c) * SAMPLE_BATCH + k] = rays[k].tfar >= 0.0f ? unoccluded[c][k] : 0.0f;
        }
    return traced;
}

integrator environment_specular_integrator(const embree_scene *es, const environment_specular_plan *plan)
{
    integrator it = {"env-specular", ENVIRONMENT_SPECULAR_QUANTITIES, plan->quantities, NULL,
                     environment_specular_sample_batch, es, plan, 0};
    return it;
}
