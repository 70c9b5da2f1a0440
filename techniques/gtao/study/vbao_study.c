/* VBAO beside GTAO, its error split and thickness search; see vbao_study.h. */
#include "gtao/vbao_study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ao/ao_quantity.h"
#include "core/files/exr_io.h"
#include "core/progress.h"
#include "core/reference_schema.h"
#include "metrics/noise_corrected.h"
#include "ao/heightfield_ao_integrator.h"
#include "raytracer/reference_render.h"
#include "gtao/vbao.h"
#include "project/scene_list.h"
#include "scene/scene_loaders.h"
#include "gtao/gtao_quality.h"
#include "gtao/gtao_scene_refs.h"

const char *const vbao_row_names[VBAO_ROW_COUNT] = {
    "GTAO medium", "GTAO high", "GTAO medium, thickness heuristic", "VBAO medium, the paper's choices",
    "VBAO medium, cosine sectors, depth + T", "VBAO high, cosine sectors, depth + T"};

enum { SEARCH_STEPS = 10 };
static const double search_lo = 0.002, search_hi = 1.0; /* fractions of the camera distance */

/* One scene: its references, T and the scratch planes. */
typedef struct {
    gtao_scene_refs refs;
    image hf_thick;
    const float *thick_ao, *thick_stderr;
    float camera_distance, heuristic;
    float *ao, *gtao;
} scene_run;

static vbao_params vbao_scene_params(const scene_run *s, vbao_params p)
{
    gtao_params g = gtao_scene_params(&s->refs, GTAO_PRESET_MEDIUM);
    g.slices = p.gtao.slices;
    g.steps = p.gtao.steps;
    p.gtao = g;
    return p;
}

static int render_row(const scene_run *s, vbao_row_kind k, float thickness, float *ao)
{
    const ss_gbuffer *g = &s->refs.in.g;
    int preset = k == VBAO_ROW_GTAO_HIGH || k == VBAO_ROW_EXACT_HIGH ? GTAO_PRESET_HIGH : GTAO_PRESET_MEDIUM;
    if (k <= VBAO_ROW_GTAO_HEURISTIC) {
        gtao_params p = gtao_scene_params(&s->refs, preset);
        p.thickness = k == VBAO_ROW_GTAO_HEURISTIC ? s->heuristic : 0.0f;
        return gtao_render(g, &p, ao, NULL);
    }
    vbao_params p =
        vbao_scene_params(s, vbao_preset(preset, thickness, k == VBAO_ROW_PAPER_MEDIUM ? VBAO_PAPER : VBAO_EXACT));
    return vbao_render(g, &p, ao, NULL);
}

static double mse_3d(const scene_run *s, const float *ao)
{
    double sum = 0.0;
    size_t count = 0;
    for (size_t i = 0; i < (size_t)s->refs.width * s->refs.height; ++i)
        if (s->refs.mask[i] != 0.0f) {
            double d = (double)ao[i] - s->refs.ref3d[i];
            sum += d * d;
            ++count;
        }
    return count ? sum / (double)count : 0.0;
}

/* Every row of one scene; GTAO medium first, kept for the pairing. */
static int rank_scene(const scene_run *s, float thickness, vbao_row *rows, gt_error *e)
{
    for (int k = 0; k < VBAO_ROW_COUNT; ++k) {
        vbao_row *x = &rows[k];
        float *ao = k == VBAO_ROW_GTAO_MEDIUM ? s->gtao : s->ao;
        snprintf(x->scene, sizeof x->scene, "%s", s->refs.scene);
        snprintf(x->technique, sizeof x->technique, "%s", vbao_row_names[k]);
        double t0 = seconds_now();
        if (render_row(s, (vbao_row_kind)k, thickness, ao) != 0)
            return gt_error_set(e, s->refs.scene, "out of memory");
        x->ms_per_frame = 1e3 * (seconds_now() - t0);
        if (ao_image_score_compute(&s->refs, ao, s->gtao, &x->score, e) != 0)
            return -1;
    }
    return 0;
}

/* VBAO medium (gtlab's choices)'s MSE against the 3-D reference at a thickness. */
static double mse_at(const scene_run *s, double thickness)
{
    if (render_row(s, VBAO_ROW_EXACT_MEDIUM, (float)thickness, s->ao) != 0)
        return INFINITY;
    return mse_3d(s, s->ao);
}

/* Golden-section search of log T over [search_lo, search_hi] camera distances. */
static double best_fraction(const scene_run *s, double *best_mse)
{
    const double ratio = 0.6180339887498949;
    double a = log(search_lo), b = log(search_hi);
    double c = b - ratio * (b - a), d = a + ratio * (b - a);
    double fc = mse_at(s, s->camera_distance * exp(c)), fd = mse_at(s, s->camera_distance * exp(d));
    for (int i = 0; i < SEARCH_STEPS; ++i) {
        if (fc <= fd) {
            b = d, d = c, fd = fc;
            c = b - ratio * (b - a);
            fc = mse_at(s, s->camera_distance * exp(c));
        } else {
            a = c, c = d, fc = fd;
            d = a + ratio * (b - a);
            fd = mse_at(s, s->camera_distance * exp(d));
        }
    }
    *best_mse = fc <= fd ? fc : fd;
    return exp(fc <= fd ? c : d);
}

static double rmse_between(const scene_run *s, const float *a, const float *b)
{
    double sum = 0.0;
    size_t count = 0;
    for (size_t i = 0; i < (size_t)s->refs.width * s->refs.height; ++i)
        if (s->refs.mask[i] != 0.0f) {
            sum += ((double)a[i] - b[i]) * ((double)a[i] - b[i]);
            ++count;
        }
    return count ? sqrt(sum / (double)count) : 0.0;
}

static void split_scene(const scene_run *s, float thickness, vbao_split_row *x)
{
    size_t n = (size_t)s->refs.width * s->refs.height;
    double thick_var = noise_mean_variance(s->thick_stderr, s->refs.mask, n);
    double hf_var = noise_mean_variance(s->refs.hf_stderr, s->refs.mask, n);
    double ref_var = noise_mean_variance(s->refs.ref3d_stderr, s->refs.mask, n);
    snprintf(x->scene, sizeof x->scene, "%s", s->refs.scene);
    x->thickness = thickness;
    render_row(s, VBAO_ROW_EXACT_MEDIUM, thickness, s->ao);
    x->default_mse_3d = mse_3d(s, s->ao);
    x->estimator_rmse = noise_corrected_rmse(rmse_between(s, s->ao, s->thick_ao), thick_var);
    x->screen_rmse = noise_corrected_rmse(rmse_between(s, s->thick_ao, s->refs.ref3d), thick_var + ref_var);
    x->screen_rmse_infinite = noise_corrected_rmse(rmse_between(s, s->refs.hf_ao, s->refs.ref3d), hf_var + ref_var);
    x->infinite_mse_3d = mse_at(s, INFINITY);
    x->best_fraction = best_fraction(s, &x->best_mse_3d);
    x->best_thickness = x->best_fraction * s->camera_distance;
}

/* The thickness-T height-field reference at the 3-D reference's camera, written beside the infinite one. */
static int render_thick(const study_context *ctx, const char *gtao_dir, int spp, float thickness, scene_run *s,
                        gt_error *e)
{
    char path[4096];
    const char *spec = study_scene_spec(ctx, s->refs.scene);
    snprintf(path, sizeof path, "%s/%s_heightfield_thickness.exr", gtao_dir, s->refs.scene);
    scene sc;
    if (scene_load(spec, &sc, e) != 0)
        return -1;
    heightfield_ao_options o = heightfield_ao_thickness(thickness);
    reference_request req = {.quantity = QUANTITY_HEIGHTFIELD_AO,
                             .sampling = {.spp = spp, .seed = 1, .threads = ctx->threads},
                             .normals = NORMAL_SHADING, .settings = &o.header};
    render_stats stats;
    int rc = reference_render(&sc, spec, &s->refs.in.cam, &req, &s->hf_thick, &stats, e);
    scene_free(&sc);
    if (rc == 0 && (rc = exr_write(path, &s->hf_thick, e)) != 0)
        image_free(&s->hf_thick);
    s->thick_ao = rc == 0 ? image_channel_data(&s->hf_thick, CH_AO) : NULL;
    s->thick_stderr = rc == 0 ? image_channel_data(&s->hf_thick, CH_AO_STDERR) : NULL;
    return rc;
}

static int run_scene(const study_context *ctx, const gtao_shortcuts_request *rq, vbao_study_result *r, scene_run *s,
                     int i, gt_error *e)
{
    s->camera_distance = v3_length(v3_sub(s->refs.in.cam.target, s->refs.in.cam.position));
    float thickness = (float)VBAO_THICKNESS_FRACTION * s->camera_distance;
    size_t n = (size_t)s->refs.width * s->refs.height;
    s->ao = malloc(sizeof(float) * n);
    s->gtao = malloc(sizeof(float) * n);
    if (!s->ao || !s->gtao)
        return gt_error_set(e, s->refs.scene, "out of memory");
    if (render_thick(ctx, rq->gtao_dir, r->heightfield_spp, thickness, s, e) != 0 ||
        rank_scene(s, thickness, r->rows[i], e) != 0)
        return -1;
    split_scene(s, thickness, &r->split[i]);
    return 0;
}

static int study_scene(const study_context *ctx, const gtao_shortcuts_request *rq, vbao_study_result *r, int i,
                       gt_error *e)
{
    scene_run s = {.heuristic = (float)r->heuristic_thickness};
    if (gtao_scene_refs_load(rq->ao_references_dir, rq->gtao_dir, study_scene_at(ctx, i)->label, &s.refs, e) != 0)
        return -1;
    int rc = run_scene(ctx, rq, r, &s, i, e);
    free(s.ao);
    free(s.gtao);
    image_free(&s.hf_thick);
    gtao_scene_refs_free(&s.refs);
    return rc;
}

static void pool(vbao_study_result *r)
{
    for (int k = 0; k < VBAO_ROW_COUNT; ++k)
        ao_image_score_pool(&r->rows[0][k].score, sizeof r->rows[0], r->scene_count, &r->pooled_vs_gtao_3d[k],
                            &r->pooled_rmse_3d[k]);
}

int vbao_study(const study_context *ctx, const gtao_shortcuts_request *rq, float heuristic, vbao_study_result *out,
               gt_error *e)
{
    memset(out, 0, sizeof *out);
    out->heightfield_spp = gtao_quality_of(ctx->quality)->vbao_heightfield_spp;
    out->heuristic_thickness = heuristic;
    int count = study_scene_count(ctx);
    out->scene_count = count < VBAO_MAX_SCENES ? count : VBAO_MAX_SCENES;
    for (int i = 0; i < out->scene_count; ++i)
        if (study_scene(ctx, rq, out, i, e) != 0)
            return -1;
    pool(out);
    return 0;
}
