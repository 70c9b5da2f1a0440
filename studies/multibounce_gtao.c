/* "Agnostic to the source of AO" (studies/multibounce.h,
 * multibounce_gtao_study; issue 25, item 5; issue 42): the talk's
 * multi-bounce f on two ground-truth V_d (the 3-D reference's and the
 * height-field reference's), each scored on the light it adds; and, beside
 * it, f on GTAO's V_d against the multi-bounce reference with GTAO's share
 * of the error. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/reference_schema.h"
#include "realtime/gtao.h"
#include "studies/gtao_scene_refs.h"
#include "studies/gbuffer_input.h"
#include "studies/multibounce_parts.h"

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

/* Adds scene k's errors of f on the 3-D reference's V_d and on the height
 * field's `hf`: the change f makes against the truth's (V'_d - V_d of the
 * odd half), and the whole of f(V_d) against V'_d. */
static void accumulate_sources(const multibounce_state *st, int k, const float *hf, agnostic_sums *sums)
{
    const multibounce_model talk = multibounce_model_jimenez2016();
    const image *img = &st->refs[k], *even = &st->halves[k][0], *odd = &st->halves[k][1];
    const float *mask = image_channel_data(img, CH_MASK), *vd = image_channel_data(even, CH_AO);
    const float *vd_odd = image_channel_data(odd, CH_AO);
    const size_t n = image_pixel_count(img);
    for (int a = 0; a < MULTIBOUNCE_STUDY_ALBEDOS; ++a) {
        const double rho = st->plan.settings.albedos[a];
        const float *target = image_channel_data(odd, st->plan.quantities[a].name);
        source_sums *g = &sums->g[k][a];
        for (size_t i = 0; i < n; ++i) {
            if (mask[i] == 0.0f)
                continue;
            double truth_gain = (double)target[i] - vd_odd[i];
            double f3 = gtao_multibounce(&talk, vd[i], rho), fh = gtao_multibounce(&talk, hf[i], rho);
            double e3 = (f3 - vd[i]) - truth_gain, eh = (fh - hf[i]) - truth_gain;
            g->gain_3d += e3 * e3;
            g->gain_hf += eh * eh;
            g->total_3d += (f3 - target[i]) * (f3 - target[i]);
            g->total_hf += (fh - target[i]) * (fh - target[i]);
            g->hf_v_d += ((double)hf[i] - vd[i]) * ((double)hf[i] - vd[i]);
            g->pixels += 1.0;
        }
    }
}

/* The height-field reference of scene k at its camera, accumulated into sums. */
static int run_heightfield(const study_context *ctx, const multibounce_state *st, int k, const char *scene,
                           const camera *cam, int spp, agnostic_sums *sums, gt_error *e)
{
    char dir[2048], path[4096], spec[128];
    if (study_make_dir(ctx, MULTIBOUNCE_HEIGHTFIELD_DIR, dir, sizeof dir, e) != 0)
        return -1;
    snprintf(path, sizeof path, "%s/%s.exr", dir, scene);
    snprintf(spec, sizeof spec, "builtin:%s", scene);
    image hf;
    if (gtao_render_heightfield(ctx, spec, cam, spp, path, &hf, e) != 0)
        return -1;
    const float *ao = image_channel_data(&hf, CH_AO);
    int rc = 0;
    if (!ao || hf.width != st->refs[k].width || hf.height != st->refs[k].height)
        rc = gt_error_set(e, path, "not an AO image of the multi-bounce reference's size");
    else
        accumulate_sources(st, k, ao, sums);
    image_free(&hf);
    return rc;
}

/* GTAO at every preset on scene k's G-buffer, accumulated into sums, and
 * the height-field reference at its camera into sources. */
static int run_scene(const study_context *ctx, const multibounce_state *st, int k, const char *scene, int spp,
                     preset_sums *sums, agnostic_sums *sources, gt_error *e)
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
        rc = run_heightfield(ctx, st, k, scene, &in.cam, spp, sources, e);
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
    const int spp = req->sampling.spp / 2; /* as many as the 3-D reference's even half */
    int rc = 0;
    for (int k = 0; k < MULTIBOUNCE_STUDY_SCENES && rc == 0; ++k)
        rc = run_scene(ctx, st, k, scenes[k], spp, sums, sources, e);
    for (int p = 0; p < MULTIBOUNCE_GTAO_PRESETS && rc == 0; ++p)
        preset_row(&sums[p], p, &out->rows[p]);
    if (rc == 0)
        agnostic_row(sources, spp, &out->agnostic);
    free(sums);
    free(sources);
    return rc;
}
