/* Part of the `gtlab all` sphere-light stage: scene renders. A glossy
 * dielectric floor at grazing view under a sun-sized light low over the
 * horizon (the talk's "sun's reflection at low angles") and under a large
 * near light; the reference (`gtlab render sphere-light`) against Karis,
 * Decima and Decima refit evaluated per pixel from the reference's own
 * G-buffer, by DSSIM beside the reference's noise floor, with heatmaps;
 * and the reference with --shadows beside it without, on sphere-on-plane. */
#define _GNU_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/all_stage_sphere_light.h"
#include "core/exr_io.h"
#include "core/fresnel.h"
#include "core/frame.h"
#include "core/image_io.h"
#include "metrics/ssim.h"
#include "raytracer/reference_render.h"
#include "raytracer/sphere_light_reference.h"
#include "realtime/sphere_light.h"
#include "scene/scene_loaders.h"

#define APPROX 3
static const char *approx_names[APPROX] = {"Karis", "Decima", "Decima refit"};
static const char *approx_files[APPROX] = {"karis", "decima", "decima_refit"};

typedef struct {
    const char *name, *title;
    vec3 light;
    float radius, radiance;
} light_scene;

/* Floor material of the comparison: grey dielectric, glossy; metallic 0 so
 * that F0 = 0.04 and the G-buffer's albedo is the diffuse colour. */
#define FLOOR_ROUGHNESS 0.25f
#define FLOOR_ALBEDO 0.5f
#define F0_DIELECTRIC 0.04f

/* The radiance an approximation gives at pixel i: the exact Lambert part
 * (Frostbite's illuminance, the same for all) plus the method's specular. */
static float approx_pixel(int method, const image *ref, size_t i, vec3 eye, const light_scene *ls,
                          const decima_sphere_constants *refit)
{
    vec3 p = v3(image_channel_data(ref, "P.X")[i], image_channel_data(ref, "P.Y")[i], image_channel_data(ref, "P.Z")[i]);
    vec3 n = v3(image_channel_data(ref, "N.X")[i], image_channel_data(ref, "N.Y")[i], image_channel_data(ref, "N.Z")[i]);
    float albedo = image_channel_data(ref, "albedo.G")[i], roughness = image_channel_data(ref, "roughness.Y")[i];
    frame f = frame_from_normal(v3_normalize(n));
    vec3 to_light = v3_sub(ls->light, p);
    float d = v3_length(to_light), sin_sigma = ls->radius / d, alpha = roughness * roughness;
    vec3 v = frame_to_local(&f, v3_normalize(v3_sub(eye, p))), lc = frame_to_local(&f, v3_scale(to_light, 1.0f / d));
    if (!(v.z > 0.0f))
        return 0.0f;
    float e_perp = (float)sphere_light_normal_illuminance(sin_sigma);
    float diffuse = albedo / (float)M_PI * sphere_illuminance_frostbite(lc.z, sin_sigma);
    float l_dot_h = sqrtf(fmaxf(0.0f, 0.5f + 0.5f * v3_dot(v, lc)));
    float spec;
    if (method == 0) {
        spec = karis_sphere_ggx(v, lc, sin_sigma, alpha) * fresnel_schlick(l_dot_h, F0_DIELECTRIC);
    } else {
        decima_sphere_constants published = decima_sphere_published();
        spec = decima_sphere_ggx(lc.z, v.z, v3_dot(v, lc), l_dot_h, sin_sigma, alpha, F0_DIELECTRIC,
                                 method == 1 ? &published : refit, 1);
    }
    return ls->radiance * (diffuse + e_perp * spec);
}

static int compare_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* The 99th percentile of the masked values: the scale of previews and
 * heatmaps (a sun's highlight would make the maximum useless). */
static float percentile99(const float *v, const float *mask, size_t n)
{
    float *tmp = malloc(n * sizeof *tmp), out = 1.0f;
    size_t m = 0;
    if (!tmp)
        return out;
    for (size_t i = 0; i < n; ++i)
        if (mask[i] != 0.0f)
            tmp[m++] = v[i];
    if (m > 0) {
        qsort(tmp, m, sizeof *tmp, compare_float);
        out = tmp[(size_t)(0.99 * (double)(m - 1))];
    }
    free(tmp);
    return out > 0.0f ? out : 1.0f;
}

typedef struct {
    double dssim[APPROX], noise_floor;
    int width, height;
} scene_figures;

/* Renders one scene, compares, writes EXR, previews and heatmaps. */
static int compare_scene(all_context *ctx, const char *dir, const light_scene *ls, const decima_sphere_constants *refit,
                         scene_figures *fig, gt_error *e)
{
    const int preview = ctx->quality == QUALITY_PREVIEW;
    scene s;
    if (scene_load("builtin:plane", &s, e) != 0)
        return -1;
    for (int m = 0; m < s.material_count; ++m) {
        s.materials[m].metallic = 0.0f, s.materials[m].roughness = FLOOR_ROUGHNESS;
        s.materials[m].base_color[0] = s.materials[m].base_color[1] = s.materials[m].base_color[2] = FLOOR_ALBEDO;
    }
    /* Half a unit above the floor, looking 6 units ahead: grazing view. */
    camera cam = {v3(0.0f, 0.5f, 6.0f), v3(0.0f, 0.0f, -2.0f), v3(0.0f, 1.0f, 0.0f), (float)(40.0 * M_PI / 180.0),
                  preview ? 192 : 480, preview ? 112 : 280};
    reference_request req;
    memset(&req, 0, sizeof req);
    req.quantity = QUANTITY_SPHERE_LIGHT;
    req.sampling.spp = preview ? 64 : 1024;
    req.sampling.seed = 1;
    req.sampling.threads = ctx->threads;
    req.normals = NORMAL_SHADING;
    req.sphere_light.position = ls->light;
    req.sphere_light.radius = ls->radius;
    req.sphere_light.radiance = ls->radiance;
    image ref;
    render_stats stats;
    int rc = reference_render(&s, "builtin:plane (glossy grey floor)", &cam, &req, &ref, &stats, e);
    scene_free(&s);
    if (rc != 0)
        return -1;
    size_t n = image_pixel_count(&ref);
    const float *mask = image_channel_data(&ref, "mask.A"), *want = image_channel_data(&ref, "sphere.G");
    float *approx = malloc(APPROX * n * sizeof *approx), *err = malloc(n * sizeof *err);
    char path[8192];
    fig->width = ref.width, fig->height = ref.height;
    if (!approx || !err) {
        rc = gt_error_set(e, dir, "out of memory");
        goto done;
    }
    snprintf(path, sizeof path, "%s/scene_%s.exr", dir, ls->name);
    ssim_result floor;
    if ((rc = ssim_noise_floor(&ref, path, "sphere.G", mask, &floor, e)) != 0)
        goto done;
    fig->noise_floor = floor.dssim;
    if ((rc = exr_write(path, &ref, e)) != 0)
        goto done;
    float scale = percentile99(want, mask, n);
    snprintf(path, sizeof path, "%s/scene_%s_reference.png", dir, ls->name);
    if ((rc = image_write_preview(path, &want, 1, ref.width, ref.height, 1.0f / scale, e)) != 0)
        goto done;
    for (int m = 0; m < APPROX; ++m) {
        float *a = approx + m * n;
        for (size_t i = 0; i < n; ++i) {
            a[i] = mask[i] != 0.0f ? approx_pixel(m, &ref, i, cam.position, ls, refit) : 0.0f;
            err[i] = fabsf(a[i] - want[i]);
        }
        ssim_result r;
        if ((rc = ssim_compute(a, want, mask, ref.width, ref.height, approx_names[m], NULL, &r, e)) != 0)
            goto done;
        fig->dssim[m] = r.dssim;
        const float *plane = a;
        snprintf(path, sizeof path, "%s/scene_%s_%s.png", dir, ls->name, approx_files[m]);
        if ((rc = image_write_preview(path, &plane, 1, ref.width, ref.height, 1.0f / scale, e)) != 0)
            goto done;
        snprintf(path, sizeof path, "%s/scene_%s_%s_error.png", dir, ls->name, approx_files[m]);
        if ((rc = image_write_heatmap(path, err, mask, ref.width, ref.height, 0.5f * scale, "inferno", e)) != 0)
            goto done;
    }
done:
    free(approx);
    free(err);
    image_free(&ref);
    return rc;
}

/* One reference of the sphere over the floor, with or without shadows. */
static int render_sphere_on_plane(all_context *ctx, const camera *cam, int shadows, image *out, gt_error *e)
{
    scene s;
    if (scene_load("builtin:sphere-on-plane", &s, e) != 0)
        return -1;
    reference_request req;
    memset(&req, 0, sizeof req);
    req.quantity = QUANTITY_SPHERE_LIGHT;
    req.sampling = (sampling_settings){.spp = ctx->quality == QUALITY_PREVIEW ? 64 : 1024, .seed = 1,
                                       .threads = ctx->threads};
    req.normals = NORMAL_SHADING;
    req.sphere_light = (sphere_light_settings){v3(-2.5f, 4.0f, 1.5f), 0.5f, 5.0f, shadows};
    render_stats stats;
    int rc = reference_render(&s, "builtin:sphere-on-plane", cam, &req, out, &stats, e);
    scene_free(&s);
    return rc;
}

/* What none of the approximations models: the same light with --shadows. */
static int shadow_comparison(all_context *ctx, const char *dir, cJSON *json, gt_error *e)
{
    const int preview = ctx->quality == QUALITY_PREVIEW;
    camera cam = {v3(0.0f, 3.0f, 7.0f), v3(0.0f, 0.7f, 0.0f), v3(0.0f, 1.0f, 0.0f), (float)(40.0 * M_PI / 180.0),
                  preview ? 160 : 400, preview ? 96 : 240};
    image plain, shadowed;
    if (render_sphere_on_plane(ctx, &cam, 0, &plain, e) != 0)
        return -1;
    if (render_sphere_on_plane(ctx, &cam, 1, &shadowed, e) != 0) {
        image_free(&plain);
        return -1;
    }
    const float *mask = image_channel_data(&plain, "mask.A");
    const float *planes[2] = {image_channel_data(&plain, "sphere.G"), image_channel_data(&shadowed, "sphere.G")};
    size_t n = image_pixel_count(&plain), covered = 0, darkened = 0;
    for (size_t i = 0; i < n; ++i) {
        covered += mask[i] != 0.0f;
        darkened += mask[i] != 0.0f && planes[1][i] < 0.9f * planes[0][i];
    }
    float scale = percentile99(planes[0], mask, n);
    ssim_result r;
    char path[8192];
    int rc = ssim_compute(planes[1], planes[0], mask, plain.width, plain.height, "shadowed", NULL, &r, e);
    static const char *const names[2] = {"unshadowed", "shadowed"};
    for (int k = 0; k < 2 && rc == 0; ++k) {
        snprintf(path, sizeof path, "%s/scene_shadows_%s.png", dir, names[k]);
        rc = image_write_preview(path, &planes[k], 1, plain.width, plain.height, 1.0f / scale, e);
    }
    image_free(&plain);
    image_free(&shadowed);
    if (rc != 0)
        return -1;
    double share = covered ? (double)darkened / covered : 0.0;
    report_paragraph(ctx->doc,
                     "What none of the approximations models: the same reference with 'gtlab render sphere-light "
                     "--shadows' (one occlusion ray per light-carrying sample) on sphere-on-plane, light of radius "
                     "0.5 up and to the left. %.0f%% of the visible pixels lose more than a tenth of their light to "
                     "the sphere's shadow; DSSIM between the shadowed and the unshadowed reference %.4f. A renderer "
                     "must get that part from elsewhere (shadow maps, specular occlusion).",
                     100.0 * share, r.dssim);
    const char *figs[2] = {"sphere_light/scene_shadows_unshadowed.png", "sphere_light/scene_shadows_shadowed.png"};
    const char *caps[2] = {"unshadowed reference (what the approximations aim at)", "with --shadows"};
    report_figures(ctx->doc, 2, figs, caps);
    cJSON *o = cJSON_AddObjectToObject(json, "shadows");
    cJSON_AddNumberToObject(o, "dssim_shadowed_vs_unshadowed", r.dssim);
    cJSON_AddNumberToObject(o, "share_of_pixels_darkened_over_10_percent", share);
    return 0;
}

int all_stage_sphere_light_scenes(all_context *ctx, const char *dir, const decima_sphere_constants *refit,
                                  cJSON *json, gt_error *e)
{
    /* The sun: 0.27 deg, 6 deg above the horizon ahead of the camera, its
     * radiance such that its normal illuminance is 1. A large light: radius
     * 1 at ~9 units, low ahead, normal illuminance 1 at 5 units. */
    const double sun_sin = 0.00465, sun_elev = 6.0 * M_PI / 180.0;
    const light_scene scenes[2] = {
        {"sun", "sun-sized light (0.27 deg) 6 deg above the horizon",
         v3(0.0f, (float)(1000.0 * sin(sun_elev)), (float)(-1000.0 * cos(sun_elev))), (float)(1000.0 * sun_sin),
         (float)(1.0 / (M_PI * sun_sin * sun_sin))},
        {"large", "large light: radius 1 at 9 units, 1.5 units up",
         v3(0.0f, 1.5f, -9.0f), 1.0f, (float)(25.0 / M_PI)},
    };
    report *doc = ctx->doc;
    report_heading(doc, 3, "Scene renders: glossy floor at grazing view");
    report_paragraph(doc,
                     "A grey dielectric floor (albedo %.2f, roughness %.2f, F0 %.2f) seen from 0.5 units above it, "
                     "unshadowed. Reference: 'gtlab render sphere-light' (MIS over the light, Fresnel inside the "
                     "integral). Approximations evaluated per pixel from the reference's G-buffer, with the exact "
                     "Lambert part (Frostbite's illuminance) in all three, so they differ only in the specular. "
                     "DSSIM on linear radiance (green channel; the scenes are grey); previews and heatmaps scaled "
                     "by the reference's 99th percentile.",
                     FLOOR_ALBEDO, FLOOR_ROUGHNESS, F0_DIELECTRIC);
    const char *headers[5] = {"scene", "Karis", "Decima", "Decima refit", "noise floor"};
    cJSON *arr = cJSON_AddArrayToObject(json, "scenes");
    scene_figures fig[2];
    for (int k = 0; k < 2; ++k)
        if (compare_scene(ctx, dir, &scenes[k], refit, &fig[k], e) != 0)
            return -1;
    report_table_begin(doc, 5, headers);
    for (int k = 0; k < 2; ++k) {
        char c[4][32];
        for (int m = 0; m < APPROX; ++m)
            snprintf(c[m], 32, "%.4g", fig[k].dssim[m]);
        snprintf(c[3], 32, "%.2g", fig[k].noise_floor);
        const char *row[5] = {scenes[k].title, c[0], c[1], c[2], c[3]};
        report_table_row(doc, row);
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "scene", scenes[k].name);
        for (int m = 0; m < APPROX; ++m)
            cJSON_AddNumberToObject(o, approx_files[m], fig[k].dssim[m]);
        cJSON_AddNumberToObject(o, "noise_floor_dssim", fig[k].noise_floor);
        cJSON_AddItemToArray(arr, o);
    }
    report_table_end(doc);
    for (int k = 0; k < 2; ++k) {
        char paths[7][256];
        const char *figs[7], *caps[7] = {"reference", "Karis", "Decima", "Decima refit",
                                         "|Karis - reference|", "|Decima - reference|", "|refit - reference|"};
        snprintf(paths[0], 256, "sphere_light/scene_%s_reference.png", scenes[k].name);
        for (int m = 0; m < APPROX; ++m) {
            snprintf(paths[1 + m], 256, "sphere_light/scene_%s_%s.png", scenes[k].name, approx_files[m]);
            snprintf(paths[4 + m], 256, "sphere_light/scene_%s_%s_error.png", scenes[k].name, approx_files[m]);
        }
        for (int j = 0; j < 7; ++j)
            figs[j] = paths[j];
        report_paragraph(doc, "%s:", scenes[k].title);
        report_figures(doc, 4, figs, caps);
        report_figures(doc, 3, figs + 4, caps + 4);
    }
    return shadow_comparison(ctx, dir, json, e);
}
