/* GTAO with the talk's distance fade against a reference with the same
 * fade; see gtao_distance_fade.h. */
#include "gtao/gtao_distance_fade.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/reference_schema.h"
#include "ao/ao_quantity.h"
#include "project/scene_list.h"
#include "scene/scene_loaders.h"
#include "gtao/gtao_quality.h"
#include "gtao/gtao_scene_refs.h"

#define FADE_START_FRACTION 0.75f /* 150 / 200 */

/* The 3-D AO reference at s's camera with occluders fading from `start` to
 * `end` (start >= end: cut off hard at end). */
static int render_faded(const study_context *ctx, const gtao_scene_refs *s, const gtao_distance_fade_result *r,
                        float start, float end, image *out, gt_error *e)
{
    const char *spec = study_scene_spec(ctx, s->scene);
    const int threads = ctx->threads;
    scene sc;
    if (scene_load(spec, &sc, e) != 0)
        return -1;
    ao_render_settings ao = {{QUANTITY_AO}, .max_distance = end, .fade_start = start};
    reference_request req = {.quantity = QUANTITY_AO, .sampling = {.spp = r->spp, .seed = 1, .threads = threads},
                             .normals = NORMAL_SHADING, .settings = &ao.header};
    render_stats stats;
    int rc = reference_render(&sc, spec, &s->in.cam, &req, out, &stats, e);
    scene_free(&sc);
    return rc;
}

static double rmse_of(const float *a, const float *b, const float *mask, size_t n)
{
    double sum = 0.0;
    size_t count = 0;
    for (size_t i = 0; i < n; ++i)
        if (mask[i] != 0.0f) {
            sum += ((double)a[i] - b[i]) * ((double)a[i] - b[i]);
            ++count;
        }
    return count ? sqrt(sum / (double)count) : 0.0;
}

/* ao: GTAO with the fade; hard: the same cut off hard at the fade's end;
 * faded, cut: the references likewise. */
static int score(const gtao_scene_refs *s, const float *ao, const float *hard, const float *faded, const float *cut,
                 float *d, fade_row *x)
{
    size_t n = (size_t)s->width * s->height;
    x->rmse_faded = rmse_of(ao, faded, s->mask, n);
    x->rmse_unbounded = rmse_of(ao, s->ref3d, s->mask, n);
    for (size_t i = 0; i < n; ++i)
        d[i] = ao[i] - faded[i];
    int rc = cluster_mean_compute(d, s->mask, s->width, s->height, CLUSTER_MEAN_SIDE, &x->signed_vs_faded);
    for (size_t i = 0; i < n; ++i)
        d[i] = faded[i] - s->ref3d[i];
    rc |= cluster_mean_compute(d, s->mask, s->width, s->height, CLUSTER_MEAN_SIDE, &x->reference_gap);
    for (size_t i = 0; i < n; ++i) {
        double u = (double)ao[i] - s->ref3d[i], f = (double)ao[i] - faded[i];
        d[i] = (float)(u * u - f * f);
    }
    rc |= cluster_mean_compute(d, s->mask, s->width, s->height, CLUSTER_MEAN_SIDE, &x->scoring_bias);
    rc |= cluster_mean_difference(ao, hard, s->mask, s->width, s->height, CLUSTER_MEAN_SIDE, &x->gtao_change);
    rc |= cluster_mean_difference(faded, cut, s->mask, s->width, s->height, CLUSTER_MEAN_SIDE, &x->reference_change);
    for (size_t i = 0; i < n; ++i)
        d[i] = (float)(((double)ao[i] - hard[i]) - ((double)faded[i] - cut[i]));
    rc |= cluster_mean_compute(d, s->mask, s->width, s->height, CLUSTER_MEAN_SIDE, &x->change_vs_truth);
    return rc;
}

static int study_scene(const study_context *ctx, const gtao_shortcuts_request *rq, gtao_distance_fade_result *r,
                       int i, gt_error *e)
{
    gtao_scene_refs s;
    fade_row *x = &r->rows[i];
    if (gtao_scene_refs_load(rq->ao_references_dir, rq->gtao_dir, study_scene_at(ctx, i)->label, &s, e) != 0)
        return -1;
    snprintf(x->scene, sizeof x->scene, "%s", s.scene);
    x->fade_end = s.vo_radius;
    x->fade_start = FADE_START_FRACTION * s.vo_radius;
    image faded = {0}, cut = {0};
    int rc = render_faded(ctx, &s, r, x->fade_start, x->fade_end, &faded, e);
    if (rc == 0)
        rc = render_faded(ctx, &s, r, x->fade_end, x->fade_end, &cut, e);
    size_t n = (size_t)s.width * s.height;
    float *ao = malloc(sizeof *ao * n), *hard = malloc(sizeof *hard * n), *d = malloc(sizeof *d * n);
    if (rc == 0 && (!ao || !hard || !d))
        rc = gt_error_set(e, s.scene, "out of memory");
    if (rc == 0) {
        gtao_params p = gtao_scene_params(&s, GTAO_PRESET_REFERENCE);
        p.slices = r->slices;
        p.steps = r->steps;
        p.radius = s.vo_radius;
        gtao_params fade = p; /* p: cut off hard at the radius (falloff 0) */
        fade.falloff = 1.0f - FADE_START_FRACTION;
        rc = gtao_render(&s.in.g, &fade, ao, NULL) != 0 || gtao_render(&s.in.g, &p, hard, NULL) != 0
                 ? gt_error_set(e, s.scene, "out of memory")
             : score(&s, ao, hard, image_channel_data(&faded, CH_AO), image_channel_data(&cut, CH_AO), d, x) != 0
                 ? gt_error_set(e, s.scene, "no pixel inside the mask, or out of memory")
                 : 0;
    }
    free(ao);
    free(hard);
    free(d);
    image_free(&faded);
    image_free(&cut);
    gtao_scene_refs_free(&s);
    return rc;
}

int gtao_distance_fade_study(const study_context *ctx, const gtao_shortcuts_request *rq,
                             gtao_distance_fade_result *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    const gtao_quality *q = gtao_quality_of(ctx->quality);
    out->slices = q->distance_fade_slices;
    out->steps = q->distance_fade_steps;
    out->spp = q->distance_fade_spp;
    out->scene_count = study_scene_count(ctx) < FADE_MAX_SCENES ? study_scene_count(ctx) : FADE_MAX_SCENES;
    cluster_mean a[FADE_MAX_SCENES], b[FADE_MAX_SCENES], c[FADE_MAX_SCENES], g[FADE_MAX_SCENES], t[FADE_MAX_SCENES],
        h[FADE_MAX_SCENES];
    for (int i = 0; i < out->scene_count; ++i) {
        if (study_scene(ctx, rq, out, i, e) != 0)
            return -1;
        a[i] = out->rows[i].signed_vs_faded;
        b[i] = out->rows[i].reference_gap;
        c[i] = out->rows[i].scoring_bias;
        g[i] = out->rows[i].gtao_change;
        t[i] = out->rows[i].change_vs_truth;
        h[i] = out->rows[i].reference_change;
    }
    out->pooled_signed_vs_faded = cluster_mean_pool(a, out->scene_count);
    out->pooled_reference_gap = cluster_mean_pool(b, out->scene_count);
    out->pooled_scoring_bias = cluster_mean_pool(c, out->scene_count);
    out->pooled_gtao_change = cluster_mean_pool(g, out->scene_count);
    out->pooled_change_vs_truth = cluster_mean_pool(t, out->scene_count);
    out->pooled_reference_change = cluster_mean_pool(h, out->scene_count);
    return 0;
}
