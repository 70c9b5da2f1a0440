/* The combination images' scores and files (height_fog/aerial_perspective_study.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/exr_io.h"
#include "core/files/image_io.h"
#include "core/reference_schema.h"
#include "metrics/image_error.h"
#include "metrics/ssim.h"
#include "height_fog/aerial_perspective_parts.h"

static const char *const WHAT = "aerial perspective";

void aerial_file_name(const aerial_case *c, const char *kind, const char *suffix, char *out, size_t size)
{
    snprintf(out, size, "%s_%s_sun%02d%s", kind, c->weather, (int)c->sun_elevation_deg, suffix);
}

static int count_inside(const float *select, size_t n)
{
    int count = 0;
    for (size_t i = 0; i < n; ++i)
        count += metrics_in_mask(select, i);
    return count;
}

/* Mean of a plane inside select (0 when empty). */
static double plane_mean(const float *v, const float *select, size_t n)
{
    double sum = 0.0;
    int count = 0;
    for (size_t i = 0; i < n; ++i)
        if (metrics_in_mask(select, i))
            sum += v[i], ++count;
    return count ? sum / count : 0.0;
}

/* RMSE over RGB of a against b inside select (0 when empty); b = NULL: b = 0 (a's RMS). */
static double rgb_rmse(float *const a[3], float *const b[3], const float *select, size_t n)
{
    double sum = 0.0;
    int count = 0;
    for (int c = 0; c < 3; ++c)
        for (size_t i = 0; i < n; ++i)
            if (metrics_in_mask(select, i)) {
                double d = (double)a[c][i] - (b ? b[c][i] : 0.0f);
                sum += d * d, ++count;
            }
    return count ? sqrt(sum / count) : 0.0;
}

/* DSSIM of the green channels, both divided by the reference's largest green value. */
static int green_dssim(const aerial_rays *rays, const float *model, const float *reference, const float *select,
                       double *dssim, gt_error *e)
{
    size_t n = (size_t)rays->width * rays->height;
    float peak = 0.0f, *a = malloc(2 * n * sizeof(float));
    if (!a)
        return gt_error_set(e, WHAT, "out of memory");
    for (size_t i = 0; i < n; ++i)
        peak = metrics_in_mask(select, i) ? fmaxf(peak, reference[i]) : peak;
    for (size_t i = 0; i < n; ++i)
        a[i] = model[i] / (peak > 0.0f ? peak : 1.0f), a[n + i] = reference[i] / (peak > 0.0f ? peak : 1.0f);
    ssim_result s;
    int rc = ssim_compute(a, a + n, select, rays->width, rays->height, WHAT, NULL, &s, e);
    *dssim = s.dssim;
    free(a);
    return rc;
}

/* |model - reference| / reference (0 where the reference is 0), malloc'd; NULL out of memory. */
static float *relative_error_plane(const float *model, const float *reference, size_t n)
{
    float *rel = malloc(n * sizeof(float));
    for (size_t i = 0; rel && i < n; ++i)
        rel[i] = reference[i] > 0.0f ? fabsf(model[i] - reference[i]) / reference[i] : 0.0f;
    return rel;
}

/* The median over select of |model - reference| / reference. */
static int median_relative(const aerial_rays *rays, const float *model, const float *reference, const float *select,
                           double *median, gt_error *e)
{
    size_t n = (size_t)rays->width * rays->height;
    float *rel = relative_error_plane(model, reference, n), value = 0.0f;
    if (!rel)
        return gt_error_set(e, WHAT, "out of memory");
    int rc = metrics_percentile(rel, select, n, 50.0, WHAT, &value, e);
    *median = value;
    free(rel);
    return rc;
}

static int score_view(const aerial_rays *rays, const aerial_planes *p, aerial_case *c, gt_error *e)
{
    size_t n = (size_t)rays->width * rays->height;
    float *sky = malloc(n * sizeof(float));
    if (!sky)
        return gt_error_set(e, WHAT, "out of memory");
    for (size_t i = 0; i < n; ++i)
        sky[i] = rays->terrain[i] < 0.5f ? 1.0f : 0.0f;
    c->terrain_pixels = count_inside(rays->terrain, n), c->sky_pixels = count_inside(sky, n);
    c->reference_mean_terrain = plane_mean(p->reference[1], rays->terrain, n);
    c->reference_mean_sky = plane_mean(p->reference[1], sky, n);
    c->model_mean_sky = plane_mean(p->model[0][1], sky, n);
    c->rmse_sky = rgb_rmse(p->model[0], p->reference, sky, n);
    double rms = rgb_rmse(p->reference, NULL, NULL, n);
    int rc = 0;
    for (int m = 0; m < AERIAL_MODELS && rc == 0; ++m) {
        c->model_mean_terrain[m] = plane_mean(p->model[m][1], rays->terrain, n);
        c->rmse_terrain[m] = rgb_rmse(p->model[m], p->reference, rays->terrain, n);
        c->rmse_view[m] = rgb_rmse(p->model[m], p->reference, NULL, n);
        c->relative_rmse_view[m] = rms > 0.0 ? c->rmse_view[m] / rms : 0.0;
        rc = green_dssim(rays, p->model[m][1], p->reference[1], NULL, &c->dssim_view[m], e);
        if (rc == 0)
            rc = median_relative(rays, p->model[m][1], p->reference[1], NULL, &c->median_relative_view[m], e);
    }
    free(sky);
    return rc;
}

/* Model 0 against the reference inside the fisheye's circle. */
static int score_sky(const aerial_rays *rays, const aerial_planes *p, double *rmse, double *relative, double *dssim,
                     double *median, gt_error *e)
{
    size_t n = (size_t)rays->width * rays->height;
    *rmse = rgb_rmse(p->model[0], p->reference, rays->inside, n);
    double rms = rgb_rmse(p->reference, NULL, rays->inside, n);
    *relative = rms > 0.0 ? *rmse / rms : 0.0;
    if (green_dssim(rays, p->model[0][1], p->reference[1], rays->inside, dssim, e) != 0)
        return -1;
    return median_relative(rays, p->model[0][1], p->reference[1], rays->inside, median, e);
}

int aerial_score(const aerial_rays *rays, const aerial_planes *planes, int is_view, aerial_case *c, gt_error *e)
{
    if (is_view)
        return score_view(rays, planes, c, e);
    size_t n = (size_t)rays->width * rays->height;
    c->fisheye_pixels = count_inside(rays->inside, n);
    c->reference_mean_fisheye = plane_mean(planes->reference[1], rays->inside, n);
    c->model_mean_fisheye = plane_mean(planes->model[0][1], rays->inside, n);
    return score_sky(rays, planes, &c->rmse_fisheye, &c->relative_rmse_fisheye, &c->dssim_fisheye,
                     &c->median_relative_fisheye, e);
}

int aerial_score_fine(const aerial_rays *rays, const aerial_planes *planes, aerial_case *c, gt_error *e)
{
    return score_sky(rays, planes, &c->rmse_fisheye_fine, &c->relative_rmse_fisheye_fine, &c->dssim_fisheye_fine,
                     &c->median_relative_fisheye_fine, e);
}

/* ---- Files ----------------------------------------------------------------- */

/* Adds three channels holding planes (one at a time: adding may move the others). */
static int add_rgb(image *img, const char *const names[3], float *const planes[3])
{
    for (int c = 0; c < 3; ++c) {
        float *dst = image_add_channel(img, names[c]);
        if (!dst)
            return -1;
        memcpy(dst, planes[c], image_pixel_count(img) * sizeof(float));
    }
    return 0;
}

static int write_exr(const char *path, const aerial_rays *rays, const aerial_planes *p, const float *mask, gt_error *e)
{
    static const char *const ref[3] = CH_AERIAL_REFERENCE_RGB, *const model[3] = CH_AERIAL_MODEL_RGB;
    static const char *const corrected[3] = CH_AERIAL_CORRECTED_RGB;
    image img;
    if (image_init(&img, rays->width, rays->height) != 0)
        return gt_error_set(e, WHAT, "out of memory");
    int rc = add_rgb(&img, ref, p->reference) || add_rgb(&img, model, p->model[AERIAL_MODEL_PUBLISHED]) ||
             add_rgb(&img, corrected, p->model[AERIAL_MODEL_SKY_ATTENUATED]);
    float *m = rc == 0 ? image_add_channel(&img, CH_MASK) : NULL;
    if (!m)
        rc = gt_error_set(e, WHAT, "out of memory");
    else
        memcpy(m, mask, image_pixel_count(&img) * sizeof(float)), rc = exr_write(path, &img, e);
    image_free(&img);
    return rc;
}

/* The reference (left) and the published model (right), one exposure. */
static int write_side_by_side(const char *path, const aerial_rays *rays, const aerial_planes *p, gt_error *e)
{
    int w = rays->width, h = rays->height;
    float *block = calloc((size_t)6 * w * h, sizeof(float));
    if (!block)
        return gt_error_set(e, WHAT, "out of memory");
    const float *planes[3] = {block, block + 2 * (size_t)w * h, block + 4 * (size_t)w * h};
    for (int c = 0; c < 3; ++c)
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) {
                size_t k = (size_t)j * w + i;
                block[2 * (size_t)w * h * c + (size_t)j * 2 * w + i] = p->reference[c][k];
                block[2 * (size_t)w * h * c + (size_t)j * 2 * w + w + i] = p->model[AERIAL_MODEL_PUBLISHED][c][k];
            }
    double mean = plane_mean(p->reference[1], rays->inside, (size_t)w * h);
    int rc = image_write_preview(path, planes, 3, 2 * w, h, mean > 0.0 ? (float)(0.18 / mean) : 1.0f, e);
    free(block);
    return rc;
}

/* |model - reference| / reference of the published model, green. */
static int write_error(const char *path, const aerial_rays *rays, const aerial_planes *p, gt_error *e)
{
    float *rel = relative_error_plane(p->model[AERIAL_MODEL_PUBLISHED][1], p->reference[1],
                                      (size_t)rays->width * rays->height);
    if (!rel)
        return gt_error_set(e, WHAT, "out of memory");
    int rc = image_write_heatmap(path, rel, rays->inside, rays->width, rays->height, 0.5f, "inferno", e);
    free(rel);
    return rc;
}

int aerial_write(const char *dir, const char *kind, const aerial_rays *rays, const aerial_planes *planes,
                 const aerial_case *c, gt_error *e)
{
    char name[128], path[4096];
    int is_view = strcmp(kind, "aerial") == 0;
    aerial_file_name(c, kind, ".exr", name, sizeof name);
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (write_exr(path, rays, planes, is_view ? rays->terrain : rays->inside, e) != 0)
        return -1;
    aerial_file_name(c, kind, ".png", name, sizeof name);
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (write_side_by_side(path, rays, planes, e) != 0)
        return -1;
    aerial_file_name(c, kind, "_error.png", name, sizeof name);
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return write_error(path, rays, planes, e);
}
