/* The scene part of the sphere-light study (sphere_light/sphere_light_study.h). A
 * glossy dielectric floor at grazing view under a sun-sized light low over
 * the horizon (the talk's "sun's reflection at low angles") and under a large
 * near light; the reference (`gtlab render sphere-light`) against Karis,
 * Decima and Decima refit evaluated per pixel from the reference's own
 * G-buffer (sphere_light/sphere_light.h), by DSSIM beside the reference's noise
 * floor, with heatmaps; and the reference with --shadows beside it without,
 * on sphere-on-plane. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/exr_io.h"
#include "core/files/image_io.h"
#include "core/reference_schema.h"
#include "ltc/ltc_sphere.h"
#include "metrics/flip.h"
#include "metrics/ssim.h"
#include "sphere_light/sphere_light_quality.h"
#include "sphere_light/sphere_light_quantity.h"
#include "scene/scene_loaders.h"
#include "sphere_light/sphere_light.h"
#include "sphere_light/sphere_light_study.h"

const char *const sphere_scene_approx_files[SPHERE_SCENE_APPROX] = {"karis", "decima", "decima_refit", "ltc"};
static const char *const approx_names[SPHERE_SCENE_APPROX] = {"Karis", "Decima", "Decima refit", "LTC"};

/* Approximation m's specular: the talks' (Karis, Decima with constants) or
 * the LTC's with its table. */
typedef struct {
    sphere_specular_fn specular; /* NULL: sphere_light_shade with k */
    const void *user;
} scene_model;

typedef struct {
    const char *name, *title;
    sphere_light_source light;
} light_scene;

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

/* The floor lit by the scene's light, seen at grazing view. */
static int render_floor(const study_context *ctx, const light_scene *ls, const camera *cam, image *ref, gt_error *e)
{
    scene s;
    if (scene_load("builtin:plane", &s, e) != 0)
        return -1;
    for (int m = 0; m < s.material_count; ++m) {
        s.materials[m].metallic = 0.0f, s.materials[m].roughness = SPHERE_FLOOR_ROUGHNESS;
        s.materials[m].base_color[0] = s.materials[m].base_color[1] = s.materials[m].base_color[2] =
            SPHERE_FLOOR_ALBEDO;
    }
    reference_request req;
    memset(&req, 0, sizeof req);
    req.quantity = QUANTITY_SPHERE_LIGHT;
    req.sampling.spp = sphere_light_quality_of(ctx->quality)->scene_spp;
    req.sampling.seed = 1;
    req.sampling.threads = ctx->threads;
    req.normals = NORMAL_SHADING;
    sphere_light_quantity_settings light = sphere_light_quantity_settings_of(
        (sphere_light_settings){ls->light.position, ls->light.radius, ls->light.radiance, 0});
    req.settings = &light.header;
    render_stats stats;
    int rc = reference_render(&s, "builtin:plane (glossy grey floor)", cam, &req, ref, &stats, e);
    scene_free(&s);
    return rc;
}

/* The reference's G-buffer planes. */
static sphere_light_gbuffer gbuffer_of(const image *ref)
{
    sphere_light_gbuffer g = {{image_channel_data(ref, CH_P_X), image_channel_data(ref, CH_P_Y),
                               image_channel_data(ref, CH_P_Z)},
                              {image_channel_data(ref, CH_N_X), image_channel_data(ref, CH_N_Y),
                               image_channel_data(ref, CH_N_Z)},
                              image_channel_data(ref, CH_ALBEDO_G),
                              image_channel_data(ref, CH_ROUGHNESS),
                              image_channel_data(ref, CH_MASK),
                              image_pixel_count(ref)};
    return g;
}

/* The FLIP map of approx against the reference `want` (magma, 0 to 1; the
 * report draws its labelled colour bar beside it); its mean into *flip. */
static int flip_map(const char *dir, const light_scene *ls, const image *ref, int m, const float *want,
                    const float *approx, const float *mask, float *map, double *flip, gt_error *e)
{
    flip_result f;
    char path[8192];
    snprintf(path, sizeof path, "%s/scene_%s_%s_flip.png", dir, ls->name, sphere_scene_approx_files[m]);
    if (flip_grey(want, approx, mask, ref->width, ref->height, path, map, &f, e) != 0)
        return -1;
    *flip = f.mean;
    return image_write_heatmap(path, map, mask, ref->width, ref->height, 1.0f, "magma", e);
}

/* Approximation m of the scene: its DSSIM and FLIP, preview, heatmap and FLIP map. */
static int score_approx(const char *dir, const light_scene *ls, const image *ref, vec3 eye, int m,
                        const scene_model *model, float scale, float *approx, float *err, double *dssim,
                        double *flip, gt_error *e)
{
    sphere_light_gbuffer g = gbuffer_of(ref);
    const float *want = image_channel_data(ref, CH_SPHERE_G);
    if (model->specular)
        sphere_light_shade_specular(&g, eye, &ls->light, SPHERE_F0_DIELECTRIC, model->specular, model->user, approx);
    else
        sphere_light_shade(&g, eye, &ls->light, SPHERE_F0_DIELECTRIC, model->user, approx);
    ssim_result r;
    char path[8192];
    if (ssim_compute(approx, want, g.mask, ref->width, ref->height, approx_names[m], NULL, &r, e) != 0)
        return -1;
    *dssim = r.dssim;
    if (flip_map(dir, ls, ref, m, want, approx, g.mask, err, flip, e) != 0)
        return -1;
    for (size_t i = 0; i < g.count; ++i)
        err[i] = fabsf(approx[i] - want[i]);
    snprintf(path, sizeof path, "%s/scene_%s_%s.png", dir, ls->name, sphere_scene_approx_files[m]);
    if (image_write_preview(path, (const float *const *)&approx, 1, ref->width, ref->height, 1.0f / scale, e) != 0)
        return -1;
    snprintf(path, sizeof path, "%s/scene_%s_%s_error.png", dir, ls->name, sphere_scene_approx_files[m]);
    return image_write_heatmap(path, err, g.mask, ref->width, ref->height, 0.5f * scale, "inferno", e);
}

/* The reference's EXR, noise floor and preview; then each approximation. */
static int score_scene(const char *dir, const light_scene *ls, const image *ref, vec3 eye,
                       const scene_model models[SPHERE_SCENE_APPROX], sphere_scene_row *row, gt_error *e)
{
    size_t n = image_pixel_count(ref);
    const float *mask = image_channel_data(ref, CH_MASK), *want = image_channel_data(ref, CH_SPHERE_G);
    char path[8192];
    snprintf(path, sizeof path, "%s/scene_%s.exr", dir, ls->name);
    ssim_result floor;
    if (ssim_noise_floor(ref, path, CH_SPHERE_G, mask, &floor, e) != 0 || exr_write(path, ref, e) != 0)
        return -1;
    row->noise_floor = floor.dssim;
    float scale = percentile99(want, mask, n);
    snprintf(path, sizeof path, "%s/scene_%s_reference.png", dir, ls->name);
    if (image_write_preview(path, &want, 1, ref->width, ref->height, 1.0f / scale, e) != 0)
        return -1;
    float *approx = malloc(n * sizeof *approx), *err = malloc(n * sizeof *err);
    double *dssim[SPHERE_SCENE_APPROX] = {&row->karis, &row->decima, &row->refit, &row->ltc};
    double *flip[SPHERE_SCENE_APPROX] = {&row->karis_flip, &row->decima_flip, &row->refit_flip, &row->ltc_flip};
    int rc = approx && err ? 0 : gt_error_set(e, dir, "out of memory");
    for (int m = 0; m < SPHERE_SCENE_APPROX && rc == 0; ++m)
        rc = score_approx(dir, ls, ref, eye, m, &models[m], scale, approx, err, dssim[m], flip[m], e);
    free(approx), free(err);
    return rc;
}

/* Renders one scene, compares, writes EXR, previews and heatmaps. */
static int compare_scene(const study_context *ctx, const char *dir, const light_scene *ls,
                         const decima_sphere_constants *refit, const ltc_table *ltc, sphere_scene_row *row,
                         gt_error *e)
{
    const sphere_light_quality *q = sphere_light_quality_of(ctx->quality);
    /* Half a unit above the floor, looking 6 units ahead: grazing view. */
    camera cam = {v3(0.0f, 0.5f, 6.0f), v3(0.0f, 0.0f, -2.0f), v3(0.0f, 1.0f, 0.0f), (float)(40.0 * M_PI / 180.0),
                  q->floor_width, q->floor_height};
    image ref;
    if (render_floor(ctx, ls, &cam, &ref, e) != 0)
        return -1;
    const decima_sphere_constants published = decima_sphere_published();
    const scene_model models[SPHERE_SCENE_APPROX] = {
        {NULL, NULL}, {NULL, &published}, {NULL, refit}, {ltc_sphere_specular, ltc}};
    row->name = ls->name, row->title = ls->title;
    row->width = ref.width, row->height = ref.height;
    int rc = score_scene(dir, ls, &ref, cam.position, models, row, e);
    image_free(&ref);
    return rc;
}

/* One reference of the sphere over the floor, with or without shadows. */
static int render_sphere_on_plane(const study_context *ctx, const camera *cam, int shadows, image *out, gt_error *e)
{
    scene s;
    if (scene_load("builtin:sphere-on-plane", &s, e) != 0)
        return -1;
    reference_request req;
    memset(&req, 0, sizeof req);
    req.quantity = QUANTITY_SPHERE_LIGHT;
    req.sampling = (sampling_settings){.spp = sphere_light_quality_of(ctx->quality)->scene_spp, .seed = 1,
                                       .threads = ctx->threads};
    req.normals = NORMAL_SHADING;
    sphere_light_quantity_settings light =
        sphere_light_quantity_settings_of((sphere_light_settings){v3(-2.5f, 4.0f, 1.5f), 0.5f, 5.0f, shadows});
    req.settings = &light.header;
    render_stats stats;
    int rc = reference_render(&s, "builtin:sphere-on-plane", cam, &req, out, &stats, e);
    scene_free(&s);
    return rc;
}

/* The share of visible pixels losing more than a tenth of their light, the
 * DSSIM and the two previews. */
static int compare_shadows(const char *dir, const image *plain, const image *shadowed, sphere_shadow_result *out,
                           gt_error *e)
{
    const float *mask = image_channel_data(plain, CH_MASK);
    const float *planes[2] = {image_channel_data(plain, CH_SPHERE_G), image_channel_data(shadowed, CH_SPHERE_G)};
    size_t n = image_pixel_count(plain), covered = 0, darkened = 0;
    for (size_t i = 0; i < n; ++i) {
        covered += mask[i] != 0.0f;
        darkened += mask[i] != 0.0f && planes[1][i] < 0.9f * planes[0][i];
    }
    float scale = percentile99(planes[0], mask, n);
    ssim_result r;
    char path[8192];
    int rc = ssim_compute(planes[1], planes[0], mask, plain->width, plain->height, "shadowed", NULL, &r, e);
    static const char *const names[2] = {"unshadowed", "shadowed"};
    for (int k = 0; k < 2 && rc == 0; ++k) {
        snprintf(path, sizeof path, "%s/scene_shadows_%s.png", dir, names[k]);
        rc = image_write_preview(path, &planes[k], 1, plain->width, plain->height, 1.0f / scale, e);
    }
    out->dssim = r.dssim;
    out->share_darkened = covered ? (double)darkened / covered : 0.0;
    return rc;
}

/* What none of the approximations models: the same light with --shadows. */
static int shadow_comparison(const study_context *ctx, const char *dir, sphere_shadow_result *out, gt_error *e)
{
    const sphere_light_quality *q = sphere_light_quality_of(ctx->quality);
    camera cam = {v3(0.0f, 3.0f, 7.0f), v3(0.0f, 0.7f, 0.0f), v3(0.0f, 1.0f, 0.0f), (float)(40.0 * M_PI / 180.0),
                  q->shadows_width, q->shadows_height};
    image plain, shadowed;
    if (render_sphere_on_plane(ctx, &cam, 0, &plain, e) != 0)
        return -1;
    if (render_sphere_on_plane(ctx, &cam, 1, &shadowed, e) != 0) {
        image_free(&plain);
        return -1;
    }
    int rc = compare_shadows(dir, &plain, &shadowed, out, e);
    image_free(&plain);
    image_free(&shadowed);
    return rc;
}

int sphere_scenes_study(const study_context *ctx, const char *dir, const decima_sphere_constants *refit,
                        const ltc_table *ltc, sphere_scene_row rows[SPHERE_SCENES], sphere_shadow_result *shadows,
                        gt_error *e)
{
    /* The sun: 0.27 deg, 6 deg above the horizon ahead of the camera, its
     * radiance such that its normal illuminance is 1. A large light: radius
     * 1 at ~9 units, low ahead, normal illuminance 1 at 5 units. */
    const double sun_sin = 0.00465, sun_elev = 6.0 * M_PI / 180.0;
    const light_scene scenes[SPHERE_SCENES] = {
        {"sun", "sun-sized light (0.27 deg) 6 deg above the horizon",
         {v3(0.0f, (float)(1000.0 * sin(sun_elev)), (float)(-1000.0 * cos(sun_elev))), (float)(1000.0 * sun_sin),
          (float)(1.0 / (M_PI * sun_sin * sun_sin))}},
        {"large", "large light: radius 1 at 9 units, 1.5 units up", {v3(0.0f, 1.5f, -9.0f), 1.0f, (float)(25.0 / M_PI)}},
    };
    for (int k = 0; k < SPHERE_SCENES; ++k)
        if (compare_scene(ctx, dir, &scenes[k], refit, ltc, &rows[k], e) != 0)
            return -1;
    return shadow_comparison(ctx, dir, shadows, e);
}
