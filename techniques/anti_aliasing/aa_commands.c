/* The anti-aliasing commands' work (aa_commands.h). */
#include "anti_aliasing/aa_commands.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "anti_aliasing/frames_render.h"
#include "anti_aliasing/taa_sampling.h"
#include "core/files/exr_io.h"
#include "core/files/image_io.h"
#include "core/sampling/pixel_filter.h"
#include "core/reference_schema.h"
#include "core/optics/srgb.h" /* srgb_to_linear */
#include "raytracer/shaded_frame.h"
#include "scene/camera_path.h"

static const char *const names[AA_T_TECHNIQUES] = {"none", "fxaa", "taa", "edge-taa", "checkerboard"};

int aa_technique_parse(const char *name)
{
    for (int t = 0; t < AA_T_TECHNIQUES; ++t)
        if (!strcmp(name, names[t]))
            return t;
    return -1;
}

const char *aa_technique_short_name(int technique) { return names[technique]; }

/* The jitter the technique renders frame k with (the study's). */
static void technique_jitter(int technique, int k, float jitter[2])
{
    jitter[0] = jitter[1] = technique == 4 ? -0.5f : 0.0f;
    if (technique == 2)
        taa_halton_jitter(k, 8, jitter);
    if (technique == 3)
        taa_edge_jitter(k, jitter);
}

static camera_path request_path(const aa_frames_request *rq, const camera *cam)
{
    camera_path path = camera_path_static(cam);
    path.step = v3(rq->step[0], rq->step[1], rq->step[2]);
    path.yaw_step = (float)(rq->yaw_deg * 3.14159265358979323846 / 180.0);
    return path;
}

/* The truth's three planes and its header line, when it was rendered. */
static int add_truth(image *img, const aa_frames_request *rq, const float *truth)
{
    static const char *const names[3] = CH_FRAME_TRUTH_RGB;
    size_t px = image_pixel_count(img);
    for (int c = 0; c < 3; ++c) {
        float *plane = image_add_channel(img, names[c]);
        if (!plane)
            return -1;
        for (size_t p = 0; p < px; ++p)
            plane[p] = truth[3 * p + (size_t)c];
    }
    char text[128];
    snprintf(text, sizeof text, "%d x %d strata, %s, seed %u", rq->truth_strata, rq->truth_strata,
             pixel_filter_name(rq->truth_filter), AA_FRAMES_TRUTH_SEED);
    return image_set_attribute(img, ATTR_TRUTH, text);
}

/* One frame's EXR: channels, its jitter and index, the truth if any. */
static int write_frame_exr(const char *path, const aa_frames_request *rq, const frame_buffers *f, const float *truth,
                           int width, int height, const float jitter[2], int k, gt_error *e)
{
    static const char *const rgb[3] = CH_FRAME_RGB;
    image img;
    if (image_init(&img, width, height) != 0)
        return gt_error_set(e, path, "out of memory");
    float *planes[7];
    const char *channel[7] = {rgb[0], rgb[1], rgb[2], CH_DEPTH, CH_MOTION_X, CH_MOTION_Y, CH_DISOCCLUDED};
    int ok = 1;
    for (int c = 0; c < 7; ++c)
        ok = ok && (planes[c] = image_add_channel(&img, channel[c]));
    for (size_t p = 0; ok && p < (size_t)width * height; ++p) {
        planes[0][p] = f->rgb[3 * p], planes[1][p] = f->rgb[3 * p + 1], planes[2][p] = f->rgb[3 * p + 2];
        planes[3][p] = f->depth[p], planes[4][p] = f->motion[2 * p], planes[5][p] = f->motion[2 * p + 1];
        planes[6][p] = f->disoccluded[p];
    }
    char text[64];
    snprintf(text, sizeof text, "%.9g %.9g", jitter[0], jitter[1]);
    ok = ok && image_set_attribute(&img, ATTR_JITTER, text) == 0 && schema_set_int(&img, ATTR_FRAME, k) == 0;
    ok = ok && (!truth || add_truth(&img, rq, truth) == 0);
    int rc = ok ? exr_write(path, &img, e) : gt_error_set(e, path, "out of memory");
    image_free(&img);
    return rc;
}

typedef struct {
    scene s;
    camera cam;
    embree_scene es;
    camera_path path;
} loaded_view;

static int load(const aa_frames_request *rq, loaded_view *v, gt_error *e)
{
    if (study_load_view(rq->scene, rq->width, rq->height, &v->s, &v->cam, e) != 0)
        return -1;
    if (embree_scene_build(&v->s, &v->es, e) != 0)
        return scene_free(&v->s), -1;
    v->path = request_path(rq, &v->cam);
    return 0;
}

static void unload(loaded_view *v)
{
    embree_scene_release(&v->es);
    scene_free(&v->s);
}

/* The truth of one frame: (W s) x (H s) samples in `samples` and `xy`, resolved into truth. */
static void render_truth(const aa_frames_request *rq, const loaded_view *v, const camera *cam, float *samples,
                         float *xy, float *truth)
{
    const frame_lighting light = frame_lighting_default();
    int s = rq->truth_strata;
    shaded_frame_render_supersampled(&v->es, cam, &light, s, AA_FRAMES_TRUTH_SEED, rq->threads, samples, xy);
    pixel_filter_resolve((pixel_filter)rq->truth_filter, samples, xy, cam->width, cam->height, s, rq->threads, truth);
}

/* Scratch for the truth: its samples, their positions and the image; all NULL without one. */
typedef struct {
    float *samples, *xy, *truth;
} truth_buffers;

static int truth_alloc(truth_buffers *t, const aa_frames_request *rq, int width, int height)
{
    size_t px = (size_t)width * height, s2 = (size_t)rq->truth_strata * (size_t)rq->truth_strata;
    *t = (truth_buffers){NULL, NULL, NULL};
    if (rq->truth_strata <= 0)
        return 0;
    t->samples = malloc(sizeof(float) * 3 * px * s2);
    t->xy = malloc(sizeof(float) * 2 * px * s2);
    t->truth = malloc(sizeof(float) * 3 * px);
    return t->samples && t->xy && t->truth ? 0 : -1;
}

static void truth_free(truth_buffers *t)
{
    free(t->samples);
    free(t->xy);
    free(t->truth);
}

static int write_frames(const aa_frames_request *rq, const loaded_view *v, frame_buffers *f, truth_buffers *t,
                        gt_error *e)
{
    const frame_lighting light = frame_lighting_default();
    int rc = 0;
    for (int k = 0; k < rq->frames && rc == 0; ++k) {
        camera now = camera_path_at(&v->path, k), before = camera_path_at(&v->path, k > 0 ? k - 1 : 0);
        float jitter[2];
        technique_jitter(rq->technique, k, jitter);
        frames_render(&v->es, &now, k > 0 ? &before : NULL, &light, jitter, rq->threads, f);
        if (t->truth)
            render_truth(rq, v, &now, t->samples, t->xy, t->truth);
        char path[4096 + 32];
        snprintf(path, sizeof path, "%s/frame_%03d.exr", rq->dir, k);
        rc = write_frame_exr(path, rq, f, t->truth, v->cam.width, v->cam.height, jitter, k, e);
    }
    return rc;
}

int aa_frames_write(const aa_frames_request *rq, gt_error *e)
{
    loaded_view v;
    frame_buffers f;
    truth_buffers t = {NULL, NULL, NULL};
    if (load(rq, &v, e) != 0)
        return -1;
    int rc = frame_buffers_alloc(&f, v.cam.width, v.cam.height) == 0 &&
                     truth_alloc(&t, rq, v.cam.width, v.cam.height) == 0
                 ? write_frames(rq, &v, &f, &t, e)
                 : gt_error_set(e, rq->dir, "out of memory");
    truth_free(&t);
    frame_buffers_free(&f);
    unload(&v);
    return rc;
}

/* A display image as EXR (frame.R/G/B) and PNG, base path without extension. */
static int write_display(const char *base, const float *rgb, int width, int height, gt_error *e)
{
    static const char *const names_rgb[3] = CH_FRAME_RGB;
    size_t px = (size_t)width * height;
    image img;
    if (image_init(&img, width, height) != 0)
        return gt_error_set(e, base, "out of memory");
    float *planes[3] = {image_add_channel(&img, names_rgb[0]), image_add_channel(&img, names_rgb[1]),
                        image_add_channel(&img, names_rgb[2])};
    int rc = planes[0] && planes[1] && planes[2] ? 0 : gt_error_set(e, base, "out of memory");
    for (size_t p = 0; rc == 0 && p < px; ++p)
        for (int c = 0; c < 3; ++c)
            planes[c][p] = (float)srgb_to_linear(rgb[3 * p + c]);
    char path[4096 + 32];
    snprintf(path, sizeof path, "%s.png", base);
    if (rc == 0)
        rc = image_write_preview(path, (const float *const *)planes, 3, width, height, 1.0f, e);
    for (size_t p = 0; rc == 0 && p < px; ++p)
        for (int c = 0; c < 3; ++c)
            planes[c][p] = rgb[3 * p + c];
    snprintf(path, sizeof path, "%s.exr", base);
    if (rc == 0)
        rc = exr_write(path, &img, e);
    image_free(&img);
    return rc;
}

int aa_approx(const aa_frames_request *rq, gt_error *e)
{
    loaded_view v;
    if (load(rq, &v, e) != 0)
        return -1;
    aa_work *w = aa_work_new(v.cam.width, v.cam.height);
    int rc = w ? 0 : gt_error_set(e, rq->dir, "out of memory");
    for (int k = 0; k < rq->frames && rc == 0; ++k) {
        camera now = camera_path_at(&v.path, k), before = camera_path_at(&v.path, k > 0 ? k - 1 : 0);
        rc = aa_work_frame(w, &v.es, &now, k > 0 ? &before : NULL, k, rq->threads) == 0
                 ? 0 : gt_error_set(e, rq->dir, "out of memory");
        char base[4096];
        snprintf(base, sizeof base, "%s/%s_%03d", rq->dir, names[rq->technique], k);
        if (rc == 0)
            rc = write_display(base, aa_work_output(w, rq->technique), v.cam.width, v.cam.height, e);
    }
    aa_work_delete(w);
    unload(&v);
    return rc;
}

int aa_bench(int threads, int frames, double ms[AA_T_TECHNIQUES], gt_error *e)
{
    enum { W = 1920, H = 1080 };
    float *input = malloc(3 * sizeof(float) * W * H), *motion = malloc(2 * sizeof(float) * W * H);
    aa_work *w = aa_work_new(W, H);
    int rc = input && motion && w ? 0 : gt_error_set(e, "bench aa", "out of memory");
    for (size_t p = 0; rc == 0 && p < (size_t)W * H; ++p) { /* edges every 7 and 5 pixels, a slow pan */
        for (int c = 0; c < 3; ++c)
            input[3 * p + c] = ((p % W) / 7 + (p / W) / 5 + c) % 3 == 0 ? 0.8f : 0.2f;
        motion[2 * p] = 0.7f, motion[2 * p + 1] = -0.3f;
    }
    for (int k = 0; k < frames && rc == 0; ++k)
        rc = aa_work_run(w, input, motion, k, threads) == 0 ? 0 : gt_error_set(e, "bench aa", "out of memory");
    for (int t = 0; t < AA_T_TECHNIQUES && rc == 0; ++t)
        ms[t] = 1e3 * aa_work_seconds(w, t) / frames;
    aa_work_delete(w);
    free(input), free(motion);
    return rc;
}

int aa_bench_print(FILE *out, int threads, gt_error *e)
{
    double ms[AA_T_TECHNIQUES];
    if (aa_bench(threads, 8, ms, e) != 0)
        return -1;
    for (int t = 0; t < AA_T_TECHNIQUES; ++t)
        fprintf(out, "%-13s %8.2f ms per 1080p frame (%d threads)\n", names[t], ms[t], threads);
    return 0;
}
