/* GTAO beside HBAO, VO, Alchemy, Crytek and the pitfall; see
 * gtao_baselines.h. */
#include "gtao/gtao_baselines.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/progress.h"
#include "gtao/alchemy_ao.h"
#include "gtao/crytek_ssao.h"
#include "gtao/gtao_sin_n_pitfall.h"
#include "gtao/hbao.h"
#include "gtao/volumetric_obscurance.h"
#include "project/scene_list.h"
#include "gtao/gtao_scene_refs.h"

const char *const baseline_names[BASELINE_COUNT] = {
    "GTAO medium", "HBAO 8x8", "VO 4 samples", "Alchemy 12 samples", "Crytek SSAO 16 points",
    "GTAO medium, |sin n| pitfall"};

/* Technique t on scene s into ao, one frame, denoised. */
static int render(const gtao_scene_refs *s, baseline_technique t, float *ao)
{
    const ss_gbuffer *g = &s->in.g;
    gtao_params p = gtao_scene_params(s, GTAO_PRESET_MEDIUM);
    switch (t) {
    case BASELINE_GTAO: return gtao_render(g, &p, ao, NULL);
    case BASELINE_PITFALL: return gtao_pitfall_render(g, &p, ao);
    case BASELINE_HBAO: {
        hbao_params h = {8, 8, p.radius, p.max_radius_px, 0, 1, 1, 1};
        return hbao_render(g, &h, ao);
    }
    case BASELINE_VO: {
        vo_params o = {s->vo_radius, p.max_radius_px, 1, 1, 1};
        return vo_render(g, &o, ao);
    }
    case BASELINE_ALCHEMY: {
        alchemy_params a = alchemy_default_params(s->vo_radius);
        a.max_radius_px = p.max_radius_px;
        a.denoise = 1;
        return alchemy_render(g, &a, ao);
    }
    default: {
        crytek_params c = {16, s->vo_radius, 1, 1, 1};
        return crytek_render(g, &c, ao);
    }
    }
}

/* Every technique on one scene; GTAO first, kept in gtao for the pairing. */
static int study_scene(const gtao_scene_refs *s, float *ao, float *gtao, baseline_row *rows, gt_error *e)
{
    for (int t = 0; t < BASELINE_COUNT; ++t) {
        baseline_row *x = &rows[t];
        snprintf(x->scene, sizeof x->scene, "%s", s->scene);
        snprintf(x->technique, sizeof x->technique, "%s", baseline_names[t]);
        double t0 = seconds_now();
        if (render(s, (baseline_technique)t, t == BASELINE_GTAO ? gtao : ao) != 0)
            return gt_error_set(e, s->scene, "out of memory");
        x->ms_per_frame = 1e3 * (seconds_now() - t0);
        if (ao_image_score_compute(s, t == BASELINE_GTAO ? gtao : ao, gtao, &x->score, e) != 0)
            return -1;
    }
    return 0;
}

static void pool(gtao_baselines_result *r)
{
    for (int t = 0; t < BASELINE_COUNT; ++t)
        ao_image_score_pool(&r->rows[0][t].score, sizeof r->rows[0], r->scene_count, &r->pooled_vs_gtao_3d[t],
                            &r->pooled_rmse_3d[t]);
}

int gtao_baselines_study(const study_context *ctx, const gtao_shortcuts_request *rq, gtao_baselines_result *out,
                         gt_error *e)
{
    memset(out, 0, sizeof *out);
    out->scene_count = study_scene_count(ctx) < BASELINES_MAX_SCENES ? study_scene_count(ctx) : BASELINES_MAX_SCENES;
    for (int i = 0; i < out->scene_count; ++i) {
        gtao_scene_refs s;
        if (gtao_scene_refs_load(rq->ao_references_dir, rq->gtao_dir, study_scene_at(ctx, i)->label, &s, e) != 0)
            return -1;
        size_t n = (size_t)s.width * s.height;
        float *ao = malloc(sizeof *ao * n), *gtao = malloc(sizeof *gtao * n);
        int rc = ao && gtao ? study_scene(&s, ao, gtao, out->rows[i], e) : gt_error_set(e, s.scene, "out of memory");
        free(ao);
        free(gtao);
        gtao_scene_refs_free(&s);
        if (rc != 0)
            return -1;
    }
    pool(out);
    return 0;
}
