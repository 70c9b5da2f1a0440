/* `gtlab all` stage: AO and bent-normal references of every built-in scene,
 * with their previews, standard-error maps and noise floors. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli/all_stages.h"
#include "core/exr_io.h"
#include "core/image_io.h"
#include "metrics/ssim.h"
#include "raytracer/reference_render.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_loaders.h"

typedef struct {
    double seconds, rays_per_second, mean_spp, mean_stderr, max_stderr, noise_floor_dssim;
    int covered;
} ao_figures;

static void measure(const image *img, const render_stats *stats, ao_figures *f)
{
    const float *mask = image_channel_data(img, "mask.A"), *n = image_channel_data(img, "spp.N");
    const float *err = image_channel_data(img, "ao.V.stderr");
    double spp = 0.0, sum_err = 0.0, max_err = 0.0;
    int covered = 0;
    for (size_t i = 0; i < image_pixel_count(img); ++i) {
        if (mask[i] == 0.0f)
            continue;
        ++covered;
        spp += n[i];
        sum_err += err[i];
        max_err = fmax(max_err, err[i]);
    }
    f->covered = covered;
    f->seconds = stats->seconds;
    f->rays_per_second = stats->seconds > 0 ? (double)stats->rays / stats->seconds : 0.0;
    f->mean_spp = covered ? spp / covered : 0.0;
    f->mean_stderr = covered ? sum_err / covered : 0.0;
    f->max_stderr = max_err;
}

/* ao.V, the bent normal as 0.5 + 0.5 n, and the standard-error heatmap. */
static int write_previews(const image *img, const char *figures, const char *name, double max_stderr, gt_error *e)
{
    char path[4096];
    const float *ao = image_channel_data(img, "ao.V");
    snprintf(path, sizeof path, "%s/ao_%s.png", figures, name);
    if (image_write_preview(path, &ao, 1, img->width, img->height, 1.0f, e) != 0)
        return -1;
    float *bent[3];
    const char *axes[3] = {"bent.X", "bent.Y", "bent.Z"};
    image shown;
    if (image_init(&shown, img->width, img->height) != 0)
        return gt_error_set(e, name, "out of memory");
    const float *mask = image_channel_data(img, "mask.A");
    for (int a = 0; a < 3; ++a) {
        const float *src = image_channel_data(img, axes[a]);
        if (!(bent[a] = image_add_channel(&shown, axes[a]))) {
            image_free(&shown);
            return gt_error_set(e, name, "out of memory");
        }
        for (size_t i = 0; i < image_pixel_count(img); ++i)
            bent[a][i] = mask[i] != 0.0f ? 0.5f + 0.5f * src[i] : 0.0f;
    }
    snprintf(path, sizeof path, "%s/bent_%s.png", figures, name);
    int rc = image_write_preview(path, (const float *const *)bent, 3, img->width, img->height, 1.0f, e);
    image_free(&shown);
    if (rc != 0)
        return -1;
    snprintf(path, sizeof path, "%s/ao_stderr_%s.png", figures, name);
    return image_write_heatmap(path, image_channel_data(img, "ao.V.stderr"), mask, img->width, img->height,
                               (float)fmax(max_stderr, 1e-6), "inferno", e);
}

static void add_row(all_context *ctx, const char *name, uint64_t triangles, const image *img, const ao_figures *f)
{
    char cells[9][64];
    snprintf(cells[0], 64, "%s", name);
    snprintf(cells[1], 64, "%llu", (unsigned long long)triangles);
    snprintf(cells[2], 64, "%dx%d", img->width, img->height);
    snprintf(cells[3], 64, "%.0f", f->mean_spp);
    snprintf(cells[4], 64, "%.2f", f->seconds);
    snprintf(cells[5], 64, "%.1f", f->rays_per_second * 1e-6);
    snprintf(cells[6], 64, "%.2e", f->mean_stderr);
    snprintf(cells[7], 64, "%.2e", f->max_stderr);
    snprintf(cells[8], 64, "%.2e", f->noise_floor_dssim);
    const char *row[9];
    for (int i = 0; i < 9; ++i)
        row[i] = cells[i];
    report_table_row(ctx->doc, row);
}

static void add_json(cJSON *list, const char *name, uint64_t triangles, const image *img, const ao_figures *f)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "scene", name);
    cJSON_AddNumberToObject(o, "triangles", (double)triangles);
    cJSON_AddNumberToObject(o, "width", img->width);
    cJSON_AddNumberToObject(o, "height", img->height);
    cJSON_AddNumberToObject(o, "covered_pixels", f->covered);
    cJSON_AddNumberToObject(o, "mean_spp", f->mean_spp);
    cJSON_AddNumberToObject(o, "seconds", f->seconds);
    cJSON_AddNumberToObject(o, "rays_per_second", f->rays_per_second);
    cJSON_AddNumberToObject(o, "mean_stderr_ao", f->mean_stderr);
    cJSON_AddNumberToObject(o, "max_stderr_ao", f->max_stderr);
    cJSON_AddNumberToObject(o, "noise_floor_dssim_ao", f->noise_floor_dssim);
    cJSON_AddItemToArray(list, o);
}

static int render_scene(all_context *ctx, const builtin_scene *b, const char *refs, const char *figures,
                        const reference_request *req, int size, cJSON *list, gt_error *e)
{
    char spec[128], path[4096];
    snprintf(spec, sizeof spec, "builtin:%s", b->name);
    scene s;
    if (scene_load(spec, &s, e) != 0)
        return -1;
    camera cam;
    image img;
    render_stats stats;
    int rc = scene_choose_camera(&s, NULL, size, 0, &cam, e);
    if (rc == 0)
        rc = reference_render(&s, spec, &cam, req, &img, &stats, e);
    uint64_t triangles = scene_triangle_count(&s);
    scene_free(&s);
    if (rc != 0)
        return -1;
    ao_figures f;
    measure(&img, &stats, &f);
    ssim_result floor;
    snprintf(path, sizeof path, "%s/%s.exr", refs, b->name);
    rc = ssim_noise_floor(&img, path, "ao.V", image_channel_data(&img, "mask.A"), &floor, e);
    f.noise_floor_dssim = floor.dssim;
    if (rc == 0)
        rc = exr_write(path, &img, e);
    if (rc == 0) {
        snprintf(path, sizeof path, "%s/%s.camera.json", refs, b->name);
        rc = camera_write_json(path, &cam, e);
    }
    if (rc == 0)
        rc = write_previews(&img, figures, b->name, f.max_stderr, e);
    if (rc == 0) {
        add_row(ctx, b->name, triangles, &img, &f);
        add_json(list, b->name, triangles, &img, &f);
    }
    image_free(&img);
    return rc;
}

static void add_figures(all_context *ctx)
{
    for (int i = 0; i < builtin_scene_count(); ++i) {
        const char *name = builtin_scene_at(i)->name;
        char paths[3][256], captions[3][256];
        snprintf(paths[0], 256, "figures/ao_%s.png", name);
        snprintf(paths[1], 256, "figures/bent_%s.png", name);
        snprintf(paths[2], 256, "figures/ao_stderr_%s.png", name);
        snprintf(captions[0], 256, "%s: cosine AO", name);
        snprintf(captions[1], 256, "%s: bent normal (0.5 + 0.5 n)", name);
        snprintf(captions[2], 256, "%s: standard error of AO", name);
        const char *p[3] = {paths[0], paths[1], paths[2]}, *c[3] = {captions[0], captions[1], captions[2]};
        report_figures(ctx->doc, 3, p, c);
    }
}

int all_stage_ao_references(all_context *ctx, gt_error *e)
{
    int preview = ctx->quality == QUALITY_PREVIEW;
    int size = preview ? 256 : 512;
    reference_request req = {.quantity = QUANTITY_AO,
                             .sampling = {.spp = preview ? 256 : 4096, .seed = 1,
                                          .target_stderr = preview ? 0.0 : 0.002, .threads = ctx->threads},
                             .normals = NORMAL_SHADING, .max_distance = INFINITY};
    char refs[2048], figures[2048];
    if (all_make_dir(ctx, "ao", refs, sizeof refs, e) != 0 || all_make_dir(ctx, "figures", figures, sizeof figures, e))
        return -1;
    report_heading(ctx->doc, 2, "Ambient occlusion and bent-normal references");
    report_paragraph(ctx->doc,
                     "Cosine-weighted AO V_d = (1/pi) integral of V(w) (n.w) over the hemisphere, uniform AO and "
                     "the bent normal, at the surface seen through each pixel centre, rendered with Embree from "
                     "Owen-scrambled Sobol' samples (%d per pixel at most%s; seed 1). Standard errors are per "
                     "pixel, from the samples themselves. The noise floor is the DSSIM between the AO of the even "
                     "and of the odd samples: no approximation can be scored more finely than that.",
                     req.sampling.spp, preview ? "" : ", stopping at a standard error of 0.002");
    static const char *const headers[9] = {"scene", "triangles", "size", "mean spp", "seconds", "Mrays/s",
                                           "mean stderr", "max stderr", "noise floor (DSSIM)"};
    report_table_begin(ctx->doc, 9, headers);
    cJSON *list = cJSON_AddArrayToObject(ctx->summary, "ao_references");
    int rc = 0;
    for (int i = 0; i < builtin_scene_count() && rc == 0; ++i)
        rc = render_scene(ctx, builtin_scene_at(i), refs, figures, &req, size, list, e);
    report_table_end(ctx->doc);
    if (rc == 0)
        add_figures(ctx);
    return rc;
}
