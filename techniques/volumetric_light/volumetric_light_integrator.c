/* The volumetric-light reference over the G-buffer; see
 * volumetric_light_integrator.h. */
#include "volumetric_light/volumetric_light_integrator.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/reference_schema.h"

static const char *const method_names[] = {"quadrature", "monte-carlo"};

const char *volumetric_light_method_name(volumetric_light_method m)
{
    return m == VLIGHT_QUADRATURE || m == VLIGHT_MONTE_CARLO ? method_names[m] : "unknown";
}

int volumetric_light_method_parse(const char *name, volumetric_light_method *m)
{
    for (int i = 0; i < 2; ++i)
        if (strcmp(name, method_names[i]) == 0) {
            *m = (volumetric_light_method)i;
            return 0;
        }
    return -1;
}

void volumetric_light_settings_default(volumetric_light_settings *s)
{
    memset(s, 0, sizeof *s);
    s->kind = VOLUMETRIC_SPOT_LIGHT;
    s->method = VLIGHT_QUADRATURE;
    s->outer_deg = 30.0;
    s->inner_deg = 20.0;
    s->albedo = 0.8;
    s->g = 0.3;
    s->rel_tol = 1e-5;
}

static vec3 relative_point(vec3 lo, vec3 hi, float fx, float fy, float fz)
{
    vec3 e = v3_sub(hi, lo);
    return v3(lo.x + fx * e.x, lo.y + fy * e.y, lo.z + fz * e.z);
}

int volumetric_light_resolve(const volumetric_light_settings *s, vec3 lo, vec3 hi, volumetric_light *light,
                             volumetric_medium *medium, gt_error *e)
{
    double extent = v3_length(v3_sub(hi, lo));
    if (!(extent > 0.0) && (!s->has_placement || !(s->sigma_t > 0.0) || !(s->intensity > 0.0)))
        return gt_error_set(e, "volumetric-light", "the scene has no extent to place the light in");
    vec3 position = s->has_placement ? s->position : relative_point(lo, hi, 0.15f, 0.9f, 1.6f);
    vec3 target = s->has_placement ? s->target : relative_point(lo, hi, 0.6f, 0.0f, 0.3f);
    double grey = s->intensity > 0.0 ? s->intensity : extent * extent, intensity[3] = {grey, grey, grey};
    *light = s->kind == VOLUMETRIC_SPOT_LIGHT
                 ? volumetric_spot_light(position, target, s->outer_deg, s->inner_deg, intensity)
                 : volumetric_point_light(position, intensity);
    medium->sigma_t = s->sigma_t > 0.0 ? s->sigma_t : 1.0 / extent;
    medium->sigma_s = s->albedo * medium->sigma_t;
    medium->g = s->g;
    if (!(s->albedo >= 0.0 && s->albedo <= 1.0))
        return gt_error_set(e, "volumetric-light", "the albedo must be in [0, 1], got %g", s->albedo);
    if (s->kind == VOLUMETRIC_SPOT_LIGHT && v3_length(v3_sub(target, position)) == 0.0f)
        return gt_error_set(e, "volumetric-light", "the spot's target is its position");
    if (volumetric_medium_validate(medium, "volumetric-light", e) != 0)
        return -1;
    return volumetric_light_validate(light, "volumetric-light", e);
}

/* Samples stay below a few times I sigma_s max(p) pi / h; h is rarely below
 * a hundredth of the light's distance to the camera. */
static void name_quantities(volumetric_light_plan *plan)
{
    static const char *const names[VLIGHT_QUANTITIES] = {CH_VLIGHT_L_R,       CH_VLIGHT_L_G,
                                                          CH_VLIGHT_L_B,       CH_VLIGHT_L_ERROR_R,
                                                          CH_VLIGHT_L_ERROR_G, CH_VLIGHT_L_ERROR_B};
    const volumetric_light *l = &plan->light;
    double i_max = fmax(l->intensity[0], fmax(l->intensity[1], l->intensity[2]));
    double a = 1.0 - fabs(plan->medium.g), p_max = (1.0 - plan->medium.g * plan->medium.g) / (4.0 * M_PI * a * a * a);
    double h = 0.01 * fmax(1e-3, v3_length(v3_sub(l->position, plan->eye)));
    double bound = fmax(1.0, i_max * plan->medium.sigma_s * p_max * M_PI / h);
    plan->quantity_count = plan->method == VLIGHT_QUADRATURE ? 6 : 3;
    for (int q = 0; q < plan->quantity_count; ++q) {
        snprintf(plan->quantities[q].name, sizeof plan->quantities[q].name, "%s", names[q]);
        plan->quantities[q].scale_exponent = (int)ceil(log2(4.0 * bound));
    }
}

int volumetric_light_plan_init(volumetric_light_plan *plan, const volumetric_light_settings *s,
                               const embree_scene *es, vec3 lo, vec3 hi, vec3 eye, gt_error *e)
{
    memset(plan, 0, sizeof *plan);
    if (volumetric_light_resolve(s, lo, hi, &plan->light, &plan->medium, e) != 0)
        return -1;
    if (!(s->rel_tol > 0.0 && s->rel_tol < 1.0))
        return gt_error_set(e, "volumetric-light", "the quadrature tolerance must be in (0, 1)");
    plan->method = s->method;
    plan->rel_tol = s->rel_tol;
    plan->eye = eye;
    plan->lighting.light = &plan->light;
    plan->lighting.medium = &plan->medium;
    plan->lighting.occluders = s->no_shadows ? NULL : es;
    name_quantities(plan);
    return 0;
}

static int vlight_sample_batch(const integrator *self, const pixel_context *px, uint32_t first_index, int count,
                               float *values)
{
    const volumetric_light_plan *plan = self->settings;
    vec3 to_surface = v3_sub(px->surface->p, plan->eye);
    double distance = v3_length(to_surface);
    vec3 dir = v3_scale(to_surface, (float)(1.0 / distance));
    if (plan->method == VLIGHT_QUADRATURE) {
        volumetric_ray_estimate q;
        volumetric_light_quadrature(&plan->lighting, plan->eye, dir, distance, plan->rel_tol, &q);
        for (int k = 0; k < count; ++k)
            for (int c = 0; c < 3; ++c) {
                values[c * SAMPLE_BATCH + k] = (float)q.radiance[c];
                values[(3 + c) * SAMPLE_BATCH + k] = (float)q.error[c];
            }
        return (int)q.rays;
    }
    float u0[SAMPLE_BATCH], u1[SAMPLE_BATCH];
    double samples[SAMPLE_BATCH];
    const sample_pair_seeds seeds = sample_pair_seeds_for(px, 0);
    sample_pair_points(&seeds, first_index, count, u0, u1);
    int rays = volumetric_light_mc_samples(&plan->lighting, plan->eye, dir, distance, u0, count, samples);
    for (int k = 0; k < count; ++k)
        for (int c = 0; c < 3; ++c)
            values[c * SAMPLE_BATCH + k] = (float)(plan->light.intensity[c] * samples[k]);
    return rays;
}

integrator volumetric_light_integrator(const embree_scene *es, const volumetric_light_plan *plan)
{
    integrator it = {"volumetric-light", plan->quantity_count, plan->quantities, NULL, vlight_sample_batch, es,
                     plan, 0};
    return it;
}
