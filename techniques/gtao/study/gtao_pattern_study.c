/* Issue 25, item 7: the talk's spatio-temporal pattern (seeds/001,
 * "Achieving the Performance Target": 1 direction per pixel, 16 spatial
 * rotations in 4x4 tiles x 6 temporal ones = 96 effective directions;
 * "Noise Distribution": rows ordered by full rotation "worked better than
 * Morton order"). On each scene, the talk's configuration (GTAO medium:
 * one slice, 4 samples per side, the 4x4 bilateral filter, the temporal
 * accumulation of a static camera) after 1 and 24 frames, in row and in
 * Morton order (the cycle of gtao_shortcuts.c), against its brute force:
 * the same configuration with its 96 directions evaluated in one frame
 * (regular slices, no filter). The pattern's exact equality with the brute
 * force, before any filter, is tests/test_gtao_pattern.c; here the
 * filter's bilateral weights and the step offsets enter. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "gtao/gtao_pattern.h"
#include "gtao/gtao_shortcuts.h"
#include "metrics/image_error.h"
#include "metrics/noise_corrected.h"

const int gtao_pattern_frames[GTAO_PATTERN_RUNS] = {1, GTAO_CYCLE_FRAMES};

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

/* Run k of both orders scored, their paired difference pooled. */
static int run_orders(const gtao_shortcut_scene *s, const gtao_cycle *c, int k, float *scratch,
                      gtao_pattern_scene *x, gtao_pattern_result *r, gt_error *e)
{
    const ss_gbuffer *g = s->g;
    const float *rows = k == 0 ? c->first[0] : c->last[0], *morton = k == 0 ? c->first[1] : c->last[1];
    if (rmse_of(s, rows, c->brute, &x->rmse_rows[k], e) != 0 || rmse_of(s, morton, c->brute, &x->rmse_morton[k], e))
        return -1;
    size_t n = (size_t)g->width * g->height;
    squared_error_difference(rows, morton, c->brute, n, scratch);
    block_mean_add(&r->order_difference[k], scratch, g->mask, g->width, g->height, BLOCK_MEAN_SIZE);
    return 0;
}

int gtao_pattern_scene_study(const gtao_shortcut_scene *s, const gtao_cycle *c, gtao_pattern_result *r,
                             gt_error *e)
{
    if (r->scene_count == GTAO_SHORTCUT_MAX_SCENES)
        return gt_error_set(e, s->name, "more than %d scenes", GTAO_SHORTCUT_MAX_SCENES);
    gtao_pattern_scene *x = &r->scenes[r->scene_count++];
    snprintf(x->scene, sizeof x->scene, "%s", s->name);
    const ss_gbuffer *g = s->g;
    size_t n = (size_t)g->width * g->height;
    float *scratch = malloc(sizeof(float) * n);
    double hf_rmse = 0.0;
    if (!scratch)
        return gt_error_set(e, s->name, "out of memory");
    int rc = s->hf ? rmse_of(s, c->brute, s->hf, &hf_rmse, e) : 0; /* no reference in the talk's setting */
    for (int k = 0; k < GTAO_PATTERN_RUNS && rc == 0; ++k)
        rc = run_orders(s, c, k, scratch, x, r, e);
    if (rc == 0 && (rc = rmse_of(s, c->raw_last, c->brute, &x->rmse_raw_cycle, e)) == 0) {
        x->brute_rmse_hf = noise_corrected_rmse(hf_rmse, s->hf_mean_variance);
        squared_error_difference(c->last[0], NULL, c->brute, n, scratch);
        block_mean_add(&r->cycle_se2, scratch, g->mask, g->width, g->height, BLOCK_MEAN_SIZE);
        r->hf_noise_rmse += s->hf_mean_variance; /* summed here, averaged in gtao_pattern_finish */
    }
    free(scratch);
    return rc;
}

void gtao_pattern_finish(gtao_pattern_result *r)
{
    block_mean_rmse(&r->cycle_se2, &r->cycle_rmse, &r->cycle_rmse_se);
    r->hf_noise_rmse = r->scene_count > 0 ? sqrt(r->hf_noise_rmse / r->scene_count) : 0.0;
}
