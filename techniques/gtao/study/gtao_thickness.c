/* The thickness heuristic against the 3-D reference; see gtao_thickness.h. */
#include "gtao/gtao_thickness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "project/scene_list.h"
#include "gtao/gtao_quality.h"
#include "gtao/gtao_scene_refs.h"

const float gtao_thickness_values[THICKNESS_VALUES] = {0.05f, 0.1f, 0.25f, 0.5f};

static double mse_of(const float *a, const float *b, const float *mask, size_t n)
{
    double sum = 0.0;
    size_t count = 0;
    for (size_t i = 0; i < n; ++i)
        if (mask[i] != 0.0f) {
            sum += ((double)a[i] - b[i]) * ((double)a[i] - b[i]);
            ++count;
        }
    return count ? sum / (double)count : 0.0;
}

static double mean_variance(const float *stderr_plane, const float *mask, size_t n)
{
    double sum = 0.0;
    size_t count = 0;
    for (size_t i = 0; i < n; ++i)
        if (mask[i] != 0.0f) {
            sum += (double)stderr_plane[i] * stderr_plane[i];
            ++count;
        }
    return count ? sum / (double)count : 0.0;
}

static int score_scene(const gtao_scene_refs *s, const gtao_params *base, float *none, float *ao,
                       gtao_thickness_result *r, int i, gt_error *e)
{
    size_t n = (size_t)s->width * s->height;
    gtao_params p = *base;
    if (gtao_render(&s->in.g, &p, none, NULL) != 0)
        return gt_error_set(e, s->scene, "out of memory");
    r->mse_none_3d[i] = mse_of(none, s->ref3d, s->mask, n);
    r->mse_none_hf[i] = mse_of(none, s->hf_ao, s->mask, n);
    double model = r->mse_none_3d[i] - mean_variance(s->ref3d_stderr, s->mask, n);
    for (int k = 0; k < THICKNESS_VALUES; ++k) {
        thickness_row *x = &r->rows[i][k];
        snprintf(x->scene, sizeof x->scene, "%s", s->scene);
        p.thickness = gtao_thickness_values[k];
        x->thickness = p.thickness;
        if (gtao_render(&s->in.g, &p, ao, NULL) != 0)
            return gt_error_set(e, s->scene, "out of memory");
        x->mse_3d = mse_of(ao, s->ref3d, s->mask, n);
        x->mse_hf = mse_of(ao, s->hf_ao, s->mask, n);
        if (cluster_mean_paired_sq_error(ao, none, s->ref3d, s->mask, s->width, s->height, CLUSTER_MEAN_SIDE,
                                       &x->vs_none_3d) != 0 ||
            cluster_mean_difference(ao, none, s->mask, s->width, s->height, CLUSTER_MEAN_SIDE, &x->change) != 0 ||
            cluster_mean_code_changes(ao, none, s->mask, s->width, s->height, CLUSTER_MEAN_SIDE, &x->codes) != 0)
            return gt_error_set(e, s->scene, "out of memory");
        x->removed_percent = model > 0.0 ? -100.0 * x->vs_none_3d.mean / model : 0.0;
    }
    return 0;
}

static int study_scene(const study_context *ctx, const gtao_shortcuts_request *rq, gtao_thickness_result *r, int i,
                       gt_error *e)
{
    gtao_scene_refs s;
    if (gtao_scene_refs_load(rq->ao_references_dir, rq->gtao_dir, study_scene_at(ctx, i)->label, &s, e) != 0)
        return -1;
    gtao_params p = gtao_scene_params(&s, GTAO_PRESET_REFERENCE);
    p.slices = r->slices;
    p.steps = r->steps;
    size_t n = (size_t)s.width * s.height;
    float *none = malloc(sizeof *none * n), *ao = malloc(sizeof *ao * n);
    int rc = none && ao ? score_scene(&s, &p, none, ao, r, i, e) : gt_error_set(e, s.scene, "out of memory");
    free(none);
    free(ao);
    gtao_scene_refs_free(&s);
    return rc;
}

int gtao_thickness_study(const study_context *ctx, const gtao_shortcuts_request *rq, gtao_thickness_result *out,
                         gt_error *e)
{
    memset(out, 0, sizeof *out);
    const gtao_quality *q = gtao_quality_of(ctx->quality);
    out->slices = q->thickness_slices;
    out->steps = q->thickness_steps;
    out->corner_scene = -1;
    out->scene_count = study_scene_count(ctx) < THICKNESS_MAX_SCENES ? study_scene_count(ctx) : THICKNESS_MAX_SCENES;
    for (int i = 0; i < out->scene_count; ++i) {
        if (study_scene(ctx, rq, out, i, e) != 0)
            return -1;
        if (strcmp(study_scene_at(ctx, i)->spec, "builtin:corner") == 0)
            out->corner_scene = i;
    }
    for (int k = 0; k < THICKNESS_VALUES; ++k) {
        cluster_mean parts[THICKNESS_MAX_SCENES];
        for (int i = 0; i < out->scene_count; ++i)
            parts[i] = out->rows[i][k].vs_none_3d;
        out->pooled_vs_none_3d[k] = cluster_mean_pool(parts, out->scene_count);
        if (out->pooled_vs_none_3d[k].mean < out->pooled_vs_none_3d[out->best].mean)
            out->best = k;
    }
    return 0;
}
