#include "ao/ao_references.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "ao/ao_quantity.h"
#include "ao/ao_quality.h"
#include "core/files/exr_io.h"
#include "core/files/image_io.h"
#include "core/reference_schema.h"
#include "metrics/noise_corrected.h"
#include "metrics/ssim.h"
#include "raytracer/reference_render.h"
#include "project/scene_list.h"

/* Samples, standard errors and throughput over the covered pixels. */
static void measure(const image *img, const render_stats *stats, ao_reference_row *r)
{
    const float *mask = image_channel_data(img, CH_MASK), *n = image_channel_data(img, CH_SPP);
    const float *err = image_channel_data(img, CH_AO_STDERR);
    double samples = 0.0, sum_err = 0.0, max_err = 0.0;
    int covered = 0;
    for (size_t i = 0; i < image_pixel_count(img); ++i) {
        if (mask[i] == 0.0f)
            continue;
        ++covered;
        samples += n[i];
        sum_err += err[i];
        max_err = fmax(max_err, err[i]);
    }
    r->width = img->width;
    r->height = img->height;
    r->covered_pixels = covered;
    r->seconds = stats->seconds;
    r->rays_per_second = stats->seconds > 0 ? (double)stats->rays / stats->seconds : 0.0;
    r->mean_spp = covered ? samples / covered : 0.0;
    r->mean_stderr = covered ? sum_err / covered : 0.0;
    r->max_stderr = max_err;
    r->noise_rmse = sqrt(noise_mean_variance(err, mask, image_pixel_count(img)));
}

/* The bent normal shown as 0.5 + 0.5 n (black off the surfaces). */
static int write_bent_preview(const image *img, const char *path, const char *name, gt_error *e)
{
    static const char *const axes[3] = CH_BENT_XYZ;
    image shown;
    float *bent[3];
    if (image_init(&shown, img->width, img->height) != 0)
        return gt_error_set(e, name, "out of memory");
    const float *mask = image_channel_data(img, CH_MASK);
    for (int a = 0; a < 3; ++a) {
        const float *src = image_channel_data(img, axes[a]);
        if (!(bent[a] = image_add_channel(&shown, axes[a]))) {
            image_free(&shown);
            return gt_error_set(e, name, "out of memory");
        }
        for (size_t i = 0; i < image_pixel_count(img); ++i)
            bent[a][i] = mask[i] != 0.0f ? 0.5f + 0.5f * src[i] : 0.0f;
    }
    int rc = image_write_preview(path, (const float *const *)bent, 3, img->width, img->height, 1.0f, e);
    image_free(&shown);
    return rc;
}

/* ao.V, the bent normal and the standard-error heatmap. */
static int write_previews(const image *img, const char *figures, const char *name, double max_stderr, gt_error *e)
{
    char path[4096];
    const float *ao = image_channel_data(img, CH_AO);
    snprintf(path, sizeof path, "%s/ao_%s.png", figures, name);
    if (image_write_preview(path, &ao, 1, img->width, img->height, 1.0f, e) != 0)
        return -1;
    snprintf(path, sizeof path, "%s/bent_%s.png", figures, name);
    if (write_bent_preview(img, path, name, e) != 0)
        return -1;
    snprintf(path, sizeof path, "%s/ao_stderr_%s.png", figures, name);
    return image_write_heatmap(path, image_channel_data(img, CH_AO_STDERR), image_channel_data(img, CH_MASK),
                               img->width, img->height, (float)fmax(max_stderr, 1e-6), "inferno", e);
}

/* The reference of one scene, rendered at its entry's camera. */
static int render_scene(const study_scene_entry *b, const reference_request *req, int size, image *img, camera *cam,
                        render_stats *stats, uint64_t *triangles, gt_error *e)
{
    scene s;
    if (study_scene_view(b, size, 0, &s, cam, e) != 0)
        return -1;
    int rc = reference_render(&s, b->spec, cam, req, img, stats, e);
    *triangles = scene_triangle_count(&s);
    scene_free(&s);
    return rc;
}

/* Renders, measures and writes one scene's reference and previews. */
static int study_scene(const study_scene_entry *b, const reference_request *req, int size, const char *refs,
                       const char *figures, ao_reference_row *row, gt_error *e)
{
    char path[4096];
    camera cam;
    image img;
    render_stats stats;
    memset(row, 0, sizeof *row);
    snprintf(row->scene, sizeof row->scene, "%s", b->label);
    if (render_scene(b, req, size, &img, &cam, &stats, &row->triangles, e) != 0)
        return -1;
    measure(&img, &stats, row);
    ssim_result floor;
    snprintf(path, sizeof path, "%s/%s.exr", refs, b->label);
    int rc = ssim_noise_floor(&img, path, CH_AO, image_channel_data(&img, CH_MASK), &floor, e);
    row->noise_floor_dssim = floor.dssim;
    if (rc == 0)
        rc = exr_write(path, &img, e);
    if (rc == 0) {
        snprintf(path, sizeof path, "%s/%s.camera.json", refs, b->label);
        rc = camera_write_json(path, &cam, e);
    }
    if (rc == 0)
        rc = write_previews(&img, figures, b->label, row->max_stderr, e);
    image_free(&img);
    return rc;
}

ao_references_request ao_references_default_request(study_quality quality)
{
    const ao_quality *q = ao_quality_of(quality);
    ao_references_request rq = {q->image_width, q->reference_spp, q->noise_budget, 1, 0};
    return rq;
}

int ao_references_study(const study_context *ctx, const ao_references_request *rq, ao_references_result *out,
                        gt_error *e)
{
    memset(out, 0, sizeof *out);
    out->request = *rq;
    reference_request req = {.quantity = QUANTITY_AO,
                             .sampling = {.spp = rq->spp, .seed = rq->seed, .target_stderr = rq->target_stderr,
                                          .threads = ctx->threads},
                             .normals = NORMAL_SHADING};
    char refs[2048], figures[2048];
    if (study_make_dir(ctx, AO_REFERENCES_DIR, refs, sizeof refs, e) != 0 ||
        study_make_dir(ctx, "figures", figures, sizeof figures, e) != 0)
        return -1;
    int scenes = rq->scene_count > 0 && rq->scene_count < study_scene_count(ctx) ? rq->scene_count
                                                                                 : study_scene_count(ctx);
    for (int i = 0; i < scenes && i < AO_REFERENCES_MAX_SCENES; ++i, ++out->count)
        if (study_scene(study_scene_at(ctx, i), &req, rq->size, refs, figures, &out->rows[i], e) != 0)
            return -1;
    return 0;
}
