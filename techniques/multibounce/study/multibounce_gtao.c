/* "Agnostic to the source of AO" (multibounce/multibounce_study.h,
 * multibounce_gtao_study; issue 25, item 5; issue 42): the talk's
 * multi-bounce f on two ground-truth V_d (the 3-D reference's and the
 * height-field multi-bounce reference's), each scored on the light it adds
 * against the truth of its own world; and, beside
 * it, f on GTAO's V_d against the multi-bounce reference with GTAO's share
 * of the error. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/exr_io.h"
#include "core/reference_schema.h"
#include "gtao/gtao.h"
#include "metrics/reference_halves.h"
#include "multibounce/multibounce_parts.h"
#include "raytracer/reference_render.h"
#include "scene/scene_loaders.h"
#include "project/gbuffer_input.h"

/* Squared-error sums of one (scene, albedo) group, per preset. */
typedef struct {
    double gtao_input, reference_input, gtao_v_d;
    double pixels;
} group_sums;

typedef struct {
    group_sums g[MULTIBOUNCE_STUDY_SCENES][MULTIBOUNCE_STUDY_ALBEDOS];
} preset_sums;

/* Squared-error sums of one (scene, albedo) group for the two ground-truth sources. */
typedef struct {
    double gain_3d, gain_hf, total_3d, total_hf, hf_v_d;
    double pixels;
} source_sums;

typedef struct {
    source_sums g[MULTIBOUNCE_STUDY_SCENES][MULTIBOUNCE_STUDY_ALBEDOS];
} agnostic_sums;

/* The preset with an unbounded radius (the reference's), one frame. */
static gtao_params study_params(int preset, int width)
{
    gtao_params p;
    gtao_preset(gtao_preset_names[preset], &p);
    p.radius = 1e6f;
    p.falloff = 0.0f;
    p.max_radius_px = (float)width;
    p.frames = 1;
    return p;
}

/* Adds scene k's squared errors at every albedo for GTAO's `ao`. */
static void accumulate(const multibounce_state *st, int k, const float *ao, preset_sums *sums)
{
    const multibounce_model talk = multibounce_model_jimenez2016();
    const image *img = &st->refs[k], *even = &st->halves[k][0], *odd = &st->halves[k][1];
    const float *mask = image_channel_data(img, CH_MASK), *vd = image_channel_data(even, CH_AO);
    const size_t n = image_pixel_count(img);
    for (int a = 0; a < MULTIBOUNCE_STUDY_ALBEDOS; ++a) {
        const double rho = st->plan.settings.albedos[a];
        const float *target = image_channel_data(odd, st->plan.quantities[a].name);
        group_sums *g = &sums->g[k][a];
        for (size_t i = 0; i < n; ++i) {
            if (mask[i] == 0.0f)
                continue;
            double eg = gtao_multibounce(&talk, ao[i], rho) - target[i];
            double er = gtao_multibounce(&talk, vd[i], rho) - target[i];
            g->gtao_input += eg * eg;
            g->reference_input += er * er;
            g->gtao_v_d += ((double)ao[i] - vd[i]) * ((double)ao[i] - vd[i]);
            g->pixels += 1.0;
        }
    }
}

/* One source's halves: V_d of the even samples feeds f, V_d and V'_d per
 * albedo of the odd samples are its truth. */
typedef struct {
    const float *vd, *vd_odd, *target[MULTIBOUNCE_STUDY_ALBEDOS];
} source_halves;

static source_halves halves_of(const multibounce_state *st, const image halves[2])
{
    source_halves h = {image_channel_data(&halves[0], CH_AO), image_channel_data(&halves[1], CH_AO), {0}};
    for (int a = 0; a < MULTIBOUNCE_STUDY_ALBEDOS; ++a)
        h.target[a] = image_channel_data(&halves[1], st->plan.quantities[a].name);
    return h;
}

/* The error of the change f makes at pixel i, albedo a, against the
 * truth's change V'_d - V_d of the same source; *total: f(V_d) - V'_d. */
static double gain_error(const source_halves *h, int a, size_t i, double rho, double *total)
{
    const multibounce_model talk = multibounce_model_jimenez2016();
    double f = gtao_multibounce(&talk, h->vd[i], rho);
    *total = f - h->target[a][i];
    return (f - h->vd[i]) - ((double)h->target[a][i] - h->vd_odd[i]);
}

/* Adds scene k's errors of f on each ground-truth source, each against the
 * truth of its own world: the 3-D reference's V_d against the 3-D V'_d, the
 * height field's (`hf`, its halves) against the height-field V'_d. */
static void accumulate_sources(const multibounce_state *st, int k, const image hf[2], agnostic_sums *sums)
{
    const source_halves d3 = halves_of(st, st->halves[k]), hh = halves_of(st, hf);
    const float *mask = image_channel_data(&st->refs[k], CH_MASK);
    const size_t n = image_pixel_count(&st->refs[k]);
    for (int a = 0; a < MULTIBOUNCE_STUDY_ALBEDOS; ++a) {
        const double rho = st->plan.settings.albedos[a];
        source_sums *g = &sums->g[k][a];
        for (size_t i = 0; i < n; ++i) {
            if (mask[i] == 0.0f)
                continue;
            double t3, th, e3 = gain_error(&d3, a, i, rho, &t3), eh = gain_error(&hh, a, i, rho, &th);
            g->gain_3d += e3 * e3;
            g->gain_hf += eh * eh;
            g->total_3d += t3 * t3;
            g->total_hf += th * th;
            g->hf_v_d += ((double)hh.vd[i] - d3.vd[i]) * ((double)hh.vd[i] - d3.vd[i]);
            g->pixels += 1.0;
        }
    }
}

/* Whether the height-field reference carries the 3-D reference's channels. */
static int same_channels(const multibounce_state *st, const image halves[2])
{
    const source_halves h = halves_of(st, halves);
    int ok = h.vd && h.vd_odd;
    for (int a = 0; a < MULTIBOUNCE_STUDY_ALBEDOS; ++a)
        ok &= h.target[a] != NULL;
    return ok;
}

/* The height-field multi-bounce reference of scene k at its camera (the 3-D
 * reference's albedos and bounces; the sub-studies' samples: req), written and accumulated
 * into sums. */
static int run_heightfield(const study_context *ctx, const reference_request *req, const multibounce_state *st,
                           int k, const char *name, const camera *cam, agnostic_sums *sums, gt_error *e)
{
    char dir[2048], path[4096], spec[128];
    if (study_make_dir(ctx, MULTIBOUNCE_HEIGHTFIELD_DIR, dir, sizeof dir, e) != 0)
        return -1;
    snprintf(path, sizeof path, "%s/%s.exr", dir, name);
    snprintf(spec, sizeof spec, "builtin:%s", name);
    reference_request hreq = *req;
    hreq.quantity = QUANTITY_HEIGHTFIELD_MULTIBOUNCE;
    scene s;
    if (scene_load(spec, &s, e) != 0)
        return -1;
    image hf, halves[2];
    render_stats stats;
    int rc = reference_render(&s, spec, cam, &hreq, &hf, &stats, e);
    scene_free(&s);
    if (rc != 0)
        return -1;
    rc = exr_write(path, &hf, e);
    if (rc == 0 && hf.width == st->refs[k].width && hf.height == st->refs[k].height)
        rc = reference_halves_split(&hf, path, halves, e);
    else if (rc == 0)
        rc = gt_error_set(e, path, "not of the multi-bounce reference's size");
    image_free(&hf);
    if (rc != 0)
        return -1;
    if (same_channels(st, halves))
        accumulate_sources(st, k, halves, sums);
    else
        rc = gt_error_set(e, path, "not a multi-bounce reference of the study's albedos");
    image_free(&halves[0]);
    image_free(&halves[1]);
    return rc;
}

/* GTAO at every preset on scene k's G-buffer, accumulated into sums, and
 * the height-field reference at its camera into sources. */
static int run_scene(const study_context *ctx, const reference_request *req, const multibounce_state *st, int k,
                     const char *scene, preset_sums *sums, agnostic_sums *sources, gt_error *e)
{
    char dir[2048], path[4096];
    if (study_make_dir(ctx, MULTIBOUNCE_STUDY_DIR, dir, sizeof dir, e) != 0)
        return -1;
    snprintf(path, sizeof path, "%s/%s.exr", dir, scene);
    approx_input in;
    if (approx_load(path, NULL, &in, e) != 0)
        return -1;
    float *ao = malloc(image_pixel_count(&in.img) * sizeof *ao);
    int rc = ao ? 0 : gt_error_set(e, path, "out of memory");
    for (int p = 0; p < MULTIBOUNCE_GTAO_PRESETS && rc == 0; ++p) {
        gtao_params params = study_params(p, in.img.width);
        rc = gtao_render(&in.g, &params, ao, NULL) != 0 ? gt_error_set(e, path, "GTAO: out of memory") : 0;
        if (rc == 0)
            accumulate(st, k, ao, &sums[p]);
    }
    free(ao);
    if (rc == 0)
        rc = run_heightfield(ctx, req, st, k, scene, &in.cam, sources, e);
    approx_input_free(&in);
    return rc;
}

/* Mean squared errors over the groups of every scene but `without` (-1: all). */
static void mean_errors(const preset_sums *s, int without, double *gtao_input, double *reference_input,
                        double *gtao_v_d)
{
    double groups = 0.0;
    *gtao_input = *reference_input = *gtao_v_d = 0.0;
    for (int k = 0; k < MULTIBOUNCE_STUDY_SCENES; ++k)
        for (int a = 0; a < MULTIBOUNCE_STUDY_ALBEDOS && k != without; ++a) {
            const group_sums *g = &s->g[k][a];
            *gtao_input += g->gtao_input / g->pixels;
            *reference_input += g->reference_input / g->pixels;
            *gtao_v_d += g->gtao_v_d / g->pixels;
            groups += 1.0;
        }
    *gtao_input /= groups;
    *reference_input /= groups;
    *gtao_v_d /= groups;
}

/* The row of one preset: its figures on all scenes, and the jackknife over scenes. */
static void preset_row(const preset_sums *s, int preset, multibounce_gtao_row *row)
{
    double g, r, v, share[MULTIBOUNCE_STUDY_SCENES], diff[MULTIBOUNCE_STUDY_SCENES];
    snprintf(row->preset, sizeof row->preset, "%s", gtao_preset_names[preset]);
    mean_errors(s, -1, &g, &r, &v);
    row->rmse_gtao_input = sqrt(g);
    row->rmse_reference_input = sqrt(r);
    row->rmse_gtao_v_d = sqrt(v);
    row->gtao_share = 1.0 - r / g;
    row->difference = row->rmse_gtao_input - row->rmse_reference_input;
    double mean_share = 0.0, mean_diff = 0.0, ss_share = 0.0, ss_diff = 0.0;
    const int n = MULTIBOUNCE_STUDY_SCENES;
    for (int k = 0; k < n; ++k) {
        mean_errors(s, k, &g, &r, &v);
        share[k] = 1.0 - r / g;
        diff[k] = sqrt(g) - sqrt(r);
        mean_share += share[k] / n;
        mean_diff += diff[k] / n;
    }
    for (int k = 0; k < n; ++k) {
        ss_share += (share[k] - mean_share) * (share[k] - mean_share);
        ss_diff += (diff[k] - mean_diff) * (diff[k] - mean_diff);
    }
    row->gtao_share_se = sqrt((n - 1.0) / n * ss_share);
    row->difference_se = sqrt((n - 1.0) / n * ss_diff);
}

/* Root mean over the groups of every scene but `without` (-1: all) of the
 * sum at `offset` of source_sums, per pixel. */
static double source_rms(const agnostic_sums *s, size_t offset, int without)
{
    double sum = 0.0, groups = 0.0;
    for (int k = 0; k < MULTIBOUNCE_STUDY_SCENES; ++k)
        for (int a = 0; a < MULTIBOUNCE_STUDY_ALBEDOS && k != without; ++a) {
            const source_sums *g = &s->g[k][a];
            sum += *(const double *)((const char *)g + offset) / g->pixels;
            groups += 1.0;
        }
    return sqrt(sum / groups);
}

#define SOURCE_SUM(field) offsetof(source_sums, field)

/* The two sources' figures on all scenes, and the jackknife over scenes of their difference. */
static void agnostic_row(const agnostic_sums *s, int spp, multibounce_agnostic *out)
{
    out->spp = spp;
    out->gain_rmse_3d = source_rms(s, SOURCE_SUM(gain_3d), -1);
    out->gain_rmse_hf = source_rms(s, SOURCE_SUM(gain_hf), -1);
    out->difference = out->gain_rmse_hf - out->gain_rmse_3d;
    out->rmse_hf_v_d = source_rms(s, SOURCE_SUM(hf_v_d), -1);
    out->rmse_total_3d = source_rms(s, SOURCE_SUM(total_3d), -1);
    out->rmse_total_hf = source_rms(s, SOURCE_SUM(total_hf), -1);
    const int n = MULTIBOUNCE_STUDY_SCENES;
    double diff[MULTIBOUNCE_STUDY_SCENES], mean = 0.0, ss = 0.0;
    for (int k = 0; k < n; ++k) {
        diff[k] = source_rms(s, SOURCE_SUM(gain_hf), k) - source_rms(s, SOURCE_SUM(gain_3d), k);
        mean += diff[k] / n;
    }
    for (int k = 0; k < n; ++k)
        ss += (diff[k] - mean) * (diff[k] - mean);
    out->difference_se = sqrt((n - 1.0) / n * ss);
}

int multibounce_study_gtao(const study_context *ctx, const reference_request *req, const multibounce_state *st,
                           const char *const *scenes, multibounce_gtao_study *out, gt_error *e)
{
    preset_sums *sums = calloc(MULTIBOUNCE_GTAO_PRESETS, sizeof *sums);
    agnostic_sums *sources = calloc(1, sizeof *sources);
    if (!sums || !sources) {
        free(sums);
        free(sources);
        return gt_error_set(e, "multibounce", "out of memory");
    }
    memset(out, 0, sizeof *out);
    const int spp = req->sampling.spp; /* the height-field references' */
    int rc = 0;
    for (int k = 0; k < MULTIBOUNCE_STUDY_SCENES && rc == 0; ++k)
        rc = run_scene(ctx, req, st, k, scenes[k], sums, sources, e);
    for (int p = 0; p < MULTIBOUNCE_GTAO_PRESETS && rc == 0; ++p)
        preset_row(&sums[p], p, &out->rows[p]);
    if (rc == 0)
        agnostic_row(sources, spp, &out->agnostic);
    free(sums);
    free(sources);
    return rc;
}
