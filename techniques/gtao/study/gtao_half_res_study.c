/* Issue 25, item 6: the GTAO talk's half resolution and depth MIP chain
 * with MINIMUM filtering (seeds/001, "Achieving the Performance Target";
 * gtao_depth_mip.h), against the full-resolution horizon search
 * as a function of the radius, and its "improves samples per direction
 * (4x)": the MIN-filtered chain with 4 samples per side against 16 point
 * samples per side, both scored against a search with 32. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "gtao/gtao_depth_mip.h"
#include "gtao/gtao_shortcuts.h"
#include "metrics/cluster_mean.h"
#include "metrics/image_error.h"
#include "metrics/noise_corrected.h"

const char *const gtao_half_res_variant_names[GTAO_HALF_RES_VARIANTS] = {
    "full res, MIP", "full res, MIP + MIN filter", "half res", "half res, MIP + MIN filter (the talk's)"};

/* Of the camera distance; 0: no limit. A scene runs every
 * half_res_radius_stride-th (gtao_shortcut_scene; 0 or 1: every one). */
static const double radius_fractions[GTAO_HALF_RES_MAX_RADII] = {0.05, 0.1, 0.2, 0.4, 0.0};

typedef struct {
    const gtao_shortcut_scene *s;
    ss_depth_mip full_mip, half_mip;
    ss_half_gbuffer half;
    float *base, *out, *half_ao, *scratch, *min4;
} work;

static gtao_params search_params(const gtao_shortcut_scene *s, double fraction, int steps, int half)
{
    gtao_params p;
    gtao_preset("reference", &p);
    p.slices = GTAO_HALF_RES_SLICES;
    p.steps = steps;
    p.falloff = 0.0f;
    p.fast_math = 0;
    p.radius = fraction > 0.0 ? (float)fraction * s->camera_distance : s->radius;
    p.max_radius_px = half ? 0.5f * s->max_radius_px : s->max_radius_px; /* the same screen extent */
    return p;
}

static void render_variant(work *w, int variant, double fraction, float *out)
{
    int half = variant == GTAO_HALF_RES_HALF || variant == GTAO_HALF_RES_HALF_MIP_MIN;
    gtao_params p = search_params(w->s, fraction, GTAO_HALF_RES_STEPS, half);
    gtao_depth_fetch fetch = variant == GTAO_HALF_RES_FULL_MIP  ? GTAO_FETCH_MIP
                             : variant == GTAO_HALF_RES_HALF    ? GTAO_FETCH_POINT
                                                                : GTAO_FETCH_MIP_MIN;
    if (!half) {
        gtao_mip_frame(w->s->g, &w->full_mip, fetch, &p, out);
        return;
    }
    gtao_mip_frame(&w->half.g, &w->half_mip, fetch, &p, w->half_ao);
    ss_upsample_nearest(w->s->g, &w->half.g, w->half_ao, out);
}

/* What add_blocks accumulates of a - b per pixel. */
typedef enum { BLOCKS_SIGNED, BLOCKS_SQUARED, BLOCKS_ABSOLUTE, BLOCKS_CODE_CHANGED } blocks_of;

/* scratch = what of a - b, added to m by 8x8 blocks. */
static void add_blocks(work *w, const float *a, const float *b, blocks_of what, block_mean *m)
{
    const ss_gbuffer *g = w->s->g;
    for (long i = 0; i < (long)g->width * g->height; ++i) {
        float d = a[i] - b[i];
        w->scratch[i] = what == BLOCKS_SQUARED    ? d * d
                        : what == BLOCKS_ABSOLUTE ? fabsf(d)
                        : what == BLOCKS_CODE_CHANGED ? (float)(unorm8_code(a[i]) != unorm8_code(b[i]))
                                                      : d;
    }
    block_mean_add(m, w->scratch, g->mask, g->width, g->height, BLOCK_MEAN_SIZE);
}

static void paired_blocks(work *w, const float *a, const float *b, const float *t, block_mean *m)
{
    const ss_gbuffer *g = w->s->g;
    for (long i = 0; i < (long)g->width * g->height; ++i) {
        float ea = a[i] - t[i], eb = b[i] - t[i];
        w->scratch[i] = ea * ea - eb * eb;
    }
    block_mean_add(m, w->scratch, g->mask, g->width, g->height, BLOCK_MEAN_SIZE);
}

/* 16 point samples, 4 point samples of the MIP chain and a 32-sample search
 * at full resolution against the MIN chain's 4 (kept in w->min4). */
static void four_x(work *w, gtao_half_res_result *r)
{
    const ss_gbuffer *g = w->s->g;
    float *mip4 = w->half_ao; /* free until the next radius */
    render_variant(w, GTAO_HALF_RES_FULL_MIP, GTAO_HALF_RES_4X_RADIUS, mip4);
    gtao_params p16 = search_params(w->s, GTAO_HALF_RES_4X_RADIUS, 4 * GTAO_HALF_RES_STEPS, 0);
    gtao_params converged = search_params(w->s, GTAO_HALF_RES_4X_RADIUS, GTAO_HALF_RES_CONVERGED_STEPS, 0);
    gtao_mip_frame(g, &w->full_mip, GTAO_FETCH_POINT, &p16, w->out);
    gtao_mip_frame(g, &w->full_mip, GTAO_FETCH_POINT, &converged, w->base); /* the baseline is no longer needed */
    paired_blocks(w, w->min4, w->out, w->base, &r->four_x);
    paired_blocks(w, w->min4, mip4, w->base, &r->min_vs_mip);
    add_blocks(w, w->min4, w->base, BLOCKS_SQUARED, &r->four_x_min_se2);
    add_blocks(w, w->out, w->base, BLOCKS_SQUARED, &r->four_x_point_se2);
    add_blocks(w, mip4, w->base, BLOCKS_SQUARED, &r->mip_se2);
}

static double corrected_rmse(const gtao_shortcut_scene *s, const float *a, const float *ref, double variance)
{
    image_error_stats st;
    gt_error e;
    if (image_error_compute(a, ref, s->g->mask, s->g->width, s->g->height, s->name, &st, &e) != 0)
        return 0.0;
    return noise_corrected_rmse(st.rmse, variance);
}

/* No radius limit: the full-resolution search and the talk's against both references. */
static void against_references(work *w, const float *talk, gtao_half_res_scene *x)
{
    const gtao_shortcut_scene *s = w->s;
    x->full_rmse_hf = corrected_rmse(s, w->base, s->hf, s->hf_mean_variance);
    x->talk_rmse_hf = corrected_rmse(s, talk, s->hf, s->hf_mean_variance);
    x->full_rmse_3d = corrected_rmse(s, w->base, s->ref3d, s->ref3d_mean_variance);
    x->talk_rmse_3d = corrected_rmse(s, talk, s->ref3d, s->ref3d_mean_variance);
}

static void one_radius(work *w, gtao_half_res_radius *k, gtao_half_res_result *r, gtao_half_res_scene *x)
{
    gtao_params p = search_params(w->s, k->radius_fraction, GTAO_HALF_RES_STEPS, 0);
    gtao_mip_frame(w->s->g, &w->full_mip, GTAO_FETCH_POINT, &p, w->base);
    for (int v = 0; v < GTAO_HALF_RES_VARIANTS; ++v) {
        float *out = v == GTAO_HALF_RES_FULL_MIP_MIN ? w->min4 : w->out;
        render_variant(w, v, k->radius_fraction, out);
        add_blocks(w, out, w->base, BLOCKS_SQUARED, &k->se2[v]);
        add_blocks(w, out, w->base, BLOCKS_SIGNED, &k->bias[v]);
        add_blocks(w, out, w->base, BLOCKS_ABSOLUTE, &k->change[v]);
        add_blocks(w, out, w->base, BLOCKS_CODE_CHANGED, &k->codes[v]);
    }
    if (k->radius_fraction == 0.0 && w->s->hf && w->s->ref3d)
        against_references(w, w->out, x); /* w->out holds the talk's, the last variant */
    if (k->radius_fraction == GTAO_HALF_RES_4X_RADIUS && !w->s->no_four_x)
        four_x(w, r);
}

static void plan_radii(const gtao_shortcut_scene *s, gtao_half_res_result *r)
{
    if (r->radius_count > 0)
        return;
    if (s->claim_radius_only) {
        r->radius_count = 1;
        r->radii[0].radius_fraction = GTAO_HALF_RES_4X_RADIUS;
        return;
    }
    int stride = s->half_res_radius_stride > 1 ? s->half_res_radius_stride : 1;
    for (int k = 0; k < GTAO_HALF_RES_MAX_RADII; k += stride)
        r->radii[r->radius_count++].radius_fraction = radius_fractions[k];
}

static int run(work *w, gtao_half_res_result *r, gtao_half_res_scene *x)
{
    if (ss_depth_mip_build(w->s->g, SS_DEPTH_MIP_MAX_LEVELS, &w->full_mip) != 0)
        return -1;
    int rc = ss_half_resolution(w->s->g, &w->half);
    if (rc == 0 && (rc = ss_depth_mip_build(&w->half.g, SS_DEPTH_MIP_MAX_LEVELS, &w->half_mip)) == 0) {
        for (int k = 0; k < r->radius_count; ++k)
            one_radius(w, &r->radii[k], r, x);
        ss_depth_mip_free(&w->half_mip);
    }
    ss_half_free(&w->half);
    ss_depth_mip_free(&w->full_mip);
    return rc;
}

int gtao_half_res_scene_study(const gtao_shortcut_scene *s, gtao_half_res_result *r, gt_error *e)
{
    if (r->scene_count == GTAO_SHORTCUT_MAX_SCENES)
        return gt_error_set(e, s->name, "more than %d scenes", GTAO_SHORTCUT_MAX_SCENES);
    plan_radii(s, r);
    gtao_half_res_scene *x = &r->scenes[r->scene_count++];
    snprintf(x->scene, sizeof x->scene, "%s", s->name);
    size_t n = (size_t)s->g->width * s->g->height;
    work w = {.s = s};
    w.base = malloc(sizeof(float) * n);
    w.out = malloc(sizeof(float) * n);
    w.half_ao = malloc(sizeof(float) * n);
    w.scratch = malloc(sizeof(float) * n);
    w.min4 = malloc(sizeof(float) * n);
    int rc = w.base && w.out && w.half_ao && w.scratch && w.min4 ? run(&w, r, x) : -1;
    r->hf_noise_rmse += s->hf_mean_variance; /* averaged in gtao_half_res_finish */
    free(w.base);
    free(w.out);
    free(w.half_ao);
    free(w.scratch);
    free(w.min4);
    return rc != 0 ? gt_error_set(e, s->name, "out of memory") : 0;
}

void gtao_half_res_finish(gtao_half_res_result *r)
{
    for (int k = 0; k < r->radius_count; ++k) {
        gtao_half_res_radius *x = &r->radii[k];
        for (int v = 0; v < GTAO_HALF_RES_VARIANTS; ++v) {
            block_mean_rmse(&x->se2[v], &x->rmse[v], &x->rmse_se[v]);
            x->bias_mean[v] = block_mean_value(&x->bias[v]);
            x->bias_se[v] = block_mean_se(&x->bias[v]);
        }
    }
    r->four_x_mean = block_mean_value(&r->four_x);
    r->four_x_se = block_mean_se(&r->four_x);
    double unused;
    block_mean_rmse(&r->four_x_min_se2, &r->four_x_min_rmse, &unused);
    block_mean_rmse(&r->four_x_point_se2, &r->four_x_point_rmse, &unused);
    block_mean_rmse(&r->mip_se2, &r->mip_rmse, &unused);
    r->min_vs_mip_mean = block_mean_value(&r->min_vs_mip);
    r->min_vs_mip_se = block_mean_se(&r->min_vs_mip);
    const gtao_half_res_radius *last = &r->radii[r->radius_count > 0 ? r->radius_count - 1 : 0];
    r->talk_rmse_unbounded = last->rmse[GTAO_HALF_RES_HALF_MIP_MIN];
    r->talk_rmse_unbounded_se = last->rmse_se[GTAO_HALF_RES_HALF_MIP_MIN];
    r->hf_noise_rmse = r->scene_count > 0 ? sqrt(r->hf_noise_rmse / r->scene_count) : 0.0;
}
