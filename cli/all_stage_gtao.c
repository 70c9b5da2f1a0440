/* `gtlab all` stage: GTAO (each preset, one frame and temporally converged),
 * HBAO and volumetric obscurance scored against the two references of the
 * GTAO talk's methodology at the AO stage's cameras and pixels:
 *  (a) the height-field Monte Carlo reference (rendered here): what any
 *      screen-space technique could know; GTAO is exact for it, so its
 *      distance is the sampling/denoising error;
 *  (b) the 3-D ray-traced AO of the AO stage (ao/<scene>.exr): the distance
 *      adds the height-field assumption's error, which (a) vs (b) measures.
 * Plus heatmaps and a convergence plot of error against slices x steps. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/all_stages.h"
#include "cli/approx_io.h"
#include "cli/fit_gtao_params.h"
#include "core/atomic_file.h"
#include "core/exr_io.h"
#include "core/image_io.h"
#include "core/progress.h"
#include "metrics/image_error.h"
#include "metrics/ssim.h"
#include "raytracer/reference_render.h"
#include "realtime/gtao.h"
#include "realtime/hbao.h"
#include "realtime/volumetric_obscurance.h"
#include "scene/builtin_scenes.h"
#include "core/reference_schema.h"
#include "scene/scene_loaders.h"

enum { FULL_CYCLE = 24 };   /* 6 temporal rotations x 4 temporal offsets */
enum { PREVIEW_FRAMES = 6 }; /* one cycle of the rotations, to keep the preview quick */

typedef struct {
    double dssim_hf, rmse_hf, dssim_3d, rmse_3d, ms;
} score;

typedef struct {
    const ss_gbuffer *g;
    const float *hf, *ref3d, *mask;
    int frames;      /* the temporally converged variants' frames */
    float vo_radius; /* VO needs a finite sphere: a quarter of the camera's distance to its target */
} scene_data;

/* No radius limit: the references see the whole height field / scene. */
#define STAGE_RADIUS 1e6f

/* DSSIM and RMSE of ao against a reference over the mask. */
static int compare(const scene_data *d, const float *ao, const float *ref, const char *what, double *dssim,
                   double *rmse, gt_error *e)
{
    ssim_result s;
    image_error_stats st;
    if (ssim_compute(ao, ref, d->mask, d->g->width, d->g->height, what, NULL, &s, e) != 0 ||
        image_error_compute(ao, ref, d->mask, d->g->width, d->g->height, what, &st, e) != 0)
        return -1;
    *dssim = s.dssim;
    *rmse = st.rmse;
    return 0;
}

static int score_against_both(const scene_data *d, const float *ao, double ms, const char *what, score *out,
                              gt_error *e)
{
    out->ms = ms;
    if (compare(d, ao, d->hf, what, &out->dssim_hf, &out->rmse_hf, e) != 0)
        return -1;
    return compare(d, ao, d->ref3d, what, &out->dssim_3d, &out->rmse_3d, e);
}

/* The GTAO parameters of the stage: the preset with the scene's radius. */
static gtao_params stage_params(const char *preset, const scene_data *d, int frames)
{
    gtao_params p;
    gtao_preset(preset, &p);
    p.radius = STAGE_RADIUS;
    p.falloff = 0.0f;
    p.max_radius_px = (float)d->g->width;
    p.frames = p.pattern ? frames : 1;
    return p;
}

typedef struct {
    char name[48];
    score s;
} variant;

/* Runs every technique variant on one scene; ao receives each in turn and
 * `kept` (if non-NULL) the medium preset, one frame, for the heatmap. */
static int run_variants(const scene_data *d, int preview, variant *v, int *count, float *ao, float *kept,
                        gt_error *e)
{
    *count = 0;
    for (int i = 0; gtao_preset_names[i]; ++i)
        for (int converged = 0; converged <= 1; ++converged) {
            const char *preset = gtao_preset_names[i];
            int reference = strcmp(preset, "reference") == 0;
            if (reference && (converged || preview))
                continue; /* brute force: production only (tests prove it equals the height field) */
            int frames = converged ? d->frames : 1;
            gtao_params p = stage_params(preset, d, frames);
            double t0 = seconds_now();
            if (gtao_render(d->g, &p, ao, NULL) != 0)
                return gt_error_set(e, "gtao", "out of memory");
            variant *x = &v[(*count)++];
            if (reference)
                snprintf(x->name, sizeof x->name, "GTAO reference");
            else
                snprintf(x->name, sizeof x->name, "GTAO %s, %d frame%s", preset, frames, frames > 1 ? "s" : "");
            if (score_against_both(d, ao, 1e3 * (seconds_now() - t0) / frames, x->name, &x->s, e) != 0)
                return -1;
            if (kept && strcmp(preset, "medium") == 0 && !converged)
                memcpy(kept, ao, sizeof *ao * (size_t)d->g->width * d->g->height);
        }
    for (int converged = 0; converged <= !preview; ++converged) { /* baselines converged: production only */
        int frames = converged ? d->frames : 1;
        hbao_params h = {8, 8, STAGE_RADIUS, (float)d->g->width, 0, 1, 1, frames};
        double t0 = seconds_now();
        if (hbao_render(d->g, &h, ao) != 0)
            return gt_error_set(e, "hbao", "out of memory");
        variant *x = &v[(*count)++];
        snprintf(x->name, sizeof x->name, "HBAO 8x8, %d frame%s", frames, converged ? "s" : "");
        if (score_against_both(d, ao, 1e3 * (seconds_now() - t0) / frames, x->name, &x->s, e) != 0)
            return -1;
        vo_params o = {d->vo_radius, (float)d->g->width, 1, 1, frames};
        t0 = seconds_now();
        if (vo_render(d->g, &o, ao) != 0)
            return gt_error_set(e, "vo", "out of memory");
        x = &v[(*count)++];
        snprintf(x->name, sizeof x->name, "VO 4 samples, %d frame%s", frames, converged ? "s" : "");
        if (score_against_both(d, ao, 1e3 * (seconds_now() - t0) / frames, x->name, &x->s, e) != 0)
            return -1;
    }
    return 0;
}

static int heatmap(const char *figures, const char *stem, const char *scene_name, const scene_data *d,
                   const float *a, const float *b, gt_error *e)
{
    size_t n = (size_t)d->g->width * d->g->height;
    float *err = malloc(sizeof *err * n);
    if (!err)
        return gt_error_set(e, stem, "out of memory");
    for (size_t i = 0; i < n; ++i)
        err[i] = fabsf(a[i] - b[i]);
    char path[4096];
    snprintf(path, sizeof path, "%s/%s_%s.png", figures, stem, scene_name);
    int rc = image_write_heatmap(path, err, d->mask, d->g->width, d->g->height, 0.25f, "inferno", e);
    free(err);
    return rc;
}

/* The height-field reference at the AO reference's camera and size. */
static int render_heightfield(all_context *ctx, const char *spec, const camera *cam, int preview, const char *path,
                              image *hf, gt_error *e)
{
    scene s;
    if (scene_load(spec, &s, e) != 0)
        return -1;
    reference_request req = {.quantity = QUANTITY_HEIGHTFIELD_AO,
                             .sampling = {.spp = preview ? 32 : 1024, .seed = 1, .threads = ctx->study.threads},
                             .normals = NORMAL_SHADING, .max_distance = INFINITY};
    render_stats stats;
    int rc = reference_render(&s, spec, cam, &req, hf, &stats, e);
    scene_free(&s);
    if (rc == 0 && (rc = exr_write(path, hf, e)) != 0)
        image_free(hf);
    return rc;
}

static void add_rows(all_context *ctx, const char *scene_name, const variant *v, int count, cJSON *list)
{
    for (int i = 0; i < count; ++i) {
        char cells[6][64];
        snprintf(cells[0], 64, "%.47s", v[i].name);
        snprintf(cells[1], 64, "%.4f", v[i].s.dssim_hf);
        snprintf(cells[2], 64, "%.4f", v[i].s.rmse_hf);
        snprintf(cells[3], 64, "%.4f", v[i].s.dssim_3d);
        snprintf(cells[4], 64, "%.4f", v[i].s.rmse_3d);
        snprintf(cells[5], 64, "%.2f", v[i].s.ms);
        const char *row[6] = {cells[0], cells[1], cells[2], cells[3], cells[4], cells[5]};
        report_table_row(ctx->doc, row);
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "scene", scene_name);
        cJSON_AddStringToObject(o, "technique", v[i].name);
        cJSON_AddNumberToObject(o, "dssim_heightfield", v[i].s.dssim_hf);
        cJSON_AddNumberToObject(o, "rmse_heightfield", v[i].s.rmse_hf);
        cJSON_AddNumberToObject(o, "dssim_3d", v[i].s.dssim_3d);
        cJSON_AddNumberToObject(o, "rmse_3d", v[i].s.rmse_3d);
        cJSON_AddNumberToObject(o, "ms_per_frame", v[i].s.ms);
        cJSON_AddItemToArray(list, o);
    }
}

/* Where the error of the talk's configuration comes from, in words. */
/* RMSE against a noisy reference, less the reference's own noise: the
 * expected squared difference is the true one plus the mean variance. */
static double denoised_rmse(double rmse, double mean_variance) { return sqrt(fmax(rmse * rmse - mean_variance, 0.0)); }

/* A noise-corrected RMSE, or the plain fact that it is within the noise. */
static void noise_corrected_text(double rmse, char *text, size_t size)
{
    if (rmse > 0.0)
        snprintf(text, size, "%.4f", rmse);
    else
        snprintf(text, size, "below the references' noise");
}

static void add_statement(all_context *ctx, const char *scene_name, const variant *v, int count, double hf_vs_3d_rmse,
                          double hf_vs_3d_dssim, double hf_floor, double hf_variance, double ref_variance)
{
    const variant *medium = NULL, *converged = NULL;
    for (int i = 0; i < count; ++i) {
        if (strcmp(v[i].name, "GTAO medium, 1 frame") == 0)
            medium = &v[i];
        if (strncmp(v[i].name, "GTAO ultra, ", 12) == 0 && strcmp(v[i].name, "GTAO ultra, 1 frame") != 0)
            converged = &v[i];
    }
    if (!medium || !converged)
        return;
    double sampling_rmse = denoised_rmse(medium->s.rmse_hf, hf_variance);
    double model_rmse = denoised_rmse(hf_vs_3d_rmse, hf_variance + ref_variance);
    double sampling = sampling_rmse * sampling_rmse, model = model_rmse * model_rmse;
    char model_text[64], sampling_text[64], converged_text[64];
    noise_corrected_text(model_rmse, model_text, sizeof model_text);
    noise_corrected_text(sampling_rmse, sampling_text, sizeof sampling_text);
    noise_corrected_text(denoised_rmse(converged->s.rmse_hf, hf_variance), converged_text, sizeof converged_text);
    report_paragraph(ctx->doc,
                     "%s: the height-field assumption alone (height-field reference vs 3-D reference) costs RMSE "
                     "%.4f (%s once both references' Monte Carlo noise is taken out; DSSIM %.4f, the height-field "
                     "reference's own noise floor being DSSIM %.4f). GTAO in the talk's configuration (medium, one "
                     "frame) is RMSE %.4f from the height-field reference (%s without its noise: sampling and "
                     "denoising) and %.4f from the 3-D reference. In squared error, %.0f%% of the two parts is "
                     "sampling/denoising and %.0f%% the height-field assumption. Converged (%s), the sampling "
                     "part falls to RMSE %.4f (%s without the reference's noise).",
                     scene_name, hf_vs_3d_rmse, model_text, hf_vs_3d_dssim, hf_floor, medium->s.rmse_hf, sampling_text,
                     medium->s.rmse_3d, sampling + model > 0 ? 100.0 * sampling / (sampling + model) : 0.0,
                     sampling + model > 0 ? 100.0 * model / (sampling + model) : 0.0, converged->name,
                     converged->s.rmse_hf, converged_text);
}

/* Mean of ao.V.stderr^2 over the mask: the reference's noise in RMSE^2. */
static double mean_variance(const image *ref, const float *mask)
{
    const float *se = image_channel_data(ref, CH_AO_STDERR);
    double sum = 0;
    size_t count = 0;
    for (size_t i = 0; se && i < image_pixel_count(ref); ++i)
        if (mask[i] != 0.0f) {
            sum += (double)se[i] * se[i];
            ++count;
        }
    return count ? sum / count : 0.0;
}

static int score_scene(all_context *ctx, const builtin_scene *b, const char *dir, const char *figures,
                       cJSON *list, gt_error *e)
{
    char ref_path[4096], hf_path[4096], spec[128];
    snprintf(ref_path, sizeof ref_path, "%s/ao/%s.exr", ctx->study.output_dir, b->name);
    snprintf(hf_path, sizeof hf_path, "%s/%s_heightfield.exr", dir, b->name);
    snprintf(spec, sizeof spec, "builtin:%s", b->name);
    int preview = ctx->study.quality == QUALITY_PREVIEW;
    approx_input in;
    if (approx_load(ref_path, NULL, &in, e) != 0)
        return -1;
    image hf;
    if (render_heightfield(ctx, spec, &in.cam, preview, hf_path, &hf, e) != 0) {
        approx_input_free(&in);
        return -1;
    }
    size_t n = image_pixel_count(&in.img);
    scene_data d = {&in.g, image_channel_data(&hf, CH_AO), image_channel_data(&in.img, CH_AO), in.g.mask,
                    preview ? PREVIEW_FRAMES : FULL_CYCLE, 0.25f * v3_length(v3_sub(in.cam.target, in.cam.position))};
    float *ao = malloc(sizeof *ao * n), *medium = malloc(sizeof *medium * n);
    variant v[32];
    int count = 0, rc = -1;
    double hf_rmse = 0, hf_dssim = 0;
    ssim_result floor;
    if (!ao || !medium)
        gt_error_set(e, spec, "out of memory");
    else if (run_variants(&d, preview, v, &count, ao, medium, e) == 0 &&
             compare(&d, d.hf, d.ref3d, spec, &hf_dssim, &hf_rmse, e) == 0 &&
             ssim_noise_floor(&hf, hf_path, CH_AO, d.mask, &floor, e) == 0 &&
             heatmap(figures, "gtao_err_hf_vs_3d", b->name, &d, d.hf, d.ref3d, e) == 0 &&
             heatmap(figures, "gtao_err_medium_vs_hf", b->name, &d, medium, d.hf, e) == 0 &&
             heatmap(figures, "gtao_err_medium_vs_3d", b->name, &d, medium, d.ref3d, e) == 0) {
        report_heading(ctx->doc, 3, b->name);
        static const char *const headers[6] = {"technique", "DSSIM vs height field", "RMSE vs height field",
                                               "DSSIM vs 3-D", "RMSE vs 3-D", "ms per frame"};
        report_table_begin(ctx->doc, 6, headers);
        add_rows(ctx, b->name, v, count, list);
        report_table_end(ctx->doc);
        add_statement(ctx, b->name, v, count, hf_rmse, hf_dssim, floor.dssim, mean_variance(&hf, d.mask),
                      mean_variance(&in.img, d.mask));
        char paths[3][256], captions[3][128];
        const char *stems[3] = {"gtao_err_hf_vs_3d", "gtao_err_medium_vs_hf", "gtao_err_medium_vs_3d"};
        const char *what[3] = {"height-field vs 3-D reference", "GTAO medium (1 frame) vs height field",
                               "GTAO medium (1 frame) vs 3-D"};
        const char *p[3], *c[3];
        for (int k = 0; k < 3; ++k) {
            snprintf(paths[k], sizeof paths[k], "figures/%s_%s.png", stems[k], b->name);
            snprintf(captions[k], sizeof captions[k], "%s: |error| of %s (0 to 0.25)", b->name, what[k]);
            p[k] = paths[k];
            c[k] = captions[k];
        }
        report_figures(ctx->doc, 3, p, c);
        rc = 0;
    }
    free(ao);
    free(medium);
    image_free(&hf);
    approx_input_free(&in);
    return rc;
}

/* RMSE against the height-field reference of regular slices x steps (no
 * pattern, no denoiser) on one scene, plotted with gnuplot. */
static int convergence_plot(all_context *ctx, const char *dir, const char *figures, gt_error *e)
{
    const char *name = "boxes";
    char ref_path[4096], hf_path[4096], data_path[4096], script_path[4096], png_path[4096];
    snprintf(ref_path, sizeof ref_path, "%s/ao/%s.exr", ctx->study.output_dir, name);
    snprintf(hf_path, sizeof hf_path, "%s/%s_heightfield.exr", dir, name);
    snprintf(data_path, sizeof data_path, "%s/gtao_convergence.dat", dir);
    snprintf(script_path, sizeof script_path, "%s/gtao_convergence.gp", dir);
    snprintf(png_path, sizeof png_path, "%s/gtao_convergence.png", figures);
    approx_input in;
    image hf;
    if (approx_load(ref_path, NULL, &in, e) != 0)
        return -1;
    if (exr_read(hf_path, &hf, e) != 0) {
        approx_input_free(&in);
        return -1;
    }
    scene_data d = {&in.g, image_channel_data(&hf, CH_AO), image_channel_data(&in.img, CH_AO), in.g.mask, 1, 1.0f};
    float *ao = malloc(sizeof *ao * image_pixel_count(&hf));
    static const int steps[4] = {2, 4, 8, 16}, slices[5] = {1, 2, 4, 8, 16};
    char *data = malloc(8192);
    size_t len = 0;
    int rc = ao && data ? 0 : gt_error_set(e, name, "out of memory");
    if (data)
        len += (size_t)snprintf(data, 8192, "# slices steps_per_side slices*steps rmse_vs_heightfield rmse_vs_3d\n");
    for (int a = 0; a < 4 && rc == 0; ++a) {
        for (int b = 0; b < 5 && rc == 0; ++b) {
            gtao_params p = stage_params("reference", &d, 1);
            p.slices = slices[b];
            p.steps = steps[a];
            gtao_render(d.g, &p, ao, NULL);
            double dh = 0, rh = 0, d3 = 0, r3 = 0;
            rc = compare(&d, ao, d.hf, name, &dh, &rh, e) || compare(&d, ao, d.ref3d, name, &d3, &r3, e) ? -1 : 0;
            len += (size_t)snprintf(data + len, 8192 - len, "%d %d %d %.6g %.6g\n", slices[b], steps[a],
                                    slices[b] * steps[a], rh, r3);
        }
        len += (size_t)snprintf(data + len, 8192 - len, "\n\n");
    }
    if (rc == 0)
        rc = atomic_write_text(data_path, data, e);
    char script[16384];
    snprintf(script, sizeof script,
             "set terminal pngcairo size 800,500\nset output '%s'\nset logscale xy\n"
             "set xlabel 'slices x samples per side'\nset ylabel 'RMSE'\n"
             "set title 'GTAO on %s: regular slices, no denoiser'\nset key outside\n"
             "plot for [i=0:3] '%s' index i using 3:4 with linespoints title sprintf('vs height field, %%d steps', 2**(i+1)), "
             "for [i=0:3] '%s' index i using 3:5 with lines dashtype 2 title sprintf('vs 3-D, %%d steps', 2**(i+1))\n",
             png_path, name, data_path, data_path);
    if (rc == 0)
        rc = atomic_write_text(script_path, script, e);
    if (rc == 0) {
        char command[4200];
        snprintf(command, sizeof command, "gnuplot '%s'", script_path);
        if (system(command) != 0)
            rc = gt_error_set(e, script_path, "gnuplot failed (is gnuplot-nox installed?)");
    }
    if (rc == 0) {
        const char *p[1] = {"figures/gtao_convergence.png"}, *c[1] = {"GTAO error against slices x samples (boxes)"};
        report_paragraph(ctx->doc, "Convergence of brute-force GTAO on boxes: RMSE against the height-field "
                                   "reference (solid) and the 3-D reference (dashed). Data: gtao/gtao_convergence.dat.");
        report_figures(ctx->doc, 1, p, c);
    }
    free(ao);
    free(data);
    image_free(&hf);
    approx_input_free(&in);
    return rc;
}

/* Issue 4's auto-tune on the AO stage's references: `gtlab fit gtao-params`
 * with its defaults (DSSIM objective, high preset, trained on boxes, corner
 * and cornell, held out menger and sphere-on-plane). */
static int parameter_fit(all_context *ctx, const char *dir, cJSON *json, gt_error *e)
{
    char refs[2048], path[2300];
    snprintf(refs, sizeof refs, "%s/ao", ctx->study.output_dir);
    gtao_fit_request rq = {refs, "boxes,corner,cornell", "menger,sphere-on-plane", "high", GTAO_FIT_DSSIM};
    static gtao_fit_result r;
    if (gtao_params_fit(&rq, &r, e) != 0)
        return -1;
    cJSON *fit = gtao_fit_json(&rq, &r);
    char *text = cJSON_Print(fit);
    snprintf(path, sizeof path, "%s/params_fit.json", dir);
    int rc = text ? atomic_write_text(path, text, e) : gt_error_set(e, path, "out of memory");
    free(text);
    cJSON_AddItemToObject(json, "parameter_fit", fit);
    if (rc != 0)
        return -1;
    report_heading(ctx->doc, 3, "Parameters tuned to the 3-D references");
    report_paragraph(ctx->doc,
                     "'gtlab fit gtao-params --refs ao' (Ceres, DSSIM objective, %s preset, %d iterations%s): radius "
                     "%.3f +- %.3f of the camera's distance to its target (start %.2f), falloff %.3f +- %.3f (start "
                     "%.2f), thickness %.3f +- %.3f (start %.2f); standard errors treat pixels as independent and "
                     "are optimistic. Fitted on boxes, corner and cornell; menger and sphere-on-plane are held out.",
                     rq.preset, r.iterations, r.converged ? "" : ", not converged", r.value[0], r.se[0], r.start[0],
                     r.value[1], r.se[1], r.start[1], r.value[2], r.se[2], r.start[2]);
    static const char *const headers[6] = {"scene", "role", "DSSIM before", "DSSIM after", "RMSE before",
                                           "RMSE after"};
    report_table_begin(ctx->doc, 6, headers);
    int better = 0, held_out = 0;
    for (int i = 0; i < r.score_count; ++i) {
        const gtao_fit_score *x = &r.scores[i];
        char cells[4][32];
        snprintf(cells[0], 32, "%.4f", x->dssim_before);
        snprintf(cells[1], 32, "%.4f", x->dssim_after);
        snprintf(cells[2], 32, "%.4f", x->rmse_before);
        snprintf(cells[3], 32, "%.4f", x->rmse_after);
        const char *row[6] = {x->scene, x->held_out ? "held out" : "training", cells[0], cells[1], cells[2], cells[3]};
        report_table_row(ctx->doc, row);
        held_out += x->held_out;
        better += x->held_out && x->dssim_after < x->dssim_before;
    }
    report_table_end(ctx->doc);
    report_finding(ctx->doc, "GTAO auto-tune",
                   "Tuning GTAO's radius, falloff and thickness by DSSIM on three scenes lowers DSSIM on %d of the %d "
                   "held-out scenes (radius %.2f of the camera distance, falloff %.2f, thickness %.2f).",
                   better, held_out, r.value[0], r.value[1], r.value[2]);
    return 0;
}

int all_stage_gtao(all_context *ctx, gt_error *e)
{
    char dir[2048], figures[2048];
    if (study_make_dir(&ctx->study, "gtao", dir, sizeof dir, e) != 0 || study_make_dir(&ctx->study, "figures", figures, sizeof figures, e))
        return -1;
    report_heading(ctx->doc, 2, "GTAO, HBAO and volumetric obscurance against two references");
    report_paragraph(ctx->doc,
                     "Each technique runs on the G-buffer of the AO references (same camera, same pixels) with no "
                     "radius limit (the references have none; the screen radius is the image width, no falloff), "
                     "VO with a sphere of a quarter of the camera's distance to its target. Scores are against (a) the height-field Monte Carlo reference (rays "
                     "blocked only by the depth buffer taken as a height field of infinite thickness; %d samples "
                     "per pixel), which GTAO computes exactly given enough slices and samples (tested), so the "
                     "distance to it is sampling and denoising error; and (b) the 3-D ray-traced reference, which "
                     "adds the height-field assumption's error. 'N frames' is the temporal accumulation over N frames "
                     "of the talk's pattern with a static camera (24 is its full cycle; the preview stops at 6); ms "
                     "are per frame on this machine, shared with other work. Brute-force GTAO (reference preset) "
                     "and the baselines' converged runs are scored at production quality only.",
                     ctx->study.quality == QUALITY_PREVIEW ? 32 : 1024);
    cJSON *list = cJSON_AddArrayToObject(ctx->summary, "gtao");
    int rc = 0;
    for (int i = 0; i < builtin_scene_count() && rc == 0; ++i)
        rc = score_scene(ctx, builtin_scene_at(i), dir, figures, list, e);
    if (rc == 0)
        rc = convergence_plot(ctx, dir, figures, e);
    if (rc == 0)
        rc = parameter_fit(ctx, dir, cJSON_AddObjectToObject(ctx->summary, "gtao_parameter_fit"), e);
    return rc;
}
