/* GTAO, HBAO and VO against the height-field and 3-D AO references; see
 * gtao_validation.h. */
#include "gtao/gtao_validation.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/files/atomic_file.h"
#include "core/files/exr_io.h"
#include "core/files/image_io.h"
#include "core/progress.h"
#include "core/reference_schema.h"
#include "metrics/flip.h"
#include "metrics/image_error.h"
#include "metrics/noise_corrected.h"
#include "metrics/ssim.h"
#include "gtao/hbao.h"
#include "gtao/volumetric_obscurance.h"
#include "project/scene_list.h"
#include "project/gbuffer_input.h"
#include "scene/builtin_scenes.h"
#include "gtao/gtao_quality.h"
#include "gtao/gtao_scene_refs.h"
#include "gtao/gtao_talk_setting.h"

const int gtao_convergence_steps[GTAO_CONVERGENCE_STEPS] = {2, 4, 8, 16};
const int gtao_convergence_slices[GTAO_CONVERGENCE_SLICES] = {1, 2, 4, 8, 16};

/* No radius limit: the references see the whole height field / scene. */
#define STUDY_RADIUS 1e6f

/* One scene's inputs: its G-buffer and the two references' AO over its mask. */
typedef struct {
    const ss_gbuffer *g;
    const float *hf, *ref3d, *mask;
    float vo_radius; /* VO needs a finite sphere: a quarter of the camera's distance to its target */
    int brute_force_slices; /* the reference preset's slices (the quality table's) */
} scene_data;

/* DSSIM and RMSE of ao against a reference over the mask, and its mean
 * FLIP when flip is not NULL. */
static int compare(const scene_data *d, const float *ao, const float *ref, const char *what, double *dssim,
                   double *rmse, double *flip, gt_error *e)
{
    ssim_result s;
    image_error_stats st;
    flip_result f = {0};
    if (ssim_compute(ao, ref, d->mask, d->g->width, d->g->height, what, NULL, &s, e) != 0 ||
        image_error_compute(ao, ref, d->mask, d->g->width, d->g->height, what, &st, e) != 0 ||
        (flip && flip_grey(ref, ao, d->mask, d->g->width, d->g->height, what, NULL, &f, e) != 0))
        return -1;
    *dssim = s.dssim;
    *rmse = st.rmse;
    if (flip)
        *flip = f.mean;
    return 0;
}

static int score_against_both(const scene_data *d, const float *ao, double ms, ao_variant_row *x, gt_error *e)
{
    x->ms_per_frame = ms;
    if (compare(d, ao, d->hf, x->label, &x->dssim_hf, &x->rmse_hf, NULL, e) != 0)
        return -1;
    return compare(d, ao, d->ref3d, x->label, &x->dssim_3d, &x->rmse_3d, &x->flip_3d, e);
}

/* The GTAO parameters of the study: the preset with no radius limit. */
static gtao_params study_params(int preset, const scene_data *d, int frames)
{
    gtao_params p;
    gtao_preset(gtao_preset_names[preset], &p);
    p.radius = STUDY_RADIUS;
    p.falloff = 0.0f;
    p.max_radius_px = (float)d->g->width;
    p.frames = p.pattern ? frames : 1;
    if (preset == GTAO_PRESET_REFERENCE)
        p.slices = d->brute_force_slices;
    return p;
}

static void variant_label(ao_variant_row *x, int brute_force_slices)
{
    const char *plural = x->frames > 1 ? "s" : "";
    if (x->technique == AO_TECHNIQUE_GTAO && x->preset == GTAO_PRESET_REFERENCE)
        snprintf(x->label, sizeof x->label, "GTAO exact horizons, %d slices", brute_force_slices);
    else if (x->technique == AO_TECHNIQUE_GTAO)
        snprintf(x->label, sizeof x->label, "GTAO %s, %d frame%s", gtao_preset_names[x->preset], x->frames, plural);
    else if (x->technique == AO_TECHNIQUE_HBAO)
        snprintf(x->label, sizeof x->label, "HBAO 8x8, %d frame%s", x->frames, plural);
    else
        snprintf(x->label, sizeof x->label, "VO 4 samples, %d frame%s", x->frames, plural);
}

static void add_variant(gtao_validation_scene *s, ao_technique_kind technique, int preset, int converged,
                        const gtao_quality *q)
{
    int frames = q->converged_frames;
    ao_variant_row *x = &s->variants[s->variant_count++];
    memcpy(x->scene, s->scene, sizeof x->scene);
    x->technique = technique;
    x->preset = preset;
    x->converged = converged;
    x->frames = converged ? frames : 1;
    variant_label(x, q->brute_force_slices);
}

/* The variants of one scene in the report's order: each GTAO preset for one
 * frame and converged, then HBAO and VO. Brute-force GTAO (the reference
 * preset; tests prove it equals the height field) runs q->brute_force_runs
 * times (one frame, or not at all), the baselines q->baseline_runs times
 * (one frame, then converged). */
static void plan_variants(gtao_validation_scene *s, const gtao_quality *q)
{
    for (int preset = 0; preset < GTAO_PRESET_COUNT; ++preset) {
        int runs = preset == GTAO_PRESET_REFERENCE ? q->brute_force_runs : 2;
        for (int converged = 0; converged < runs; ++converged)
            add_variant(s, AO_TECHNIQUE_GTAO, preset, converged, q);
    }
    for (int converged = 0; converged < q->baseline_runs; ++converged) {
        add_variant(s, AO_TECHNIQUE_HBAO, -1, converged, q);
        add_variant(s, AO_TECHNIQUE_VO, -1, converged, q);
    }
}

/* The technique of x into ao. Returns 0 or -1 when out of memory. */
static int render_variant(const scene_data *d, const ao_variant_row *x, float *ao)
{
    if (x->technique == AO_TECHNIQUE_GTAO) {
        gtao_params p = study_params(x->preset, d, x->frames);
        return gtao_render(d->g, &p, ao, NULL);
    }
    if (x->technique == AO_TECHNIQUE_HBAO) {
        hbao_params h = {8, 8, STUDY_RADIUS, (float)d->g->width, 0, 1, 1, x->frames};
        return hbao_render(d->g, &h, ao);
    }
    vo_params o = {d->vo_radius, (float)d->g->width, 1, 1, x->frames};
    return vo_render(d->g, &o, ao);
}

/* Runs and scores every variant of s; `kept` receives GTAO medium, one frame
 * (for the heatmaps). ao is scratch. */
static int run_variants(const scene_data *d, gtao_validation_scene *s, float *ao, float *kept, gt_error *e)
{
    static const char *const names[3] = {"gtao", "hbao", "vo"};
    for (int i = 0; i < s->variant_count; ++i) {
        ao_variant_row *x = &s->variants[i];
        double t0 = seconds_now();
        if (render_variant(d, x, ao) != 0)
            return gt_error_set(e, names[x->technique], "out of memory");
        if (score_against_both(d, ao, 1e3 * (seconds_now() - t0) / x->frames, x, e) != 0)
            return -1;
        if (x->technique == AO_TECHNIQUE_GTAO && x->preset == GTAO_PRESET_MEDIUM && !x->converged)
            memcpy(kept, ao, sizeof *ao * (size_t)d->g->width * d->g->height);
    }
    return 0;
}

const ao_variant_row *gtao_validation_find(const gtao_validation_scene *s, ao_technique_kind technique, int preset,
                                           int converged)
{
    for (int i = 0; i < s->variant_count; ++i) {
        const ao_variant_row *x = &s->variants[i];
        if (x->technique == technique && x->preset == preset && x->converged == converged)
            return x;
    }
    return NULL;
}

/* The squared error of the talk's configuration split into sampling and
 * height-field parts, each without the references' noise. */
static void split_error(gtao_validation_scene *s)
{
    const ao_variant_row *medium = gtao_validation_find(s, AO_TECHNIQUE_GTAO, GTAO_PRESET_MEDIUM, 0);
    const ao_variant_row *ultra = gtao_validation_find(s, AO_TECHNIQUE_GTAO, GTAO_PRESET_ULTRA, 1);
    ao_error_split *x = &s->split;
    if (!(x->valid = medium && ultra))
        return;
    x->sampling_rmse = noise_corrected_rmse(medium->rmse_hf, s->hf_mean_variance);
    x->model_rmse = noise_corrected_rmse(s->hf_vs_3d_rmse, s->hf_mean_variance + s->ref3d_mean_variance);
    x->converged_sampling_rmse = noise_corrected_rmse(ultra->rmse_hf, s->hf_mean_variance);
    const ao_variant_row *exact = gtao_validation_find(s, AO_TECHNIQUE_GTAO, GTAO_PRESET_REFERENCE, 0);
    x->hf_noise_rmse = sqrt(s->hf_mean_variance);
    if ((x->exact_valid = exact != NULL)) {
        x->exact_rmse_hf = exact->rmse_hf;
        x->exact_sampling_rmse = noise_corrected_rmse(exact->rmse_hf, s->hf_mean_variance);
    }
    double sampling = x->sampling_rmse * x->sampling_rmse, model = x->model_rmse * x->model_rmse;
    x->sampling_percent = sampling + model > 0 ? 100.0 * sampling / (sampling + model) : 0.0;
    x->model_percent = sampling + model > 0 ? 100.0 * model / (sampling + model) : 0.0;
}

/* figures/<stem>_<scene>.png: |a - b| over the mask, 0 to 0.25. */
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

/* figures/<stem>_<scene>.png: the AO `ao` as a grey preview (the report's
 * comparison view shows it beside the references and the heatmaps). */
static int preview(const char *figures, const char *stem, const char *scene_name, const scene_data *d,
                   const float *ao, gt_error *e)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s_%s.png", figures, stem, scene_name);
    return image_write_preview(path, &ao, 1, d->g->width, d->g->height, 1.0f, e);
}

static int write_heatmaps(const char *figures, const char *name, const scene_data *d, const float *medium,
                          gt_error *e)
{
    if (preview(figures, "gtao_hf", name, d, d->hf, e) != 0 || preview(figures, "gtao_medium", name, d, medium, e) != 0 ||
        heatmap(figures, "gtao_err_hf_vs_3d", name, d, d->hf, d->ref3d, e) != 0 ||
        heatmap(figures, "gtao_err_medium_vs_hf", name, d, medium, d->hf, e) != 0)
        return -1;
    return heatmap(figures, "gtao_err_medium_vs_3d", name, d, medium, d->ref3d, e);
}

/* The two references of one scene: the 3-D one loaded with its G-buffer,
 * the height-field one rendered (and written to dir). */
static int scene_references(const study_context *ctx, const char *refs_dir, const char *dir, const char *name,
                            const gtao_validation_result *r, approx_input *in, image *hf, gt_error *e)
{
    char ref_path[4096], hf_path[4096];
    snprintf(ref_path, sizeof ref_path, "%s/%s.exr", refs_dir, name);
    snprintf(hf_path, sizeof hf_path, "%s/%s_heightfield.exr", dir, name);
    const char *spec = study_scene_spec(ctx, name);
    if (approx_load(ref_path, NULL, in, e) != 0)
        return -1;
    if (gtao_render_heightfield(ctx, spec, &in->cam, r->heightfield_spp, r->heightfield_noise_budget, hf_path, hf,
                                e) != 0) {
        approx_input_free(in);
        return -1;
    }
    return 0;
}

/* Every variant scored, the height field against the 3-D reference, its
 * noise floor, the heatmaps and the error split. */
static int score_scene(const scene_data *d, const image *hf, const char *figures, gtao_validation_scene *s,
                       gt_error *e)
{
    size_t n = (size_t)d->g->width * d->g->height;
    float *ao = malloc(sizeof *ao * n), *medium = malloc(sizeof *medium * n);
    ssim_result floor;
    int rc = ao && medium ? 0 : gt_error_set(e, s->scene, "out of memory");
    if (rc == 0)
        rc = run_variants(d, s, ao, medium, e) != 0 ||
                     compare(d, d->hf, d->ref3d, s->scene, &s->hf_vs_3d_dssim, &s->hf_vs_3d_rmse, NULL, e) != 0 ||
                     ssim_noise_floor(hf, s->scene, CH_AO, d->mask, &floor, e) != 0 ||
                     write_heatmaps(figures, s->scene, d, medium, e) != 0
                 ? -1
                 : 0;
    if (rc == 0) {
        s->hf_noise_floor_dssim = floor.dssim;
        s->hf_mean_variance = noise_mean_variance(image_channel_data(hf, CH_AO_STDERR), d->mask, n);
        split_error(s);
    }
    free(ao);
    free(medium);
    return rc;
}

/* The claims rows' studies in the talk's setting: the scene's 1080p frame at half resolution. */
static int talk_setting(const study_context *ctx, const char *name, const camera *cam, gtao_talk_result *r,
                        gt_error *e)
{
    double t0 = seconds_now();
    clock_t c0 = clock();
    gtao_talk_frame f;
    if (gtao_talk_frame_render(ctx, name, cam, &f, e) != 0)
        return -1;
    int rc = gtao_shortcuts_talk_scene(name, &f.full.g, &f.half.g, f.camera_distance, r, e);
    gtao_talk_frame_free(&f);
    r->seconds += seconds_now() - t0;
    r->cpu_seconds += (double)(clock() - c0) / CLOCKS_PER_SEC;
    return rc;
}

static int study_scene(const study_context *ctx, const char *refs_dir, const char *dir, const char *figures,
                       gtao_validation_result *r, gtao_validation_scene *s, gt_error *e)
{
    approx_input in;
    image hf;
    if (scene_references(ctx, refs_dir, dir, s->scene, r, &in, &hf, e) != 0)
        return -1;
    const gtao_quality *q = gtao_quality_of(ctx->quality);
    scene_data d = {&in.g, image_channel_data(&hf, CH_AO), image_channel_data(&in.img, CH_AO), in.g.mask,
                    0.25f * v3_length(v3_sub(in.cam.target, in.cam.position)), q->brute_force_slices};
    s->ref3d_mean_variance = noise_mean_variance(image_channel_data(&in.img, CH_AO_STDERR), d.mask,
                                                 image_pixel_count(&in.img));
    plan_variants(s, q);
    int rc = score_scene(&d, &hf, figures, s, e);
    gtao_shortcut_scene view = {s->scene, d.g, d.hf, d.ref3d, s->hf_mean_variance, s->ref3d_mean_variance,
                                STUDY_RADIUS, (float)d.g->width,
                                v3_length(v3_sub(in.cam.target, in.cam.position)), q->half_res_radius_stride, 0, 0,
                                0.0f};
    if (rc == 0)
        rc = gtao_shortcuts_scene(&view, &r->shortcuts, e);
    if (rc == 0 && gtao_talk_scene(ctx, s->scene))
        rc = talk_setting(ctx, s->scene, &in.cam, &r->shortcuts.talk, e);
    image_free(&hf);
    approx_input_free(&in);
    return rc;
}

/* RMSE against both references of brute-force GTAO (regular slices, no
 * pattern, no denoiser) at every slices x steps, into r->convergence. */
static int convergence_rows(const scene_data *d, float *ao, gtao_validation_result *r, gt_error *e)
{
    for (int a = 0; a < GTAO_CONVERGENCE_STEPS; ++a)
        for (int b = 0; b < GTAO_CONVERGENCE_SLICES; ++b) {
            gtao_convergence_row *x = &r->convergence[r->convergence_count++];
            gtao_params p = study_params(GTAO_PRESET_REFERENCE, d, 1);
            x->slices = p.slices = gtao_convergence_slices[b];
            x->steps = p.steps = gtao_convergence_steps[a];
            double unused;
            if (gtao_render(d->g, &p, ao, NULL) != 0)
                return gt_error_set(e, r->convergence_scene, "out of memory");
            if (compare(d, ao, d->hf, r->convergence_scene, &unused, &x->rmse_hf, NULL, e) != 0 ||
                compare(d, ao, d->ref3d, r->convergence_scene, &unused, &x->rmse_3d, NULL, e) != 0)
                return -1;
        }
    return 0;
}

/* The rows as gnuplot data (GTAO_CONVERGENCE_DATA's layout). */
static int write_convergence(const gtao_validation_result *r, const char *path, gt_error *e)
{
    char data[8192];
    size_t len = (size_t)snprintf(data, sizeof data,
                                  "# slices steps_per_side slices*steps rmse_vs_heightfield rmse_vs_3d\n");
    for (int i = 0; i < r->convergence_count && len < sizeof data; ++i) {
        const gtao_convergence_row *x = &r->convergence[i];
        len += (size_t)snprintf(data + len, sizeof data - len, "%d %d %d %.6g %.6g\n", x->slices, x->steps,
                                x->slices * x->steps, x->rmse_hf, x->rmse_3d);
        if ((i + 1) % GTAO_CONVERGENCE_SLICES == 0 && len < sizeof data)
            len += (size_t)snprintf(data + len, sizeof data - len, "\n\n");
    }
    return atomic_write_text(path, data, e);
}

/* The convergence on r->convergence_scene, against the height-field
 * reference this study wrote to dir. */
static int convergence(const char *refs_dir, const char *dir, gtao_validation_result *r, gt_error *e)
{
    char ref_path[4096], hf_path[4096], data_path[4096];
    snprintf(ref_path, sizeof ref_path, "%s/%s.exr", refs_dir, r->convergence_scene);
    snprintf(hf_path, sizeof hf_path, "%s/%s_heightfield.exr", dir, r->convergence_scene);
    snprintf(data_path, sizeof data_path, "%s/%s", dir, GTAO_CONVERGENCE_DATA);
    approx_input in;
    image hf;
    if (approx_load(ref_path, NULL, &in, e) != 0)
        return -1;
    if (exr_read(hf_path, &hf, e) != 0) {
        approx_input_free(&in);
        return -1;
    }
    scene_data d = {&in.g, image_channel_data(&hf, CH_AO), image_channel_data(&in.img, CH_AO), in.g.mask, 1.0f,
                    0 /* each convergence row sets its slices */};
    float *ao = malloc(sizeof *ao * image_pixel_count(&hf));
    int rc = ao ? convergence_rows(&d, ao, r, e) : gt_error_set(e, r->convergence_scene, "out of memory");
    if (rc == 0)
        rc = write_convergence(r, data_path, e);
    free(ao);
    image_free(&hf);
    approx_input_free(&in);
    return rc;
}

/* Appends label to the comma-separated list. */
static void list_append(char *list, size_t size, const char *label)
{
    size_t used = strlen(list);
    snprintf(list + used, size - used, "%s%s", used ? "," : "", label);
}

/* The GTAO fit's split: on the built-in set the talk's, with the
 * procedural family's members held out too; on a project's scenes the
 * first half (rounded up) trains and the rest is held out, and a single
 * scene is both (the held-out score is then in-sample). */
static void fit_split(const study_context *ctx, gtao_validation_result *out)
{
    const int project = study_scenes_from_project(ctx), n = study_scene_count(ctx);
    const int train = !project ? 0 : n > 1 ? (n + 1) / 2 : n;
    snprintf(out->fit_train, sizeof out->fit_train, "%s", project ? "" : GTAO_FIT_DEFAULT_TRAIN);
    snprintf(out->fit_test, sizeof out->fit_test, "%s", project ? "" : GTAO_FIT_DEFAULT_TEST);
    for (int i = project ? 0 : builtin_study_scene_count(); i < n; ++i) {
        const char *label = study_scene_at(ctx, i)->label;
        if (i < train)
            list_append(out->fit_train, sizeof out->fit_train, label);
        else
            list_append(out->fit_test, sizeof out->fit_test, label);
    }
    if (n == 1 && project)
        snprintf(out->fit_test, sizeof out->fit_test, "%s", out->fit_train);
}

int gtao_validation_study(const study_context *ctx, const gtao_validation_request *rq, gtao_validation_result *out,
                          gt_error *e)
{
    char dir[2048], figures[2048];
    if (study_make_dir(ctx, GTAO_VALIDATION_DIR, dir, sizeof dir, e) != 0 ||
        study_make_dir(ctx, "figures", figures, sizeof figures, e) != 0)
        return -1;
    memset(out, 0, sizeof *out);
    snprintf(out->convergence_scene, sizeof out->convergence_scene, "%s",
             study_scenes_from_project(ctx) ? study_scene_at(ctx, 0)->label : GTAO_CONVERGENCE_SCENE);
    out->heightfield_spp = gtao_quality_of(ctx->quality)->heightfield_spp;
    out->heightfield_noise_budget = gtao_quality_of(ctx->quality)->heightfield_noise_budget;
    out->converged_frames = gtao_quality_of(ctx->quality)->converged_frames;
    for (int i = 0; i < study_scene_count(ctx); ++i) {
        if (i == GTAO_VALIDATION_MAX_SCENES)
            return gt_error_set(e, "gtao", "more than %d scenes", GTAO_VALIDATION_MAX_SCENES);
        gtao_validation_scene *s = &out->scenes[out->scene_count++];
        snprintf(s->scene, sizeof s->scene, "%s", study_scene_at(ctx, i)->label);
        if (study_scene(ctx, rq->ao_references_dir, dir, figures, out, s, e) != 0)
            return -1;
    }
    gtao_shortcuts_finish(&out->shortcuts);
    if (convergence(rq->ao_references_dir, dir, out, e) != 0)
        return -1;
    fit_split(ctx, out);
    out->fit_request = (gtao_fit_request){rq->ao_references_dir, out->fit_train, out->fit_test,
                                          GTAO_FIT_DEFAULT_PRESET, GTAO_FIT_DSSIM};
    return gtao_params_study(&out->fit_request, &out->fit, e);
}
