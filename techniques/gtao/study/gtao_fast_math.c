/* The fast arc cosine and square root in AO error, and the arc cosine's
 * refit; see gtao_fast_math.h. */
#include "gtao/gtao_fast_math.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fitters/ceres_bridge.h"
#include "project/scene_list.h"
#include "gtao/gtao_quality.h"
#include "gtao/gtao_scene_refs.h"
#include "gtao/gtao_talk_setting.h"

const char *const fast_acos_variant_names[FAST_ACOS_VARIANTS] = {
    "exact acosf", "talk, sqrt constant as transcribed", "talk (Drobot's sqrt constant)", "slope refitted",
    "slope and constant refitted",
    "slope refitted to the references"};

#define FD_STEP 1e-3 /* central differences of the AO in the coefficients (the AO is float) */

/* One scene's horizons, searched once, and its references. */
typedef struct {
    const gtao_scene_refs *refs;
    int slices, count, stride;
    int against_reference; /* the fit's target: 0 the exact-acosf AO, 1 the height-field reference */
    long *pixel;           /* the masked pixels */
    float *exact;          /* the replayed AO with acosf, per masked pixel */
    gtao_slice_cosines *c; /* count x slices */
} replay_scene;

static float replay_pixel(const replay_scene *rs, int k, const gtao_acos_poly *poly)
{
    float sum = 0.0f;
    for (int j = 0; j < rs->slices; ++j)
        sum += gtao_replay_slice(&rs->c[(size_t)k * rs->slices + j], poly);
    return sum / (float)rs->slices;
}

/* The replayed AO of every masked pixel into ao (0 elsewhere). */
static void replay_image(const replay_scene *rs, const gtao_acos_poly *poly, float *ao)
{
    memset(ao, 0, sizeof *ao * (size_t)rs->refs->width * rs->refs->height);
#pragma omp parallel for schedule(dynamic, 256)
    for (int k = 0; k < rs->count; ++k)
        ao[rs->pixel[k]] = replay_pixel(rs, k, poly);
}

/* Regular slices (no pattern), offset 0.5: the brute-force sampling of p. */
static int build_replay(const gtao_scene_refs *refs, const gtao_params *p, int stride, replay_scene *rs)
{
    size_t n = (size_t)refs->width * refs->height;
    rs->refs = refs;
    rs->slices = p->slices;
    rs->stride = stride;
    rs->count = 0;
    rs->against_reference = 0;
    rs->pixel = malloc(sizeof *rs->pixel * n);
    rs->exact = malloc(sizeof *rs->exact * n);
    rs->c = malloc(sizeof *rs->c * n * (size_t)p->slices);
    if (!rs->pixel || !rs->c || !rs->exact)
        return -1;
    for (size_t i = 0; i < n; ++i)
        if (refs->mask[i] != 0.0f)
            rs->pixel[rs->count++] = (long)i;
#pragma omp parallel for schedule(dynamic, 64)
    for (int k = 0; k < rs->count; ++k)
        for (int j = 0; j < p->slices; ++j) {
            int x = (int)(rs->pixel[k] % refs->width), y = (int)(rs->pixel[k] / refs->width);
            float phi = gtao_slice_angle(x, y, 0, j, p->slices, 0);
            gtao_slice_cosines_at(&refs->in.g, x, y, p, phi, 0.5f, &rs->c[(size_t)k * p->slices + j]);
        }
#pragma omp parallel for schedule(dynamic, 256)
    for (int k = 0; k < rs->count; ++k)
        rs->exact[k] = replay_pixel(rs, k, NULL);
    return 0;
}

static void free_replay(replay_scene *rs)
{
    free(rs->pixel);
    free(rs->exact);
    free(rs->c);
}

static int on_bound(const double *p)
{
    return fabs(p[0] - -1.0) < 1e-9 || fabs(p[0] - 1.0) < 1e-9 || fabs(p[1] - 1.0) < 1e-9 || fabs(p[1] - 2.5) < 1e-9;
}

static gtao_acos_poly poly_of(const double *params)
{
    return (gtao_acos_poly){(float)params[0], (float)params[1], GTAO_FAST_SQRT_MAGIC};
}

/* Residuals AO - target (the exact-acosf AO or the height-field reference)
 * on every stride-th masked pixel; the Jacobian by central differences. */
static int fit_residuals(void *user, const double *params, double *r, double *jac)
{
    const replay_scene *rs = user;
    gtao_acos_poly at = poly_of(params);
    for (int i = 0, k = 0; k < rs->count; ++i, k += rs->stride) {
        float target = rs->against_reference ? rs->refs->hf_ao[rs->pixel[k]] : rs->exact[k];
        r[i] = (double)replay_pixel(rs, k, &at) - target;
        for (int j = 0; jac && j < 2; ++j) {
            double lo[2] = {params[0], params[1]}, hi[2] = {params[0], params[1]};
            lo[j] -= FD_STEP;
            hi[j] += FD_STEP;
            gtao_acos_poly a = poly_of(lo), b = poly_of(hi);
            jac[2 * i + j] = ((double)replay_pixel(rs, k, &b) - replay_pixel(rs, k, &a)) / (2.0 * FD_STEP);
        }
    }
    return 0;
}

static int residual_count(const replay_scene *rs) { return (rs->count + rs->stride - 1) / rs->stride; }

/* Fits c1 (and c0 unless hold_constant) on every scene but `left_out` (-1:
 * all), from params. Returns 0 or -1 with e. */
static int fit_poly(const replay_scene *rs, int scenes, int left_out, int hold_constant, int threads, double *params,
                    gt_fit_result *res, double *slope_se, gt_error *e)
{
    gt_fit *fit = gt_fit_create(2, params, e);
    if (!fit)
        return -1;
    int rc = gt_fit_set_bounds(fit, 0, -1.0, 1.0, e) != 0 || gt_fit_set_bounds(fit, 1, 1.0, 2.5, e) != 0 ||
             gt_fit_hold(fit, 1, hold_constant, e) != 0;
    for (int s = 0; s < scenes && !rc; ++s)
        if (s != left_out)
            rc = gt_fit_add_block(fit, residual_count(&rs[s]), fit_residuals, (void *)&rs[s], NULL, e) != 0;
    gt_fit_options o = gt_fit_default_options();
    o.threads = threads;
    o.function_tolerance = 1e-10;
    if (!rc)
        rc = gt_fit_solve(fit, &o, res, e) != 0;
    if (!rc && slope_se) {
        double se[2];
        rc = gt_fit_covariance(fit, NULL, se, NULL, e) != 0;
        *slope_se = se[0];
    }
    gt_fit_destroy(fit);
    return rc ? -1 : 0;
}

static double function_error(const gtao_acos_poly *poly)
{
    double worst = 0.0;
    for (int i = 0; i <= 4000; ++i) {
        float x = -1.0f + (float)i / 2000.0f;
        double a = poly ? gtao_fast_acos_poly(x, poly) : acosf(x);
        worst = fmax(worst, fabs(a - acos((double)x)));
    }
    return worst;
}

static double jackknife_se(const double *values, int n)
{
    double mean = 0.0, sum = 0.0;
    for (int i = 0; i < n; ++i)
        mean += values[i] / n;
    for (int i = 0; i < n; ++i)
        sum += (values[i] - mean) * (values[i] - mean);
    return sqrt((double)(n - 1) / n * sum);
}

static void mean_and_se(const double *values, int n, double *mean, double *se)
{
    *mean = 0.0;
    for (int i = 0; i < n; ++i)
        *mean += values[i] / n;
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        sum += (values[i] - *mean) * (values[i] - *mean);
    *se = n > 1 ? sqrt(sum / (n - 1) / n) : 0.0;
}

/* Mean and max |a - b| over the mask. */
static void shift_stats(const float *a, const float *b, const float *mask, size_t n, double *mean, double *max)
{
    double sum = 0.0;
    size_t count = 0;
    *max = 0.0;
    for (size_t i = 0; i < n; ++i)
        if (mask[i] != 0.0f) {
            double d = fabs((double)a[i] - b[i]);
            sum += d;
            *max = fmax(*max, d);
            ++count;
        }
    *mean = count ? sum / (double)count : 0.0;
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

/* GTAO with p's fast maths on into `on`, off into `off`. */
static int on_off(const ss_gbuffer *g, gtao_params p, const char *name, float *on, float *off, gt_error *e)
{
    p.fast_math = 1;
    if (gtao_render(g, &p, on, NULL) != 0)
        return gt_error_set(e, name, "out of memory");
    p.fast_math = 0;
    if (gtao_render(g, &p, off, NULL) != 0)
        return gt_error_set(e, name, "out of memory");
    return 0;
}

/* (a): GTAO medium, one frame, fast maths on against off. */
static int medium_on_off(const gtao_scene_refs *s, float *on, float *off, gtao_fast_math_scene *x, gt_error *e)
{
    if (on_off(&s->in.g, gtao_scene_params(s, GTAO_PRESET_MEDIUM), s->scene, on, off, e) != 0)
        return -1;
    shift_stats(on, off, s->mask, (size_t)s->width * s->height, &x->medium_shift_mean, &x->medium_shift_max);
    if (cluster_mean_paired_sq_error(on, off, s->hf_ao, s->mask, s->width, s->height, CLUSTER_MEAN_SIDE,
                                   &x->medium_paired_hf) != 0 ||
        cluster_mean_abs_difference(on, off, s->mask, s->width, s->height, CLUSTER_MEAN_SIDE, &x->medium_change) != 0 ||
        cluster_mean_code_changes(on, off, s->mask, s->width, s->height, CLUSTER_MEAN_SIDE, &x->medium_codes) != 0)
        return gt_error_set(e, s->scene, "no pixel inside the mask, or out of memory");
    return 0;
}

/* (c) on one scene: GTAO medium at the talk's radius on and off on the
 * half-resolution pass of its 1080p frame. */
static int talk_on_off(const study_context *ctx, const gtao_scene_refs *s, gtao_fast_math_result *r,
                       cluster_mean *change, cluster_mean *codes, gt_error *e)
{
    gtao_talk_frame f;
    if (gtao_talk_frame_render(ctx, s->scene, &s->in.cam, &f, e) != 0)
        return -1;
    const ss_gbuffer *g = &f.half.g;
    size_t n = (size_t)g->width * g->height;
    float *on = malloc(sizeof *on * n), *off = malloc(sizeof *off * n);
    gtao_params p = gtao_scene_params(s, GTAO_PRESET_MEDIUM);
    gtao_talk_radius(f.camera_distance, g, &p);
    int rc = on && off ? on_off(g, p, s->scene, on, off, e) : gt_error_set(e, s->scene, "out of memory");
    if (rc == 0) {
        double mean, max;
        shift_stats(on, off, g->mask, n, &mean, &max);
        r->talk_shift_max = fmax(r->talk_shift_max, max);
        r->talk_width = g->width, r->talk_height = g->height;
        if (cluster_mean_abs_difference(on, off, g->mask, g->width, g->height, CLUSTER_MEAN_SIDE, change) != 0 ||
            cluster_mean_code_changes(on, off, g->mask, g->width, g->height, CLUSTER_MEAN_SIDE, codes) != 0)
            rc = gt_error_set(e, s->scene, "no pixel inside the mask, or out of memory");
    }
    free(on);
    free(off);
    gtao_talk_frame_free(&f);
    return rc;
}

/* (c) over the talk-setting scenes, pooled. */
static int talk_setting(const study_context *ctx, const gtao_scene_refs *refs, gtao_fast_math_result *r, gt_error *e)
{
    cluster_mean change[FAST_MATH_TALK_SCENES], codes[FAST_MATH_TALK_SCENES];
    for (int s = 0; s < r->scene_count && r->talk_scene_count < FAST_MATH_TALK_SCENES; ++s) {
        if (!gtao_talk_scene(ctx, refs[s].scene))
            continue;
        int k = r->talk_scene_count++;
        memcpy(r->talk_scenes[k], refs[s].scene, sizeof r->talk_scenes[k]);
        if (talk_on_off(ctx, &refs[s], r, &change[k], &codes[k], e) != 0)
            return -1;
    }
    r->talk_change = cluster_mean_pool(change, r->talk_scene_count);
    r->talk_codes = cluster_mean_pool(codes, r->talk_scene_count);
    return 0;
}

/* (b): every variant on the replayed horizons, against the exact one. */
static int score_variants(const replay_scene *rs, const gtao_fast_math_result *r, float *ao, float *exact,
                          gtao_fast_math_scene *x, gt_error *e)
{
    const gtao_scene_refs *s = rs->refs;
    size_t n = (size_t)s->width * s->height;
    replay_image(rs, NULL, exact);
    for (int v = 0; v < FAST_ACOS_VARIANTS; ++v) {
        replay_image(rs, v == FAST_ACOS_EXACT ? NULL : &r->poly[v], ao);
        x->rmse_hf[v] = rmse_of(ao, s->hf_ao, s->mask, n);
        x->rmse_3d[v] = rmse_of(ao, s->ref3d, s->mask, n);
        shift_stats(ao, exact, s->mask, n, &x->shift_mean[v], &x->shift_max[v]);
        if (cluster_mean_paired_sq_error(ao, exact, s->hf_ao, s->mask, s->width, s->height, CLUSTER_MEAN_SIDE,
                                       &x->paired_hf[v]) != 0)
            return gt_error_set(e, s->scene, "no pixel inside the mask, or out of memory");
    }
    return 0;
}

/* The mean over scene s's pixels of (refit - hf)^2 - (talk - hf)^2. */
static double heldout_gain(const replay_scene *rs, const gtao_acos_poly *refit, const gtao_acos_poly *talk,
                           float *a, float *b)
{
    const gtao_scene_refs *s = rs->refs;
    replay_image(rs, refit, a);
    replay_image(rs, talk, b);
    cluster_mean m;
    if (cluster_mean_paired_sq_error(a, b, s->hf_ao, s->mask, s->width, s->height, CLUSTER_MEAN_SIDE, &m) != 0)
        return NAN;
    return m.mean;
}

/* The slope fitted to the height-field references (no jackknife). */
static int reference_fit(const study_context *ctx, replay_scene *rs, gtao_fast_math_result *r, gt_error *e)
{
    double p[2] = {r->poly[FAST_ACOS_TALK].slope, r->poly[FAST_ACOS_TALK].constant};
    gt_fit_result res;
    for (int s = 0; s < r->scene_count; ++s)
        rs[s].against_reference = 1;
    int rc = fit_poly(rs, r->scene_count, -1, 1, ctx->threads, p, &res, NULL, e);
    for (int s = 0; s < r->scene_count; ++s)
        rs[s].against_reference = 0;
    r->objective_start[2] = res.initial_cost;
    r->objective_end[2] = res.final_cost;
    r->iterations[2] = res.iterations;
    r->poly[FAST_ACOS_SLOPE_REFERENCE] = poly_of(p);
    r->at_bound[2] = on_bound(p);
    return rc;
}

/* The two refits on all scenes, then each scene left out: jackknife
 * standard errors and held-out gains. */
static int refits(const study_context *ctx, replay_scene *rs, gtao_fast_math_result *r, float *a, float *b,
                  gt_error *e)
{
    const gtao_acos_poly talk = r->poly[FAST_ACOS_TALK];
    int n = r->scene_count;
    double slopes[FAST_MATH_MAX_SCENES], both[2][FAST_MATH_MAX_SCENES], gains[2][FAST_MATH_MAX_SCENES];
    for (int model = 0; model < 2; ++model) {
        double full[2] = {talk.slope, talk.constant};
        gt_fit_result res;
        if (fit_poly(rs, n, -1, model == 0, ctx->threads, full, &res, model == 0 ? &r->slope_ceres_se : NULL, e))
            return -1;
        r->objective_start[model] = res.initial_cost;
        r->objective_end[model] = res.final_cost;
        r->iterations[model] = res.iterations;
        r->poly[model == 0 ? FAST_ACOS_SLOPE : FAST_ACOS_BOTH] = poly_of(full);
        r->at_bound[model] = on_bound(full);
        for (int s = 0; s < n; ++s) { /* one scene (a project's) leaves none to fit: no held-out figure (NaN) */
            double p[2] = {n > 1 ? full[0] : NAN, n > 1 ? full[1] : NAN};
            if (n > 1 && fit_poly(rs, n, s, model == 0, ctx->threads, p, &res, NULL, e) != 0)
                return -1;
            gtao_acos_poly held = poly_of(p);
            slopes[s] = p[0];
            both[0][s] = p[0];
            both[1][s] = p[1];
            gains[model][s] = n > 1 ? heldout_gain(&rs[s], &held, &talk, a, b) : NAN;
            if (model == 0)
                r->scenes[s].heldout_slope_gain = gains[0][s];
            else
                r->scenes[s].heldout_both_gain = gains[1][s];
        }
        if (model == 0)
            r->slope_jackknife_se = jackknife_se(slopes, n);
    }
    if (reference_fit(ctx, rs, r, e) != 0)
        return -1;
    r->both_jackknife_se[0] = jackknife_se(both[0], n);
    r->both_jackknife_se[1] = jackknife_se(both[1], n);
    mean_and_se(gains[0], n, &r->heldout_slope_gain_mean, &r->heldout_slope_gain_se);
    mean_and_se(gains[1], n, &r->heldout_both_gain_mean, &r->heldout_both_gain_se);
    return 0;
}

static void pool(gtao_fast_math_result *r)
{
    cluster_mean parts[FAST_MATH_MAX_SCENES], change[FAST_MATH_MAX_SCENES], codes[FAST_MATH_MAX_SCENES];
    double shift = 0.0;
    r->medium_shift_max = 0.0;
    for (int s = 0; s < r->scene_count; ++s) {
        parts[s] = r->scenes[s].medium_paired_hf;
        change[s] = r->scenes[s].medium_change;
        codes[s] = r->scenes[s].medium_codes;
        shift += r->scenes[s].medium_shift_mean / r->scene_count;
        r->medium_shift_max = fmax(r->medium_shift_max, r->scenes[s].medium_shift_max);
    }
    r->medium_paired_hf = cluster_mean_pool(parts, r->scene_count);
    r->medium_change = cluster_mean_pool(change, r->scene_count);
    r->medium_codes = cluster_mean_pool(codes, r->scene_count);
    r->medium_shift_mean = shift;
}

static double mean_variance(const gtao_scene_refs *s)
{
    double sum = 0.0;
    size_t count = 0;
    for (size_t i = 0; i < (size_t)s->width * s->height; ++i)
        if (s->mask[i] != 0.0f) {
            sum += (double)s->hf_stderr[i] * s->hf_stderr[i];
            ++count;
        }
    return count ? sum / (double)count : 0.0;
}

/* Per scene: (a), and the replay of (b) built. */
static int prepare_scene(const gtao_fast_math_result *r, gtao_scene_refs *refs, replay_scene *rs, gtao_fast_math_scene *x, float *a, float *b, gt_error *e)
{
    if (medium_on_off(refs, a, b, x, e) != 0)
        return -1;
    gtao_params p = gtao_scene_params(refs, GTAO_PRESET_REFERENCE);
    p.slices = r->slices;
    p.steps = r->steps;
    if (build_replay(refs, &p, r->fit_stride, rs) != 0)
        return gt_error_set(e, refs->scene, "out of memory");
    return 0;
}

static void setup(const study_context *ctx, gtao_fast_math_result *r)
{
    const gtao_quality *q = gtao_quality_of(ctx->quality);
    memset(r, 0, sizeof *r);
    r->slices = q->fast_math_slices;
    r->steps = q->fast_math_steps;
    r->fit_stride = q->fast_math_fit_stride;
    r->poly[FAST_ACOS_TALK] = gtao_acos_poly_talk();
    r->poly[FAST_ACOS_TRANSCRIBED] = r->poly[FAST_ACOS_TALK];
    r->poly[FAST_ACOS_TRANSCRIBED].magic = GTAO_FAST_SQRT_MAGIC_AS_TRANSCRIBED;
    r->scene_count = study_scene_count(ctx) < FAST_MATH_MAX_SCENES ? study_scene_count(ctx) : FAST_MATH_MAX_SCENES;
}

/* Loads every scene's references; returns the largest pixel count, or 0 with e. */
static size_t load_scenes(const study_context *ctx, const gtao_shortcuts_request *rq, gtao_scene_refs *refs,
                          gtao_fast_math_result *r, gt_error *e)
{
    size_t most = 0;
    for (int s = 0; s < r->scene_count; ++s) {
        gtao_fast_math_scene *x = &r->scenes[s];
        snprintf(x->scene, sizeof x->scene, "%s", study_scene_at(ctx, s)->label);
        if (gtao_scene_refs_load(rq->ao_references_dir, rq->gtao_dir, x->scene, &refs[s], e) != 0)
            return 0;
        r->hf_mean_variance += mean_variance(&refs[s]) / r->scene_count;
        size_t n = (size_t)refs[s].width * refs[s].height;
        most = n > most ? n : most;
    }
    return most;
}

static int run(const study_context *ctx, gtao_scene_refs *refs, replay_scene *rs, gtao_fast_math_result *r,
               float *a, float *b, gt_error *e)
{
    for (int s = 0; s < r->scene_count; ++s)
        if (prepare_scene(r, &refs[s], &rs[s], &r->scenes[s], a, b, e) != 0)
            return -1;
    if (refits(ctx, rs, r, a, b, e) != 0)
        return -1;
    for (int s = 0; s < r->scene_count; ++s)
        if (score_variants(&rs[s], r, a, b, &r->scenes[s], e) != 0)
            return -1;
    for (int v = 0; v < FAST_ACOS_VARIANTS; ++v)
        r->function_error[v] = function_error(v == FAST_ACOS_EXACT ? NULL : &r->poly[v]);
    pool(r);
    return talk_setting(ctx, refs, r, e);
}

int gtao_fast_math_study(const study_context *ctx, const gtao_shortcuts_request *rq, gtao_fast_math_result *out,
                         gt_error *e)
{
    setup(ctx, out);
    static gtao_scene_refs refs[FAST_MATH_MAX_SCENES];
    replay_scene rs[FAST_MATH_MAX_SCENES];
    memset(refs, 0, sizeof refs);
    memset(rs, 0, sizeof rs);
    size_t pixels = load_scenes(ctx, rq, refs, out, e);
    float *a = pixels ? malloc(sizeof *a * pixels) : NULL, *b = pixels ? malloc(sizeof *b * pixels) : NULL;
    int rc = !pixels ? -1 : a && b ? run(ctx, refs, rs, out, a, b, e) : gt_error_set(e, "gtao", "out of memory");
    for (int s = 0; s < out->scene_count; ++s) {
        free_replay(&rs[s]);
        gtao_scene_refs_free(&refs[s]);
    }
    free(a);
    free(b);
    return rc;
}
