/* Anti-aliasing against supersampled truth (anti_aliasing/anti_aliasing_study.h). */
#include "anti_aliasing/anti_aliasing_study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "anti_aliasing/anti_aliasing_quality.h"
#include "anti_aliasing/fxaa.h"
#include "core/files/image_io.h"
#include "core/optics/srgb.h" /* srgb_to_linear */
#include "metrics/image_error.h"
#include "metrics/ssim.h"
#include "raytracer/shaded_frame.h"

static const char *const technique_names[AA_TECHNIQUES] = {"no AA (1 sample)", "FXAA 3.11", "SSAA 2x2 (box)"};

aa_request aa_default_request(study_quality quality)
{
    const anti_aliasing_quality *q = anti_aliasing_quality_of(quality);
    aa_request rq = {q->image_width, q->image_height, {"builtin:boxes", "builtin:menger", "builtin:cornell"}, 3, 19u,
                     aa_temporal_default_request(quality)};
    return rq;
}

/* Work images of one scene: RGB display values (3 floats a pixel). */
typedef struct {
    int width, height;
    float *truth[PIXEL_FILTER_COUNT], *truth16[PIXEL_FILTER_COUNT], *technique[AA_TECHNIQUES];
    float *samples, *xy, *luma_a, *luma_b;
} aa_images;

static void to_display(float *rgb, size_t values)
{
    for (size_t k = 0; k < values; ++k)
        rgb[k] = aa_display(rgb[k]);
}

static int alloc_images(aa_images *im, int w, int h)
{
    size_t px = (size_t)w * h, big = px * 64;
    memset(im, 0, sizeof *im);
    im->width = w, im->height = h;
    int ok = (im->samples = malloc(3 * big * sizeof(float))) && (im->xy = malloc(2 * big * sizeof(float))) &&
             (im->luma_a = malloc(px * sizeof(float))) && (im->luma_b = malloc(px * sizeof(float)));
    for (int f = 0; f < PIXEL_FILTER_COUNT; ++f)
        ok = ok && (im->truth[f] = malloc(3 * px * sizeof(float))) && (im->truth16[f] = malloc(3 * px * sizeof(float)));
    for (int t = 0; t < AA_TECHNIQUES; ++t)
        ok = ok && (im->technique[t] = malloc(3 * px * sizeof(float)));
    return ok ? 0 : -1;
}

static void free_images(aa_images *im)
{
    for (int f = 0; f < PIXEL_FILTER_COUNT; ++f)
        free(im->truth[f]), free(im->truth16[f]);
    for (int t = 0; t < AA_TECHNIQUES; ++t)
        free(im->technique[t]);
    free(im->samples), free(im->xy), free(im->luma_a), free(im->luma_b);
}

/* Supersamples at s x s per pixel, resolved by every filter into `out`, displayed. */
static void render_truth(const embree_scene *es, const camera *cam, const frame_lighting *light, int s, unsigned seed,
                         int threads, aa_images *im, float **out)
{
    shaded_frame_render_supersampled(es, cam, light, s, seed, threads, im->samples, im->xy);
    for (int f = 0; f < PIXEL_FILTER_COUNT; ++f) {
        pixel_filter_resolve((pixel_filter)f, im->samples, im->xy, im->width, im->height, s, threads, out[f]);
        to_display(out[f], 3 * (size_t)im->width * im->height);
    }
}

static int render_techniques(const embree_scene *es, const camera *cam, const frame_lighting *light, int threads,
                             aa_images *im, gt_error *e)
{
    size_t values = 3 * (size_t)im->width * im->height;
    const float centre[2] = {0.0f, 0.0f};
    shaded_frame_render(es, cam, light, centre, threads, im->technique[0]);
    to_display(im->technique[0], values);
    fxaa_settings fx = fxaa_default_settings();
    if (fxaa_apply(&fx, im->technique[0], im->width, im->height, threads, im->technique[1]) != 0)
        return gt_error_set(e, "anti-aliasing", "out of memory");
    shaded_frame_render_supersampled(es, cam, light, 2, 7u, threads, im->samples, im->xy);
    pixel_filter_resolve(PIXEL_FILTER_BOX, im->samples, im->xy, im->width, im->height, 2, threads, im->technique[2]);
    to_display(im->technique[2], values);
    return 0;
}

static void display_luma(const float *rgb, size_t pixels, float *luma)
{
    for (size_t k = 0; k < pixels; ++k)
        luma[k] = 0.2126f * rgb[3 * k] + 0.7152f * rgb[3 * k + 1] + 0.0722f * rgb[3 * k + 2];
}

static double rmse(const float *a, const float *b, size_t values)
{
    double s = 0.0;
    for (size_t k = 0; k < values; ++k)
        s += ((double)a[k] - b[k]) * ((double)a[k] - b[k]);
    return sqrt(s / values);
}

static int score(aa_images *im, const float *got, const float *truth, double *r, double *dssim, gt_error *e)
{
    size_t px = (size_t)im->width * im->height;
    *r = rmse(got, truth, 3 * px);
    display_luma(got, px, im->luma_a);
    display_luma(truth, px, im->luma_b);
    ssim_result s;
    if (ssim_compute(im->luma_b, im->luma_a, NULL, im->width, im->height, "anti-aliasing", NULL, &s, e) != 0)
        return -1;
    *dssim = s.dssim;
    return 0;
}

/* A display image as a preview (decoded to linear: the writer encodes sRGB). */
static int write_preview(const char *dir, const char *name, const aa_images *im, const float *rgb, gt_error *e)
{
    size_t px = (size_t)im->width * im->height;
    float *planes[3] = {malloc(px * sizeof(float)), malloc(px * sizeof(float)), malloc(px * sizeof(float))};
    int rc = planes[0] && planes[1] && planes[2] ? 0 : gt_error_set(e, dir, "out of memory");
    for (size_t k = 0; k < px && rc == 0; ++k)
        for (int c = 0; c < 3; ++c)
            planes[c][k] = (float)srgb_to_linear(rgb[3 * k + c]);
    char path[4096 + 64];
    snprintf(path, sizeof path, "%s/%s.png", dir, name);
    if (rc == 0)
        rc = image_write_preview(path, (const float *const *)planes, 3, im->width, im->height, 1.0f, e);
    free(planes[0]), free(planes[1]), free(planes[2]);
    return rc;
}

static int write_previews(const char *dir, const aa_images *im, gt_error *e)
{
    static const char *const names[AA_TECHNIQUES] = {"no_aa", "fxaa", "ssaa4"};
    int rc = write_preview(dir, "truth_blackman_harris", im, im->truth[PIXEL_FILTER_BLACKMAN_HARRIS], e);
    for (int t = 0; t < AA_TECHNIQUES && rc == 0; ++t)
        rc = write_preview(dir, names[t], im, im->technique[t], e);
    return rc;
}

static int score_scene(const char *spec, aa_images *im, aa_result *out, gt_error *e)
{
    size_t values = 3 * (size_t)im->width * im->height;
    for (int f = 0; f < PIXEL_FILTER_COUNT; ++f) {
        aa_truth_row *t = &out->truth[out->truth_count++];
        *t = (aa_truth_row){spec, pixel_filter_name(f), rmse(im->truth16[f], im->truth[f], values)};
        for (int k = 0; k < AA_TECHNIQUES; ++k) {
            aa_row *row = &out->rows[out->row_count++];
            *row = (aa_row){spec, technique_names[k], pixel_filter_name(f), 0.0, 0.0};
            if (score(im, im->technique[k], im->truth[f], &row->rmse, &row->dssim, e) != 0)
                return -1;
        }
    }
    return 0;
}

static int study_scene(const study_context *ctx, const aa_request *rq, const char *spec, const char *dir,
                       aa_images *im, aa_result *out, gt_error *e)
{
    scene s;
    camera cam;
    embree_scene es;
    if (study_load_view(spec, rq->width, rq->height, &s, &cam, e) != 0)
        return -1;
    int rc = embree_scene_build(&s, &es, e);
    if (rc == 0) {
        frame_lighting light = frame_lighting_default();
        render_truth(&es, &cam, &light, 8, rq->seed, ctx->threads, im, im->truth);
        render_truth(&es, &cam, &light, 4, rq->seed + 1, ctx->threads, im, im->truth16);
        rc = render_techniques(&es, &cam, &light, ctx->threads, im, e);
        if (rc == 0)
            rc = score_scene(spec, im, out, e);
        if (rc == 0 && out->truth_count == PIXEL_FILTER_COUNT)
            rc = write_previews(dir, im, e);
        embree_scene_release(&es);
    }
    scene_free(&s);
    return rc;
}

int aa_study(const study_context *ctx, const aa_request *rq, aa_result *out, gt_error *e)
{
    char dir[4096];
    memset(out, 0, sizeof *out);
    out->request = *rq;
    if (study_make_dir(ctx, AA_DIR, dir, sizeof dir, e) != 0)
        return -1;
    aa_images im;
    int rc = alloc_images(&im, rq->width, rq->height) == 0 ? 0 : gt_error_set(e, dir, "out of memory");
    for (int k = 0; k < rq->scene_count && rc == 0; ++k)
        rc = study_scene(ctx, rq, rq->scenes[k], dir, &im, out, e);
    free_images(&im);
    if (rc == 0 && rq->temporal.frames > 0)
        rc = aa_temporal_study(ctx, &rq->temporal, &out->temporal, e);
    return rc;
}
