/* The talk's bent-normal estimators against the reference's; see
 * gtao_bent_normals.h. */
#include "gtao/gtao_bent_normals.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gtao/gtao_bent_horizons.h"
#include "project/scene_list.h"
#include "gtao/gtao_quality.h"
#include "gtao/gtao_scene_refs.h"

const char *const bent_estimator_names[BENT_ESTIMATORS] = {"average of the horizon vectors",
                                                           "averaged horizon angles", "visible-arc mean (gtlab)"};

#define DEGREES 57.29577951308232

/* The estimator's world-space bent normal into b[0..2]. */
static int estimate(const gtao_scene_refs *s, const gtao_params *base, bent_estimator k, float *const *b, float *ao)
{
    gtao_params p = *base;
    if (k == BENT_HORIZON_VECTORS) {
        gtao_bent_horizons_frame(&s->in.g, &p, 0, b);
        return 0;
    }
    p.bent_halfway = k == BENT_HALFWAY_ANGLES;
    return gtao_render(&s->in.g, &p, ao, b);
}

/* Angle (degrees) to the reference's bent normal; mask[i] 0 where the
 * reference has none. */
static void angles(const gtao_scene_refs *s, float *const *b, float *angle, float *mask)
{
    for (size_t i = 0; i < (size_t)s->width * s->height; ++i) {
        double r[3] = {s->bent[0][i], s->bent[1][i], s->bent[2][i]};
        double len = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
        mask[i] = s->mask[i] != 0.0f && len > 0.5f ? 1.0f : 0.0f;
        double dot = len > 0.0 ? (b[0][i] * r[0] + b[1][i] * r[1] + b[2][i] * r[2]) / len : 1.0;
        angle[i] = mask[i] != 0.0f ? (float)(DEGREES * acos(fmax(-1.0, fmin(1.0, dot)))) : 0.0f;
    }
}

static int compare_floats(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* Median and 90th percentile of angle over mask; scratch holds n floats. */
static void quantiles(const float *angle, const float *mask, size_t n, float *scratch, bent_row *x)
{
    size_t m = 0;
    for (size_t i = 0; i < n; ++i)
        if (mask[i] != 0.0f)
            scratch[m++] = angle[i];
    qsort(scratch, m, sizeof *scratch, compare_floats);
    x->median = m ? scratch[m / 2] : 0.0;
    x->p90 = m ? scratch[(size_t)(0.9 * (double)(m - 1))] : 0.0;
}

typedef struct {
    float *b[3], *ao, *angle[BENT_ESTIMATORS], *mask, *scratch;
} bent_buffers;

static int buffers_alloc(bent_buffers *w, size_t n)
{
    float **all[] = {&w->b[0], &w->b[1], &w->b[2], &w->ao, &w->angle[0], &w->angle[1], &w->angle[2], &w->mask,
                     &w->scratch};
    int ok = 1;
    for (size_t k = 0; k < sizeof all / sizeof all[0]; ++k)
        ok &= (*all[k] = malloc(sizeof(float) * n)) != NULL;
    return ok ? 0 : -1;
}

static void buffers_free(bent_buffers *w)
{
    for (int k = 0; k < 3; ++k)
        free(w->b[k]);
    for (int k = 0; k < BENT_ESTIMATORS; ++k)
        free(w->angle[k]);
    free(w->ao);
    free(w->mask);
    free(w->scratch);
}

static int score_scene(const gtao_scene_refs *s, const gtao_params *p, bent_buffers *w, bent_row *rows,
                       cluster_mean *halfway_vs_horizons, gt_error *e)
{
    size_t n = (size_t)s->width * s->height;
    for (int k = 0; k < BENT_ESTIMATORS; ++k) {
        if (estimate(s, p, (bent_estimator)k, w->b, w->ao) != 0)
            return gt_error_set(e, s->scene, "out of memory");
        angles(s, w->b, w->angle[k], w->mask);
    }
    for (int k = 0; k < BENT_ESTIMATORS; ++k) {
        bent_row *x = &rows[k];
        snprintf(x->scene, sizeof x->scene, "%s", s->scene);
        snprintf(x->estimator, sizeof x->estimator, "%s", bent_estimator_names[k]);
        if (cluster_mean_compute(w->angle[k], w->mask, s->width, s->height, CLUSTER_MEAN_SIDE, &x->angle) != 0)
            return gt_error_set(e, s->scene, "no pixel with a reference bent normal");
        quantiles(w->angle[k], w->mask, n, w->scratch, x);
        for (size_t i = 0; i < n; ++i)
            w->scratch[i] = w->angle[k][i] - w->angle[BENT_ARC_MEAN][i];
        cluster_mean_compute(w->scratch, w->mask, s->width, s->height, CLUSTER_MEAN_SIDE, &x->vs_arc_mean);
    }
    for (size_t i = 0; i < n; ++i)
        w->scratch[i] = w->angle[BENT_HALFWAY_ANGLES][i] - w->angle[BENT_HORIZON_VECTORS][i];
    cluster_mean_compute(w->scratch, w->mask, s->width, s->height, CLUSTER_MEAN_SIDE, halfway_vs_horizons);
    return 0;
}

static int study_scene(const gtao_shortcuts_request *rq, const char *name, gtao_bent_normals_result *r, int i,
                       gt_error *e)
{
    gtao_scene_refs s;
    if (gtao_scene_refs_load(rq->ao_references_dir, rq->gtao_dir, name, &s, e) != 0)
        return -1;
    int rc = 0;
    if (!s.bent[0] || !s.bent[1] || !s.bent[2])
        rc = gt_error_set(e, name, "the AO reference has no bent normal (bent.X/Y/Z)");
    gtao_params p = gtao_scene_params(&s, GTAO_PRESET_REFERENCE);
    p.slices = r->slices;
    p.steps = r->steps;
    bent_buffers w;
    memset(&w, 0, sizeof w);
    if (rc == 0 && buffers_alloc(&w, (size_t)s.width * s.height) != 0)
        rc = gt_error_set(e, name, "out of memory");
    if (rc == 0)
        rc = score_scene(&s, &p, &w, r->rows[i], &r->halfway_vs_horizons[i], e);
    buffers_free(&w);
    gtao_scene_refs_free(&s);
    return rc;
}

int gtao_bent_normals_study(const study_context *ctx, const gtao_shortcuts_request *rq, gtao_bent_normals_result *out,
                            gt_error *e)
{
    memset(out, 0, sizeof *out);
    const gtao_quality *q = gtao_quality_of(ctx->quality);
    out->slices = q->bent_normals_slices;
    out->steps = q->bent_normals_steps;
    out->scene_count = study_scene_count(ctx) < BENT_MAX_SCENES ? study_scene_count(ctx) : BENT_MAX_SCENES;
    for (int i = 0; i < out->scene_count; ++i)
        if (study_scene(rq, study_scene_at(ctx, i)->label, out, i, e) != 0)
            return -1;
    out->pooled_halfway_vs_horizons = cluster_mean_pool(out->halfway_vs_horizons, out->scene_count);
    for (int k = 0; k < BENT_ESTIMATORS; ++k) {
        cluster_mean a[BENT_MAX_SCENES], d[BENT_MAX_SCENES];
        for (int i = 0; i < out->scene_count; ++i) {
            a[i] = out->rows[i][k].angle;
            d[i] = out->rows[i][k].vs_arc_mean;
        }
        out->pooled_angle[k] = cluster_mean_pool(a, out->scene_count);
        out->pooled_vs_arc_mean[k] = cluster_mean_pool(d, out->scene_count);
    }
    return 0;
}
