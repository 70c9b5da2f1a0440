/* Issue 25, item 7: the talk's spatio-temporal pattern (seeds/001,
 * "Achieving the Performance Target": 1 direction per pixel, 16 spatial
 * rotations in 4x4 tiles x 6 temporal ones = 96 effective directions;
 * "Noise Distribution": rows ordered by full rotation "worked better than
 * Morton order"). On each scene, the talk's configuration (GTAO medium:
 * one slice, 4 samples per side, the 4x4 bilateral filter, the temporal
 * accumulation of a static camera) after 1, 6 and 24 frames, in row and in
 * Morton order, against its brute force: the same configuration with its 96
 * directions evaluated in one frame (regular slices, no filter). The
 * pattern's exact equality with the brute force, before any filter, is
 * tests/realtime/test_gtao_pattern.c; here the filter's bilateral weights
 * and the step offsets enter. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "metrics/image_error.h"
#include "metrics/noise_corrected.h"
#include "realtime/gtao.h"
#include "realtime/gtao_pattern.h"
#include "studies/gtao_shortcuts.h"

const int gtao_pattern_frames[GTAO_PATTERN_RUNS] = {1, 6, 24};

enum { CYCLE = 24 };

/* The talk's configuration at the stage's radius. */
static gtao_params talk_params(const gtao_shortcut_scene *s, int pattern, int frames, int denoise)
{
    gtao_params p;
    gtao_preset("medium", &p);
    p.radius = s->radius;
    p.falloff = 0.0f;
    p.max_radius_px = s->max_radius_px;
    p.pattern = pattern;
    p.frames = frames;
    p.denoise = denoise;
    return p;
}

static gtao_params brute_params(const gtao_shortcut_scene *s)
{
    gtao_params p = talk_params(s, GTAO_PATTERN_OFF, 1, 0);
    p.slices = GTAO_PATTERN_DIRECTIONS;
    return p;
}

static int rmse_of(const gtao_shortcut_scene *s, const float *a, const float *b, double *rmse, gt_error *e)
{
    image_error_stats st;
    if (image_error_compute(a, b, s->g->mask, s->g->width, s->g->height, s->name, &st, e) != 0)
        return -1;
    *rmse = st.rmse;
    return 0;
}

/* out_i = (a_i - t_i)^2 - (b_i - t_i)^2; b NULL: (a_i - t_i)^2. */
static void squared_error_difference(const float *a, const float *b, const float *t, size_t n, float *out)
{
    for (size_t i = 0; i < n; ++i) {
        float ea = a[i] - t[i], eb = b ? b[i] - t[i] : 0.0f;
        out[i] = ea * ea - eb * eb;
    }
}

typedef struct {
    float *brute, *rows, *morton, *scratch;
} pattern_buffers;

static int render(const gtao_shortcut_scene *s, gtao_params p, float *ao, gt_error *e)
{
    return gtao_render(s->g, &p, ao, NULL) != 0 ? gt_error_set(e, s->name, "out of memory") : 0;
}

/* Run k of both orders, scored and their paired difference pooled. */
static int run_orders(const gtao_shortcut_scene *s, int k, pattern_buffers *b, gtao_pattern_scene *x,
                      gtao_pattern_result *r, gt_error *e)
{
    size_t n = (size_t)s->g->width * s->g->height;
    int frames = gtao_pattern_frames[k];
    if (render(s, talk_params(s, GTAO_PATTERN_ROWS, frames, 1), b->rows, e) != 0 ||
        render(s, talk_params(s, GTAO_PATTERN_MORTON, frames, 1), b->morton, e) != 0 ||
        rmse_of(s, b->rows, b->brute, &x->rmse_rows[k], e) != 0 ||
        rmse_of(s, b->morton, b->brute, &x->rmse_morton[k], e) != 0)
        return -1;
    squared_error_difference(b->rows, b->morton, b->brute, n, b->scratch);
    block_mean_add(&r->order_difference[k], b->scratch, s->g->mask, s->g->width, s->g->height, BLOCK_MEAN_SIZE);
    if (frames == CYCLE) {
        squared_error_difference(b->rows, NULL, b->brute, n, b->scratch);
        block_mean_add(&r->cycle_se2, b->scratch, s->g->mask, s->g->width, s->g->height, BLOCK_MEAN_SIZE);
    }
    return 0;
}

static int pattern_runs(const gtao_shortcut_scene *s, pattern_buffers *b, gtao_pattern_scene *x,
                        gtao_pattern_result *r, gt_error *e)
{
    double hf_rmse;
    if (render(s, brute_params(s), b->brute, e) != 0 || rmse_of(s, b->brute, s->hf, &hf_rmse, e) != 0)
        return -1;
    x->brute_rmse_hf = noise_corrected_rmse(hf_rmse, s->hf_mean_variance);
    for (int k = 0; k < GTAO_PATTERN_RUNS; ++k)
        if (run_orders(s, k, b, x, r, e) != 0)
            return -1;
    if (render(s, talk_params(s, GTAO_PATTERN_ROWS, CYCLE, 0), b->rows, e) != 0)
        return -1;
    return rmse_of(s, b->rows, b->brute, &x->rmse_raw_cycle, e);
}

int gtao_pattern_scene_study(const gtao_shortcut_scene *s, gtao_pattern_result *r, gt_error *e)
{
    if (r->scene_count == GTAO_SHORTCUT_MAX_SCENES)
        return gt_error_set(e, s->name, "more than %d scenes", GTAO_SHORTCUT_MAX_SCENES);
    gtao_pattern_scene *x = &r->scenes[r->scene_count++];
    snprintf(x->scene, sizeof x->scene, "%s", s->name);
    size_t n = (size_t)s->g->width * s->g->height;
    pattern_buffers b = {malloc(sizeof(float) * n), malloc(sizeof(float) * n), malloc(sizeof(float) * n),
                         malloc(sizeof(float) * n)};
    int rc = b.brute && b.rows && b.morton && b.scratch ? pattern_runs(s, &b, x, r, e)
                                                         : gt_error_set(e, s->name, "out of memory");
    r->hf_noise_rmse += s->hf_mean_variance; /* summed here, averaged in gtao_pattern_finish */
    free(b.brute);
    free(b.rows);
    free(b.morton);
    free(b.scratch);
    return rc;
}

void gtao_pattern_finish(gtao_pattern_result *r)
{
    block_mean_rmse(&r->cycle_se2, &r->cycle_rmse, &r->cycle_rmse_se);
    r->hf_noise_rmse = r->scene_count > 0 ? sqrt(r->hf_noise_rmse / r->scene_count) : 0.0;
}
