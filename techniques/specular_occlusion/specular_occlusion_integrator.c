#include "specular_occlusion/specular_occlusion_integrator.h"

#include <math.h>
#include <stdio.h>

#include "core/optics/ggx.h"
#include "core/optics/phong.h"
#include "core/roughness_setting.h"
#include "core/optics/sky_environment.h"
#include "scene/material_lookup.h"
#include "core/reference_schema.h"

enum { OCCLUDED, UNOCCLUDED, BLOCKED, D_OCCLUDED, D_UNOCCLUDED, D_BLOCKED, P_OCCLUDED, P_UNOCCLUDED, P_BLOCKED,
       SO_QUANTITY_COUNT, SPLIT_TRUTH = SO_QUANTITY_COUNT, SPLIT_ENV_D_OCCLUDED, SPLIT_ENV_D_UNOCCLUDED,
       WITH_SPLIT_QUANTITY_COUNT };

/* f_r-weighted samples lie in [0, 1] (exponent 0), D-weighted ones in [0, 4]
 * (exponent 2), Phong-weighted ones in [0, 4 * 4/e] (exponent 3); times the
 * sky's radiance (at most 6): [0, 6] (exponent 3) and [0, 24] (exponent 5). */
static const mc_quantity so_quantities[WITH_SPLIT_QUANTITY_COUNT] = {
    {CH_SPECOCC_OCCLUDED, 0},       {CH_SPECOCC_UNOCCLUDED, 0},       {CH_SPECOCC_BLOCKED, 0},
    {CH_SPECOCC_D_OCCLUDED, 2},     {CH_SPECOCC_D_UNOCCLUDED, 2},     {CH_SPECOCC_D_BLOCKED, 2},
    {CH_SPECOCC_PHONG_OCCLUDED, 3}, {CH_SPECOCC_PHONG_UNOCCLUDED, 3}, {CH_SPECOCC_PHONG_BLOCKED, 3},
    {CH_SPLIT_TRUTH, 3},            {CH_SPLIT_ENV_D_OCCLUDED, 5},     {CH_SPLIT_ENV_D_UNOCCLUDED, 5}};

/* The view direction in the shading frame, never below its horizon. */
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

static float pixel_alpha(const integrator *self, const pixel_context *px)
{
    const specular_occlusion_settings *settings = self->settings;
    float r = settings->roughness;
    if (roughness_is_material(r))
        r = material_lookup(self->scene->source, px->surface->mesh, px->surface->uv).roughness;
    return (float)ggx_alpha(r);
}

static int so_sample_batch(const integrator *self, const pixel_context *px, uint32_t first_index, int count,
                           float *values)
{
    const specular_occlusion_settings *settings = self->settings;
    const sample_pair_seeds pair = sample_pair_seeds_for(px, 0);
    const vec3 v = local_view(px, settings->camera_position);
    const double alpha = pixel_alpha(self, px);
    _Alignas(16) struct RTCRay rays[SAMPLE_BATCH];
    const double p = phong_exponent(alpha);
    float u0[SAMPLE_BATCH], u1[SAMPLE_BATCH], w[SAMPLE_BATCH], wd[SAMPLE_BATCH], wp[SAMPLE_BATCH], env[SAMPLE_BATCH];
    sample_pair_points(&pair, first_index, count, u0, u1);
    int traced = 0;
    for (int k = 0; k < count; ++k) {
        const float u[2] = {u0[k], u1[k]};
        vec3 m = ggx_sample_visible_normal(v, alpha, u);
        vec3 l = v3_normalize(ggx_reflect(v, m));
        int lit = l.z > 0.0f;
        w[k] = (float)ggx_reflection_weight_brdf(v, l, alpha);
        wd[k] = (float)ggx_reflection_weight_ndf(v, l, alpha);
        vec3 h = v3_normalize(v3_add(v, l));
        wp[k] = lit ? (float)(wd[k] * phong_ndf(h.z, p) / ggx_ndf(h.z, alpha)) : 0.0f;
        vec3 d = frame_to_world(&px->shading, l);
        env[k] = settings->environment == ENVIRONMENT_SKY ? (float)sky_radiance(d) : 1.0f;
        int above = lit && v3_dot(d, px->surface->ng) > 0.0f;
        embree_ray_init(&rays[k], px->ray_origin, d, above ? INFINITY : -1.0f);
        traced += above;
    }
    embree_unoccluded_stream(self->scene, rays, (unsigned)count);
    for (int k = 0; k < count; ++k) {
        float visible = rays[k].tfar >= 0.0f ? 1.0f : 0.0f;
        values[OCCLUDED * SAMPLE_BATCH + k] = visible * w[k];
        values[UNOCCLUDED * SAMPLE_BATCH + k] = w[k];
        values[BLOCKED * SAMPLE_BATCH + k] = (1.0f - visible) * w[k];
        values[D_OCCLUDED * SAMPLE_BATCH + k] = visible * wd[k];
        values[D_UNOCCLUDED * SAMPLE_BATCH + k] = wd[k];
        values[D_BLOCKED * SAMPLE_BATCH + k] = (1.0f - visible) * wd[k];
        values[P_OCCLUDED * SAMPLE_BATCH + k] = visible * wp[k];
        values[P_UNOCCLUDED * SAMPLE_BATCH + k] = wp[k];
        values[P_BLOCKED * SAMPLE_BATCH + k] = (1.0f - visible) * wp[k];
        if (settings->environment == ENVIRONMENT_WHITE)
            continue;
        values[SPLIT_TRUTH * SAMPLE_BATCH + k] = visible * env[k] * w[k];
        values[SPLIT_ENV_D_OCCLUDED * SAMPLE_BATCH + k] = visible * env[k] * wd[k];
        values[SPLIT_ENV_D_UNOCCLUDED * SAMPLE_BATCH + k] = env[k] * wd[k];
    }
    return traced;
}

integrator specular_occlusion_integrator(const embree_scene *es, const specular_occlusion_settings *settings)
{
    int count = settings->environment == ENVIRONMENT_SKY ? WITH_SPLIT_QUANTITY_COUNT : SO_QUANTITY_COUNT;
    integrator it = {"specular-occlusion", count, so_quantities, NULL, so_sample_batch, es, settings, 0};
    return it;
}

/* One ratio layer: out = num / den and, when the .stderr channels exist, its
 * delta-method standard error (see the header). */
static int write_ratio(image *img, const char *prefix, const char *out_name)
{
    char name[IMAGE_NAME_MAX];
    const float *mask = image_channel_data(img, CH_MASK);
    const float *mean[3], *se[3];
    static const char *const parts[3] = {CH_SPECOCC_PART_OCCLUDED, CH_SPECOCC_PART_UNOCCLUDED,
                                         CH_SPECOCC_PART_BLOCKED};
    for (int i = 0; i < 3; ++i) {
        snprintf(name, sizeof name, CH_SPECOCC_PART_FMT, prefix, parts[i]);
        mean[i] = image_channel_data(img, name);
        se[i] = schema_stderr_data(img, name);
    }
    if (!mean[0] || !mean[1])
        return -1;
    int with_stderr = se[0] && se[1] && se[2];
    float *ratio = image_add_channel(img, out_name), *ratio_se = NULL;
    if (schema_channel_suffixed(out_name, CH_SUFFIX_STDERR, name) != 0)
        return -1;
    if (!ratio || (with_stderr && !(ratio_se = image_add_channel(img, name))))
        return -1;
    for (size_t p = 0; p < image_pixel_count(img); ++p) {
        double n = mean[0][p], d = mean[1][p];
        int valid = (!mask || mask[p] != 0.0f) && d > 0.0;
        double r = valid ? n / d : 0.0;
        ratio[p] = (float)r;
        if (!with_stderr)
            continue;
        double sn = se[0][p], sd = se[1][p], sb = se[2][p];
        double cov = 0.5 * (sn * sn + sd * sd - sb * sb);
        double var = valid ? (sn * sn - 2.0 * r * cov + r * r * sd * sd) / (d * d) : 0.0;
        ratio_se[p] = (float)sqrt(fmax(var, 0.0));
    }
    return 0;
}

/* The split approximations from the means (see the header): with
 * E = \int L D cos / \int D cos, the prefiltered environment,
 *   two   = (\int V L D cos / \int D cos) \int f_r cos
 *   three = V_s^D E \int f_r cos. */
static int write_splits(image *img)
{
    const float *mask = image_channel_data(img, CH_MASK);
    const float *env_occluded = image_channel_data(img, CH_SPLIT_ENV_D_OCCLUDED);
    const float *env_unoccluded = image_channel_data(img, CH_SPLIT_ENV_D_UNOCCLUDED);
    const float *d_occluded = image_channel_data(img, CH_SPECOCC_D_OCCLUDED);
    const float *d_unoccluded = image_channel_data(img, CH_SPECOCC_D_UNOCCLUDED);
    const float *albedo = image_channel_data(img, CH_SPECOCC_UNOCCLUDED);
    if (!env_occluded || !env_unoccluded)
        return 0; /* a white-dome render */
    float *two = image_add_channel(img, CH_SPLIT_TWO), *three = image_add_channel(img, CH_SPLIT_THREE);
    if (!two || !three || !d_occluded || !d_unoccluded || !albedo)
        return -1;
    for (size_t p = 0; p < image_pixel_count(img); ++p) {
        double d = d_unoccluded[p];
        int valid = (!mask || mask[p] != 0.0f) && d > 0.0;
        two[p] = valid ? (float)(env_occluded[p] / d * albedo[p]) : 0.0f;
        three[p] = valid ? (float)((d_occluded[p] / d) * (env_unoccluded[p] / d) * albedo[p]) : 0.0f;
    }
    return 0;
}

int specular_occlusion_write_ratios(image *img)
{
    return write_ratio(img, CH_SPECOCC_PREFIX, CH_SPECOCC) | write_ratio(img, CH_SPECOCC_D_PREFIX, CH_SPECOCC_D) |
           write_ratio(img, CH_SPECOCC_PHONG_PREFIX, CH_SPECOCC_PHONG) | write_splits(img);
}
