/* Issue 25, item 8: the GTAO talk's denoisers (seeds/001, "Spatial
 * Denoiser Details", "Temporal Denoiser Details";
 * gtao_spatial_filter.h) on the 24-frame cycle of gtao_shortcuts.c:
 *  - the spatial filter's depth test: "linear depth + 1st + 2nd order
 *    derivatives yield sharper details yet smoother flat surfaces" than log
 *    depth + 1st derivatives: frame 0 filtered with each test, squared
 *    error against the brute force, paired over 8x8 blocks, at edges and
 *    on flat pixels;
 *  - the alternating one-pixel offset of the asymmetric 4x4 window: the
 *    24-frame accumulation's shift and bias against the brute force, with
 *    the window alternating (the talk's) and fixed;
 *  - clampWindowSize: 24 frames with the history clamped to the widened
 *    neighbourhood, each window size, against no clamp. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "gtao/gtao_shortcuts.h"
#include "metrics/image_error.h"

/* A crease or silhouette at (x, y): a neighbour missing or a second depth
 * difference above 2% of the depth along x or y. */
static int crease(const ss_gbuffer *g, int x, int y)
{
    if (!ss_covered(g, x, y))
        return 1;
    for (int axis = 0; axis < 2; ++axis) {
        int ox = axis == 0, oy = axis == 1;
        if (!ss_covered(g, x - ox, y - oy) || !ss_covered(g, x + ox, y + oy))
            return 1;
        float zc = g->depth[y * g->width + x];
        float d2 = g->depth[(y + oy) * g->width + x + ox] - 2.0f * zc + g->depth[(y - oy) * g->width + x - ox];
        if (fabsf(d2) > 0.02f * zc)
            return 1;
    }
    return 0;
}

/* edge[i] = 1 for covered pixels within 2 pixels of a crease; flat[i] the other covered ones. */
static double edge_masks(const ss_gbuffer *g, float *edge, float *flat)
{
    long covered = 0, edges = 0;
    for (int y = 0; y < g->height; ++y)
        for (int x = 0; x < g->width; ++x) {
            long i = (long)y * g->width + x;
            int near = 0;
            for (int oy = -2; oy <= 2 && !near; ++oy)
                for (int ox = -2; ox <= 2 && !near; ++ox)
                    near = crease(g, x + ox, y + oy);
            int in = g->mask[i] != 0.0f;
            edge[i] = (float)(in && near);
            flat[i] = (float)(in && !near);
            covered += in;
            edges += in && near;
        }
    return covered > 0 ? (double)edges / (double)covered : 0.0;
}

typedef struct {
    const gtao_shortcut_scene *s;
    float *edge, *flat, *filtered[GTAO_DEPTH_TESTS], *scratch;
} denoise_work;

static double rmse_in(const denoise_work *w, const float *a, const float *b, const float *mask)
{
    image_error_stats st;
    gt_error e;
    if (image_error_compute(a, b, mask, w->s->g->width, w->s->g->height, w->s->name, &st, &e) != 0)
        return 0.0;
    return st.rmse;
}

/* scratch = (a - t)^2 - (b - t)^2 (b NULL: a - t) added to m over mask. */
static void paired(denoise_work *w, const float *a, const float *b, const float *t, const float *mask,
                   block_mean *m)
{
    const ss_gbuffer *g = w->s->g;
    for (long i = 0; i < (long)g->width * g->height; ++i) {
        float ea = a[i] - t[i], eb = b ? b[i] - t[i] : 0.0f;
        w->scratch[i] = b ? ea * ea - eb * eb : ea;
    }
    block_mean_add(m, w->scratch, mask, g->width, g->height, BLOCK_MEAN_SIZE);
}

static void depth_tests(denoise_work *w, const gtao_cycle *c, gtao_denoisers_scene *x, gtao_denoisers_result *r)
{
    for (int t = 0; t < GTAO_DEPTH_TESTS; ++t) {
        gtao_spatial_options o = gtao_spatial_default;
        o.depth_test = (gtao_depth_test)t;
        gtao_spatial_filter(w->s->g, 0, &o, c->raw_first, w->filtered[t]);
        x->rmse_edge[t] = rmse_in(w, w->filtered[t], c->brute, w->edge);
        x->rmse_flat[t] = rmse_in(w, w->filtered[t], c->brute, w->flat);
    }
    float *d1 = w->filtered[GTAO_DEPTH_LINEAR_D1], *d2 = w->filtered[GTAO_DEPTH_LINEAR_D2];
    float *log1 = w->filtered[GTAO_DEPTH_LOG_D1];
    paired(w, d2, log1, c->brute, w->edge, &r->d2_minus_log_edge);
    paired(w, d2, log1, c->brute, w->flat, &r->d2_minus_log_flat);
    paired(w, d2, d1, c->brute, w->edge, &r->d2_minus_d1_edge);
    paired(w, d2, d1, c->brute, w->flat, &r->d2_minus_d1_flat);
}

static void temporal(denoise_work *w, const gtao_cycle *c, gtao_denoisers_scene *x, gtao_denoisers_result *r)
{
    const ss_gbuffer *g = w->s->g;
    double se[2];
    shift_fit one_with = {0}, one_without = {0};
    shift_fit_add(&one_with, c->last[0], c->brute, g->mask, g->width, g->height, BLOCK_MEAN_SIZE);
    shift_fit_add(&one_without, c->fixed_window_last, c->brute, g->mask, g->width, g->height, BLOCK_MEAN_SIZE);
    shift_fit_solve(&one_with, x->shift_with, se);
    shift_fit_solve(&one_without, x->shift_without, se);
    shift_fit_add(&r->fit_with, c->last[0], c->brute, g->mask, g->width, g->height, BLOCK_MEAN_SIZE);
    shift_fit_add(&r->fit_without, c->fixed_window_last, c->brute, g->mask, g->width, g->height, BLOCK_MEAN_SIZE);
    x->rmse_with = rmse_in(w, c->last[0], c->brute, g->mask);
    x->rmse_without = rmse_in(w, c->fixed_window_last, c->brute, g->mask);
    paired(w, c->last[0], NULL, c->brute, g->mask, &r->bias_with);
    paired(w, c->fixed_window_last, NULL, c->brute, g->mask, &r->bias_without);
    for (int k = 0; k < GTAO_CLAMP_WINDOWS; ++k) {
        x->rmse_clamped[k] = rmse_in(w, c->clamped_last[k], c->brute, g->mask);
        paired(w, c->clamped_last[k], c->last[0], c->brute, g->mask, &r->clamp_minus_none[k]);
    }
}

int gtao_denoisers_scene_study(const gtao_shortcut_scene *s, const gtao_cycle *c, gtao_denoisers_result *r,
                               gt_error *e)
{
    if (r->scene_count == GTAO_SHORTCUT_MAX_SCENES)
        return gt_error_set(e, s->name, "more than %d scenes", GTAO_SHORTCUT_MAX_SCENES);
    gtao_denoisers_scene *x = &r->scenes[r->scene_count++];
    snprintf(x->scene, sizeof x->scene, "%s", s->name);
    size_t n = (size_t)s->g->width * s->g->height;
    float *storage = malloc(sizeof(float) * n * (3 + GTAO_DEPTH_TESTS));
    if (!storage)
        return gt_error_set(e, s->name, "out of memory");
    denoise_work w = {s, storage, storage + n, {NULL}, storage + 2 * n};
    for (int t = 0; t < GTAO_DEPTH_TESTS; ++t)
        w.filtered[t] = storage + (size_t)(3 + t) * n;
    x->edge_fraction = edge_masks(s->g, w.edge, w.flat);
    depth_tests(&w, c, x, r);
    temporal(&w, c, x, r);
    free(storage);
    return 0;
}

void gtao_denoisers_finish(gtao_denoisers_result *r)
{
    shift_fit_solve(&r->fit_with, r->shift_with, r->shift_with_se);
    shift_fit_solve(&r->fit_without, r->shift_without, r->shift_without_se);
    const double diagonal[2] = {1.0, 1.0};
    r->diagonal_rms_gradient = shift_fit_rms_gradient(&r->fit_with, diagonal);
}
