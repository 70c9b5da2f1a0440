/* Temporal anti-aliasing against supersampled truth (anti_aliasing/aa_temporal_study.h). */
#include "anti_aliasing/aa_temporal_study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "anti_aliasing/anti_aliasing_quality.h"
#include "anti_aliasing/anti_aliasing_study.h" /* AA_DIR */
#include "anti_aliasing/checkerboard.h"
#include "anti_aliasing/frames_render.h"
#include "anti_aliasing/fxaa.h"
#include "anti_aliasing/taa_accumulate.h"
#include "anti_aliasing/taa_edge.h"
#include "anti_aliasing/taa_sampling.h"
#include "core/files/image_io.h"
#include "core/sampling/pixel_filter.h"
#include "core/progress.h"
#include "core/optics/srgb.h" /* srgb_to_linear, linear_to_srgb */
#include "metrics/ssim.h"
#include "scene/camera_path.h"

enum { T_NONE, T_FXAA, T_TAA, T_EDGE, T_CHECKER };
enum { IN_PLAIN, IN_HALTON, IN_EDGE, IN_CORNER, INPUTS };
enum { STRIP = 4, HALTON_PERIOD = 8 };

const char *const aa_temporal_technique_names[AA_T_ROWS] = {"no AA",           "FXAA 3.11",
                                                            "TAA (accumulating)", "edge TAA (talk)",
                                                            "checkerboard (talk)", "checkerboard 2x (talk, 2x2 box)"};
static const char *const short_names[AA_T_ROWS] = {"none", "fxaa", "taa", "edge_taa", "checkerboard", "checkerboard_2x"};
const char *const aa_temporal_path_names[AA_T_PATHS] = {"static", "pan"};

aa_temporal_request aa_temporal_default_request(study_quality quality)
{
    const anti_aliasing_quality *q = anti_aliasing_quality_of(quality);
    aa_temporal_request rq = {q->temporal_width, q->temporal_height, q->temporal_frames, {"builtin:aa-thin"}, 1, 1919u};
    return rq;
}


float aa_display(float radiance)
{
    return (float)linear_to_srgb(radiance / (1.0 + radiance));
}

/* Path p of the scene's camera: static, or a pan: 4 cm a frame to the right
 * and a yaw of 0.25 degrees a frame to the left. */
static camera_path make_path(const camera *cam, int p)
{
    camera_path path = camera_path_static(cam);
    if (p == 1)
        path.step = v3(0.04f, 0.0f, 0.0f), path.yaw_step = (float)(0.25 * 3.14159265358979323846 / 180.0);
    return path;
}

/* Running sums of one technique's scores over the scored frames. */
typedef struct {
    double rmse, dssim, rmse16, dssim16, flicker_sq, ghost_sq;
    long flicker_n, ghost_n;
    int frames;
} score_sums;

enum { TRUTH_STRIP = AA_T_ROWS }; /* strip[TRUTH_STRIP]: the truth's */

struct aa_work {
    int width, height, rows; /* rows: outputs kept, AA_T_ROWS in the study, AA_T_TECHNIQUES in aa_work */
    size_t px;
    frame_buffers in[INPUTS], in2x; /* in2x: the corners at 2W x 2H (the study) */
    float *truth, *truth16, *prev_truth, *out[AA_T_ROWS], *prev_out[AA_T_ROWS], *full2x;
    float *sharp, *plain, *prev_sharp, *samples, *xy, *luma_a, *luma_b, *strip[AA_T_ROWS + 1];
    float *ssim_map, *dssim_sum[AA_T_ROWS]; /* a frame's SSIM map; each row's per-pixel DSSIM summed */
    /* per pixel over the scored frames: squared error, squared flicker and
     * squared error where disoccluded (summed over RGB), and the count of
     * disoccluded values */
    float *err_sq[AA_T_ROWS], *flicker_sq[AA_T_ROWS], *ghost_sq[AA_T_ROWS], *ghost_n;
    checkerboard_grid grid, prev_grid, grid2x, prev_grid2x;
    double seconds[AA_T_TECHNIQUES]; /* time spent in each technique */
};
typedef aa_work work;

static float *floats(size_t n, int *ok)
{
    float *p = malloc(n * sizeof(float));
    *ok = *ok && p;
    return p;
}

static int work_alloc(work *w, int width, int height, int with_truth)
{
    memset(w, 0, sizeof *w);
    w->width = width, w->height = height, w->px = (size_t)width * height;
    w->rows = with_truth ? AA_T_ROWS : AA_T_TECHNIQUES;
    int ok = 1;
    for (int i = 0; i < INPUTS; ++i)
        ok = ok && frame_buffers_alloc(&w->in[i], width, height) == 0;
    float **three[] = {&w->truth, &w->truth16, &w->prev_truth, &w->sharp, &w->plain, &w->prev_sharp};
    for (size_t i = 0; i < sizeof three / sizeof three[0]; ++i)
        *three[i] = floats(3 * w->px, &ok);
    for (int t = 0; t < w->rows; ++t)
        w->out[t] = floats(3 * w->px, &ok), w->prev_out[t] = floats(3 * w->px, &ok);
    for (int t = 0; t <= AA_T_ROWS; ++t)
        w->strip[t] = floats(3 * STRIP * w->px, &ok);
    if (with_truth) {
        w->samples = floats(3 * 64 * w->px, &ok), w->xy = floats(2 * 64 * w->px, &ok);
        ok = ok && frame_buffers_alloc(&w->in2x, 2 * width, 2 * height) == 0;
        w->full2x = floats(12 * w->px, &ok), w->ghost_n = floats(w->px, &ok);
        for (int t = 0; t < AA_T_ROWS; ++t)
            w->err_sq[t] = floats(w->px, &ok), w->flicker_sq[t] = floats(w->px, &ok), w->ghost_sq[t] = floats(w->px, &ok);
    }
    w->luma_a = floats(w->px, &ok), w->luma_b = floats(w->px, &ok), w->ssim_map = floats(w->px, &ok);
    for (int t = 0; t < w->rows; ++t)
        w->dssim_sum[t] = floats(w->px, &ok);
    return ok ? 0 : -1;
}

static void work_free(work *w)
{
    for (int i = 0; i < INPUTS; ++i)
        frame_buffers_free(&w->in[i]);
    frame_buffers_free(&w->in2x);
    float *all[] = {w->truth, w->truth16, w->prev_truth, w->sharp, w->plain,    w->prev_sharp, w->samples,
                    w->xy,    w->luma_a,  w->luma_b,     w->ssim_map, w->full2x, w->ghost_n};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; ++i)
        free(all[i]);
    for (int t = 0; t < AA_T_ROWS; ++t) {
        free(w->out[t]), free(w->prev_out[t]), free(w->dssim_sum[t]);
        free(w->err_sq[t]), free(w->flicker_sq[t]), free(w->ghost_sq[t]);
    }
    for (int t = 0; t <= AA_T_ROWS; ++t)
        free(w->strip[t]);
    checkerboard_grid_free(&w->grid), checkerboard_grid_free(&w->prev_grid);
    checkerboard_grid_free(&w->grid2x), checkerboard_grid_free(&w->prev_grid2x);
}

static void to_display(float *rgb, size_t values)
{
    for (size_t k = 0; k < values; ++k)
        rgb[k] = aa_display(rgb[k]);
}

static void render_truth(const embree_scene *es, const camera *cam, int s, unsigned seed, int threads, work *w,
                         float *out)
{
    const frame_lighting light = frame_lighting_default();
    shaded_frame_render_supersampled(es, cam, &light, s, seed, threads, w->samples, w->xy);
    pixel_filter_resolve(PIXEL_FILTER_BLACKMAN_HARRIS, w->samples, w->xy, w->width, w->height, s, threads, out);
    to_display(out, 3 * w->px);
}

/* The four inputs of frame k: unjittered, Halton, edge and corner samples. */
static void render_inputs(const embree_scene *es, const camera *cam, const camera *prev, int k, int threads, work *w)
{
    const frame_lighting light = frame_lighting_default();
    float jitter[INPUTS][2] = {{0.0f, 0.0f}, {0.0f, 0.0f}, {0.0f, 0.0f}, {-0.5f, -0.5f}};
    taa_halton_jitter(k, HALTON_PERIOD, jitter[IN_HALTON]);
    taa_edge_jitter(k, jitter[IN_EDGE]);
    for (int i = 0; i < INPUTS; ++i) {
        frames_render(es, cam, prev, &light, jitter[i], threads, &w->in[i]);
        to_display(w->in[i].rgb, 3 * w->px);
    }
}

static int swap_history(work *w)
{
    float *t = w->sharp;
    w->sharp = w->prev_sharp, w->prev_sharp = t;
    checkerboard_grid g = w->grid;
    w->grid = w->prev_grid, w->prev_grid = g;
    return 0;
}

/* Technique t on frame k's inputs into w->out[t]; 0 or -1 (out of memory). */
static int run_technique(int t, int k, int threads, work *w)
{
    int width = w->width, height = w->height;
    if (t == T_NONE)
        memcpy(w->out[T_NONE], w->in[IN_PLAIN].rgb, 3 * w->px * sizeof(float));
    if (t == T_FXAA) {
        fxaa_settings fx = fxaa_default_settings();
        return fxaa_apply(&fx, w->in[IN_PLAIN].rgb, width, height, threads, w->out[T_FXAA]);
    }
    if (t == T_TAA) {
        taa_accumulate_settings ts = taa_accumulate_default_settings();
        taa_accumulate(&ts, w->in[IN_HALTON].rgb, w->in[IN_HALTON].motion, k ? w->prev_out[T_TAA] : NULL, width,
                       height, threads, w->out[T_TAA]);
    }
    if (t == T_EDGE) {
        edge_taa_settings es = edge_taa_default_settings();
        if (edge_taa_resample(&es, w->in[IN_EDGE].rgb, k, width, height, threads, w->sharp, w->plain) != 0)
            return -1;
        edge_taa_resolve(w->sharp, w->plain, k ? w->prev_sharp : NULL, w->in[IN_EDGE].motion, width, height,
                         threads, w->out[T_EDGE]);
    }
    if (t == T_CHECKER) {
        checkerboard_settings cs = checkerboard_default_settings();
        checkerboard_grid_free(&w->grid);
        if (checkerboard_grid_build(&cs, w->in[IN_CORNER].rgb, width, height, k, threads, &w->grid) != 0)
            return -1;
        return checkerboard_resolve(&cs, &w->grid, k ? &w->prev_grid : NULL, w->in[IN_CORNER].motion, threads,
                                    w->out[T_CHECKER]);
    }
    return 0;
}

/* Every technique on frame k, each timed; then the histories move on. */
static int run_techniques(int k, int threads, work *w)
{
    for (int t = 0; t < AA_T_TECHNIQUES; ++t) {
        double start = seconds_now();
        if (run_technique(t, k, threads, w) != 0)
            return -1;
        w->seconds[t] += seconds_now() - start;
    }
    return swap_history(w);
}

/* The mean of each 2 x 2 block of a 2W x 2H RGB image into W x H: the
 * checkerboard at twice the resolution on the display's footprint. */
static void box_down(const float *full, int width, int height, float *out)
{
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i)
            for (int c = 0; c < 3; ++c) {
                const float *a = full + 3 * ((size_t)(2 * j) * 2 * width + 2 * i) + c, *b = a + 3 * 2 * (size_t)width;
                out[3 * ((size_t)j * width + i) + c] = 0.25f * (a[0] + a[3] + b[0] + b[3]);
            }
}

/* The checkerboard at 2W x 2H on frame k (its own corner render, history
 * and rejection at that resolution) into w->out[AA_T_CHECKER_2X] at W x H. */
static int run_checker_2x(const embree_scene *es, const camera *now, const camera *prev, int k, int threads, work *w)
{
    const frame_lighting light = frame_lighting_default();
    const float corner[2] = {-0.5f, -0.5f};
    camera c = *now, p = prev ? *prev : *now;
    c.width *= 2, c.height *= 2, p.width *= 2, p.height *= 2;
    frames_render(es, &c, prev ? &p : NULL, &light, corner, threads, &w->in2x);
    to_display(w->in2x.rgb, 12 * w->px);
    checkerboard_settings cs = checkerboard_default_settings();
    checkerboard_grid_free(&w->grid2x);
    if (checkerboard_grid_build(&cs, w->in2x.rgb, c.width, c.height, k, threads, &w->grid2x) != 0 ||
        checkerboard_resolve(&cs, &w->grid2x, k ? &w->prev_grid2x : NULL, w->in2x.motion, threads, w->full2x) != 0)
        return -1;
    box_down(w->full2x, w->width, w->height, w->out[AA_T_CHECKER_2X]);
    checkerboard_grid g = w->grid2x;
    w->grid2x = w->prev_grid2x, w->prev_grid2x = g;
    return 0;
}

static double rmse(const float *a, const float *b, size_t values)
{
    double s = 0.0;
    for (size_t k = 0; k < values; ++k)
        s += ((double)a[k] - b[k]) * ((double)a[k] - b[k]);
    return sqrt(s / values);
}

static void display_luma(const float *rgb, size_t pixels, float *luma)
{
    for (size_t k = 0; k < pixels; ++k)
        luma[k] = 0.2126f * rgb[3 * k] + 0.7152f * rgb[3 * k + 1] + 0.0722f * rgb[3 * k + 2];
}

/* DSSIM of got against truth (display luma); with per_pixel, the frame's
 * per-pixel DSSIM (1 - SSIM) / 2 is added to it (NaN off the valid centres). */
static int dssim(work *w, const float *got, const float *truth, double *out, float *per_pixel, gt_error *e)
{
    display_luma(got, w->px, w->luma_a);
    display_luma(truth, w->px, w->luma_b);
    ssim_result s;
    if (ssim_compute(w->luma_b, w->luma_a, NULL, w->width, w->height, "temporal anti-aliasing",
                     per_pixel ? w->ssim_map : NULL, &s, e) != 0)
        return -1;
    for (size_t p = 0; per_pixel && p < w->px; ++p)
        per_pixel[p] += 0.5f * (1.0f - w->ssim_map[p]);
    *out = s.dssim;
    return 0;
}

/* Each technique's DSSIM minus every other's, per pixel averaged over the
 * frames, as a mean over the valid SSIM centres with its 8x8-block standard
 * error (metrics/cluster_mean.h): the rankings' paired interval. */
static void paired_dssim(const work *w, aa_temporal_row *rows)
{
    float *diff = malloc(w->px * sizeof(float)), *valid = malloc(w->px * sizeof(float));
    for (int a = 0; diff && valid && a < w->rows; ++a)
        for (int b = 0; b < w->rows; ++b) {
            for (size_t p = 0; p < w->px; ++p) {
                diff[p] = w->dssim_sum[a][p] - w->dssim_sum[b][p];
                valid[p] = isnan(diff[p]) ? 0.0f : 1.0f;
                diff[p] = valid[p] > 0.0f ? diff[p] : 0.0f;
            }
            cluster_mean m = {NAN, NAN, 0, 0};
            if (cluster_mean_compute(diff, valid, w->width, w->height, CLUSTER_MEAN_SIDE, &m) == 0 && rows[a].frames)
                m.mean /= rows[a].frames, m.se /= rows[a].frames;
            rows[a].dssim_minus[b] = m;
        }
    free(diff), free(valid);
}

/* Flicker and ghosting sums of row t at frame k >= 1, and its per-pixel
 * sums (squared error, flicker, ghosting; the disoccluded count with t = 0). */
static void temporal_sums(const work *w, int t, score_sums *s)
{
    const unsigned char *disoccluded = w->in[IN_PLAIN].disoccluded;
    for (size_t p = 0; p < w->px; ++p)
        for (int c = 0; c < 3; ++c) {
            size_t v = 3 * p + c;
            double change = ((double)w->out[t][v] - w->prev_out[t][v]) - ((double)w->truth[v] - w->prev_truth[v]);
            double error = (double)w->out[t][v] - w->truth[v];
            s->flicker_sq += change * change, ++s->flicker_n;
            w->err_sq[t][p] += (float)(error * error), w->flicker_sq[t][p] += (float)(change * change);
            if (disoccluded[p]) {
                s->ghost_sq += error * error, ++s->ghost_n;
                w->ghost_sq[t][p] += (float)(error * error), w->ghost_n[p] += t == 0 ? 1.0f : 0.0f;
            }
        }
}

/* The RMS over the values of row a minus row b's, from per-pixel sums of
 * squares sa, sb over n[p] values each (n NULL: `count` each), with the
 * delta method's standard error: R = sqrt(S / N) moves by dS / (2 N R),
 * so R_a - R_b's error is that of the mean over the M pixels holding values
 * of x_p = (M / N) (sa_p / (2 R_a) - sb_p / (2 R_b)), clustered over
 * 8 x 8 blocks. Nothing (mean 0, no blocks) when no pixel holds a value. */
static cluster_mean rms_gap(const work *w, const float *sa, const float *sb, const float *n, double count, float *x)
{
    double a = 0.0, b = 0.0, values = 0.0;
    size_t m = 0;
    for (size_t p = 0; p < w->px; ++p) {
        double np = n ? n[p] : count;
        a += sa[p], b += sb[p], values += np, m += np > 0.0;
    }
    cluster_mean out = {0.0, 0.0, 0, 0};
    if (m == 0 || values <= 0.0)
        return out;
    double ra = sqrt(a / values), rb = sqrt(b / values);
    double ka = ra > 0.0 ? 0.5 / ra : 0.0, kb = rb > 0.0 ? 0.5 / rb : 0.0, scale = (double)m / values;
    for (size_t p = 0; p < w->px; ++p)
        x[p] = (float)(scale * (ka * sa[p] - kb * sb[p]));
    if (cluster_mean_compute(x, n, w->width, w->height, CLUSTER_MEAN_SIDE, &out) == 0)
        out.mean = ra - rb;
    return out;
}

/* Every row's RMSE, flicker and ghosting minus every other's on the path,
 * over `frames` scored frames. */
static void paired_rms(const work *w, int frames, aa_temporal_row *rows)
{
    float *x = malloc(w->px * sizeof(float));
    double count = 3.0 * frames;
    for (int a = 0; x && a < w->rows; ++a)
        for (int b = 0; b < w->rows; ++b) {
            rows[a].rmse_minus[b] = rms_gap(w, w->err_sq[a], w->err_sq[b], NULL, count, x);
            rows[a].flicker_minus[b] = rms_gap(w, w->flicker_sq[a], w->flicker_sq[b], NULL, count, x);
            rows[a].ghost_minus[b] = rms_gap(w, w->ghost_sq[a], w->ghost_sq[b], w->ghost_n, 0.0, x);
        }
    free(x);
}

static int score_frame(work *w, int k, score_sums sums[AA_T_ROWS], aa_temporal_row *rows, gt_error *e)
{
    for (int t = 0; t < w->rows; ++t) {
        double d64, d16, r64 = rmse(w->out[t], w->truth, 3 * w->px);
        rows[t].rmse_frame[k] = r64;
        if (k >= 2)
            rows[t].settle = fmax(rows[t].settle, rmse(w->out[t], w->prev_out[t], 3 * w->px));
        if (k < AA_T_WARMUP)
            continue;
        if (dssim(w, w->out[t], w->truth, &d64, w->dssim_sum[t], e) != 0 ||
            dssim(w, w->out[t], w->truth16, &d16, NULL, e) != 0)
            return -1;
        score_sums *s = &sums[t];
        s->rmse += r64, s->dssim += d64, s->rmse16 += rmse(w->out[t], w->truth16, 3 * w->px), s->dssim16 += d16;
        ++s->frames;
        temporal_sums(w, t, s);
    }
    return 0;
}

/* A display image into slot `slot` of a strip of STRIP frames side by side. */
static void strip_put(const work *w, const float *rgb, int slot, float *strip)
{
    for (int j = 0; j < w->height; ++j)
        memcpy(strip + 3 * ((size_t)j * STRIP * w->width + (size_t)slot * w->width), rgb + 3 * (size_t)j * w->width,
               3 * sizeof(float) * w->width);
}

/* A display image (decoded to linear: the writer encodes sRGB), or with
 * error = truth, a heatmap of the mean over RGB of |rgb - truth|, 0 to
 * AA_T_ERROR_MAP_MAX (the report draws its colour bar). */
static int write_png(const char *dir, const char *name, const float *rgb, const float *truth, int width, int height,
                     gt_error *e)
{
    size_t px = (size_t)width * height;
    float *planes[3] = {malloc(px * sizeof(float)), malloc(px * sizeof(float)), malloc(px * sizeof(float))};
    int rc = planes[0] && planes[1] && planes[2] ? 0 : gt_error_set(e, dir, "out of memory");
    for (size_t k = 0; k < px && rc == 0; ++k)
        for (int c = 0; c < 3; ++c)
            planes[c][k] = truth ? (fabsf(rgb[3 * k] - truth[3 * k]) + fabsf(rgb[3 * k + 1] - truth[3 * k + 1]) +
                                    fabsf(rgb[3 * k + 2] - truth[3 * k + 2])) / 3.0f
                                 : (float)srgb_to_linear(rgb[3 * k + c]);
    char path[4096 + 128];
    if (rc == 0 && snprintf(path, sizeof path, "%s/%s.png", dir, name) >= (int)sizeof path)
        rc = gt_error_set(e, dir, "path too long");
    if (rc == 0 && truth)
        rc = image_write_heatmap(path, planes[0], NULL, width, height, AA_T_ERROR_MAP_MAX, "inferno", e);
    else if (rc == 0)
        rc = image_write_preview(path, (const float *const *)planes, 3, width, height, 1.0f, e);
    free(planes[0]), free(planes[1]), free(planes[2]);
    return rc;
}

/* The last STRIP frames of each technique and of the truth, and the last
 * frame's error maps. */
static int write_figures(const char *dir, int p, const work *w, gt_error *e)
{
    char name[128];
    snprintf(name, sizeof name, "temporal_%s_truth_strip", aa_temporal_path_names[p]);
    int rc = write_png(dir, name, w->strip[TRUTH_STRIP], NULL, STRIP * w->width, w->height, e);
    for (int t = 0; t < w->rows && rc == 0; ++t) {
        snprintf(name, sizeof name, "temporal_%s_%s_strip", aa_temporal_path_names[p], short_names[t]);
        rc = write_png(dir, name, w->strip[t], NULL, STRIP * w->width, w->height, e);
        snprintf(name, sizeof name, "temporal_%s_%s_error", aa_temporal_path_names[p], short_names[t]);
        if (rc == 0)
            rc = write_png(dir, name, w->prev_out[t], w->prev_truth, w->width, w->height, e);
    }
    return rc;
}

static void keep_frame(work *w, int k, int frames)
{
    int slot = frames > 0 ? k - (frames - STRIP) : -1;
    for (int t = 0; t < w->rows; ++t) {
        if (slot >= 0)
            strip_put(w, w->out[t], slot, w->strip[t]);
        memcpy(w->prev_out[t], w->out[t], 3 * w->px * sizeof(float));
    }
    if (slot >= 0)
        strip_put(w, w->truth, slot, w->strip[TRUTH_STRIP]);
    if (frames > 0) /* a study: the truth was rendered */
        memcpy(w->prev_truth, w->truth, 3 * w->px * sizeof(float));
}

static void finish_rows(const score_sums sums[AA_T_ROWS], aa_temporal_row *rows)
{
    for (int t = 0; t < AA_T_ROWS; ++t) {
        const score_sums *s = &sums[t];
        int n = s->frames > 0 ? s->frames : 1;
        rows[t].rmse = s->rmse / n, rows[t].dssim = s->dssim / n, rows[t].rmse16 = s->rmse16 / n;
        rows[t].dssim16 = s->dssim16 / n, rows[t].frames = s->frames;
        rows[t].flicker = s->flicker_n ? sqrt(s->flicker_sq / s->flicker_n) : 0.0;
        rows[t].ghost_rmse = s->ghost_n ? sqrt(s->ghost_sq / s->ghost_n) : 0.0;
    }
}

/* The truth's own numbers of frame k (k >= 1): 16-sample error, change, disocclusion. */
static void truth_sums(const work *w, int k, double sums[3])
{
    if (k < AA_T_WARMUP)
        return;
    sums[0] += rmse(w->truth16, w->truth, 3 * w->px);
    sums[1] += pow(rmse(w->truth, w->prev_truth, 3 * w->px), 2.0);
    long d = 0;
    for (size_t p = 0; p < w->px; ++p)
        d += w->in[IN_PLAIN].disoccluded[p];
    sums[2] += (double)d / w->px;
}

static int run_path(const study_context *ctx, const aa_temporal_request *rq, const embree_scene *es,
                    const camera *cam, int p, work *w, aa_temporal_row *rows, aa_temporal_truth *truth, gt_error *e)
{
    camera_path path = make_path(cam, p);
    score_sums sums[AA_T_ROWS];
    double tsum[3] = {0.0, 0.0, 0.0};
    memset(sums, 0, sizeof sums);
    memset(w->ghost_n, 0, w->px * sizeof(float));
    for (int t = 0; t < AA_T_ROWS; ++t) {
        float *zero[] = {w->dssim_sum[t], w->err_sq[t], w->flicker_sq[t], w->ghost_sq[t]};
        for (int z = 0; z < 4; ++z)
            memset(zero[z], 0, w->px * sizeof(float));
    }
    for (int k = 0; k < rq->frames; ++k) {
        camera now = camera_path_at(&path, k), before = camera_path_at(&path, k > 0 ? k - 1 : 0);
        render_truth(es, &now, 8, rq->seed, ctx->threads, w, w->truth); /* same strata every frame: a */
        render_truth(es, &now, 4, rq->seed + 1u, ctx->threads, w, w->truth16); /* static truth has no change */
        render_inputs(es, &now, k > 0 ? &before : NULL, k, ctx->threads, w);
        if (run_techniques(k, ctx->threads, w) != 0 ||
            run_checker_2x(es, &now, k > 0 ? &before : NULL, k, ctx->threads, w) != 0)
            return gt_error_set(e, "temporal anti-aliasing", "out of memory");
        if (score_frame(w, k, sums, rows, e) != 0)
            return -1;
        truth_sums(w, k, tsum);
        keep_frame(w, k, rq->frames);
    }
    finish_rows(sums, rows);
    paired_dssim(w, rows);
    paired_rms(w, rows[0].frames, rows);
    int n = rq->frames - AA_T_WARMUP;
    truth->truth16_rmse = tsum[0] / n, truth->truth_change = sqrt(tsum[1] / n), truth->disoccluded = tsum[2] / n;
    return 0;
}

static int study_scene(const study_context *ctx, const aa_temporal_request *rq, const char *spec, const char *dir,
                       work *w, aa_temporal_result *out, gt_error *e)
{
    scene s;
    camera cam;
    embree_scene es;
    if (study_load_view(spec, rq->width, rq->height, &s, &cam, e) != 0)
        return -1;
    int rc = embree_scene_build(&s, &es, e), built = rc == 0;
    for (int p = 0; p < AA_T_PATHS && rc == 0; ++p) {
        aa_temporal_row *rows = &out->rows[out->row_count];
        aa_temporal_truth *truth = &out->truth[out->truth_count++];
        *truth = (aa_temporal_truth){spec, aa_temporal_path_names[p], 0.0, 0.0, 0.0};
        for (int t = 0; t < AA_T_ROWS; ++t) {
            memset(&rows[t], 0, sizeof rows[t]);
            rows[t].scene = spec, rows[t].path = aa_temporal_path_names[p], rows[t].technique = aa_temporal_technique_names[t];
        }
        out->row_count += AA_T_ROWS;
        rc = run_path(ctx, rq, &es, &cam, p, w, rows, truth, e);
        if (rc == 0 && spec == rq->scenes[0])
            rc = write_figures(dir, p, w, e);
    }
    if (built)
        embree_scene_release(&es);
    scene_free(&s);
    return rc;
}

int aa_temporal_study(const study_context *ctx, const aa_temporal_request *rq, aa_temporal_result *out, gt_error *e)
{
    char dir[4096];
    memset(out, 0, sizeof *out);
    out->request = *rq;
    if (rq->frames <= AA_T_WARMUP || rq->frames > AA_T_MAX_FRAMES || rq->scene_count > AA_T_MAX_SCENES)
        return gt_error_set(e, "temporal anti-aliasing", "%d frames: need %d .. %d", rq->frames, AA_T_WARMUP + 1,
                            AA_T_MAX_FRAMES);
    if (study_make_dir(ctx, AA_DIR, dir, sizeof dir, e) != 0)
        return -1;
    work w;
    int rc = work_alloc(&w, rq->width, rq->height, 1) == 0 ? 0 : gt_error_set(e, dir, "out of memory");
    for (int k = 0; k < rq->scene_count && rc == 0; ++k)
        rc = study_scene(ctx, rq, rq->scenes[k], dir, &w, out, e);
    work_free(&w);
    return rc;
}

aa_work *aa_work_new(int width, int height)
{
    work *w = malloc(sizeof *w);
    if (w && work_alloc(w, width, height, 0) != 0)
        work_free(w), free(w), w = NULL;
    return w;
}

void aa_work_delete(aa_work *w)
{
    if (w)
        work_free(w), free(w);
}

int aa_work_frame(aa_work *w, const embree_scene *es, const camera *now, const camera *prev, int k, int threads)
{
    render_inputs(es, now, prev, k, threads, w);
    int rc = run_techniques(k, threads, w);
    keep_frame(w, k, 0);
    return rc;
}

int aa_work_run(aa_work *w, const float *input, const float *motion, int k, int threads)
{
    for (int i = 0; i < INPUTS; ++i) {
        memcpy(w->in[i].rgb, input, 3 * w->px * sizeof(float));
        memcpy(w->in[i].motion, motion, 2 * w->px * sizeof(float));
    }
    int rc = run_techniques(k, threads, w);
    keep_frame(w, k, 0);
    return rc;
}

const float *aa_work_output(const aa_work *w, int technique) { return w->out[technique]; }

double aa_work_seconds(const aa_work *w, int technique) { return w->seconds[technique]; }
