#include "multibounce/multibounce_study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/exr_io.h"
#include "core/reference_schema.h"
#include "metrics/image_error.h"
#include "metrics/noise_corrected.h"
#include "metrics/reference_halves.h"
#include "multibounce/multibounce_parts.h"
#include "multibounce/multibounce_quality.h"
#include "multibounce/multibounce_quantity.h"
#include "multibounce/multibounce_throughput.h"
#include "scene/scene_loaders.h"

/* The plane is left out: V_d = V'_d = 1 everywhere, nothing to fit. */
static const char *const kScenes[MULTIBOUNCE_STUDY_SCENES] = {"sphere-on-plane", "corner", "menger", "boxes",
                                                              "cornell"};
/* The talk used seven albedos from 0.1 to 0.9 without listing them; denser
 * at the low albedos it calls the most common in nature. */
static const float kAlbedos[MULTIBOUNCE_STUDY_ALBEDOS] = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.7f, 0.9f};

/* ---- References ------------------------------------------------------------------------ */

/* The study's request, its settings in *mb. */
static reference_request request(const study_context *ctx, multibounce_render_settings *mb)
{
    const multibounce_quality *q = multibounce_quality_of(ctx->quality);
    *mb = (multibounce_render_settings){{QUANTITY_MULTIBOUNCE},
                                        {.albedo_count = MULTIBOUNCE_STUDY_ALBEDOS, .bounces = 4}};
    memcpy(mb->multibounce.albedos, kAlbedos, sizeof kAlbedos);
    return (reference_request){.quantity = QUANTITY_MULTIBOUNCE,
                               .sampling = {.spp = q->reference_spp, .seed = 1, .target_stderr = q->noise_budget,
                                            .threads = ctx->threads},
                               .normals = NORMAL_SHADING,
                               .settings = &mb->header};
}

int multibounce_reference_noise_variance(const image *ref, const multibounce_plan *plan, double *variance,
                                         size_t *covered, gt_error *e)
{
    const float *mask = image_channel_data(ref, CH_MASK);
    double sum = 0.0;
    int channels = 0;
    for (int q = 0; q < plan->quantity_count; ++q) {
        const char *name = plan->quantities[q].name;
        if (strcmp(name, CH_AO) == 0)
            continue; /* V_d: the fit's input, not what it is scored against */
        const float *stderr_plane = schema_stderr_data(ref, name);
        if (!stderr_plane)
            return gt_error_set(e, name, "the multi-bounce reference has no standard error of this channel");
        sum += noise_mean_variance(stderr_plane, mask, image_pixel_count(ref));
        ++channels;
    }
    *variance = channels ? sum / channels : 0.0;
    if (covered) {
        *covered = 0;
        for (size_t i = 0; i < image_pixel_count(ref); ++i)
            *covered += (size_t)metrics_in_mask(mask, i);
    }
    return 0;
}

/* Scene k rendered at its default camera into st->refs[k]. */
static int render_scene(const study_context *ctx, const reference_request *req, int k, const char *spec,
                        multibounce_state *st, camera *cam, render_stats *stats, gt_error *e)
{
    scene s;
    if (scene_load(spec, &s, e) != 0)
        return -1;
    int size = multibounce_quality_of(ctx->quality)->image_width;
    int rc = scene_choose_camera(&s, NULL, size, 0, cam, e);
    if (rc == 0)
        rc = reference_render(&s, spec, cam, req, &st->refs[k], stats, e);
    scene_free(&s);
    if (rc == 0)
        st->rendered[k] = 1;
    return rc;
}

/* Renders, writes and splits scene k's reference, and adds its samples to the data. */
static int study_reference(const study_context *ctx, const reference_request *req, int k, const char *dir,
                           multibounce_state *st, multibounce_render_row *row, gt_error *e)
{
    char spec[128], path[4096];
    snprintf(spec, sizeof spec, "builtin:%s", kScenes[k]);
    camera cam;
    render_stats stats;
    if (render_scene(ctx, req, k, spec, st, &cam, &stats, e) != 0)
        return -1;
    snprintf(row->scene, sizeof row->scene, "%s", kScenes[k]);
    row->seconds = stats.seconds;
    row->paths = stats.samples;
    row->rays = stats.rays;
    double variance;
    size_t covered;
    if (multibounce_reference_noise_variance(&st->refs[k], &st->plan, &variance, &covered, e) != 0)
        return -1;
    row->noise_rmse = sqrt(variance);
    row->mean_spp = covered ? (double)stats.samples / (double)covered : 0.0;
    snprintf(path, sizeof path, "%s/%s.exr", dir, kScenes[k]);
    if (exr_write(path, &st->refs[k], e) != 0)
        return -1;
    snprintf(path, sizeof path, "%s/%s.camera.json", dir, kScenes[k]);
    if (camera_write_json(path, &cam, e) != 0 || reference_halves_split(&st->refs[k], spec, st->halves[k], e) != 0)
        return -1;
    st->split[k] = 1;
    return multibounce_data_add_image(&st->data, &st->refs[k], spec, e);
}

static int study_references(const study_context *ctx, const reference_request *req, multibounce_state *st,
                            multibounce_study_result *out, gt_error *e)
{
    char dir[2048];
    if (study_make_dir(ctx, MULTIBOUNCE_STUDY_DIR, dir, sizeof dir, e) != 0)
        return -1;
    for (int k = 0; k < MULTIBOUNCE_STUDY_SCENES; ++k) {
        multibounce_render_row *r = &out->renders[k];
        if (study_reference(ctx, req, k, dir, st, r, e) != 0)
            return -1;
        out->total_seconds += r->seconds;
        out->total_paths += (double)r->paths;
        out->total_rays += (double)r->rays;
        out->mean_spp += r->mean_spp / MULTIBOUNCE_STUDY_SCENES;
        out->noise_rmse += r->noise_rmse * r->noise_rmse / MULTIBOUNCE_STUDY_SCENES;
    }
    out->noise_rmse = sqrt(out->noise_rmse);
    out->width = st->refs[0].width;
    out->height = st->refs[0].height;
    return 0;
}

/* ---- The fit ------------------------------------------------------------------------------ */

/* `gtlab fit multibounce` on the references: the analysis and fits/multibounce.*. */
static int run_fit(const study_context *ctx, multibounce_state *st, gt_error *e)
{
    char fits[2048], json[4096], header[4096], hlsl[4096], glsl[4096];
    if (study_make_dir(ctx, "fits", fits, sizeof fits, e) != 0)
        return -1;
    snprintf(json, sizeof json, "%s/multibounce.json", fits);
    snprintf(header, sizeof header, "%s/multibounce.h", fits);
    snprintf(hlsl, sizeof hlsl, "%s/multibounce.hlsl", fits);
    snprintf(glsl, sizeof glsl, "%s/multibounce.glsl", fits);
    char command[64];
    snprintf(command, sizeof command, "gtlab all --quality %s", study_quality_name(ctx->quality));
    multibounce_data_weigh(&st->data);
    if (multibounce_analyse(&st->data, st->analysis, e) != 0)
        return -1;
    return multibounce_write_outputs(&st->data, st->analysis,
                                     command, json, header, hlsl, glsl, e);
}

/* ---- Performance ------------------------------------------------------------------------ */

/* A short `gtlab bench multibounce` on one scene, and the fit's own time. */
static int measure_performance(const study_context *ctx, const reference_request *req, const multibounce_state *st,
                               multibounce_performance *p, gt_error *e)
{
    *p = (multibounce_performance){.scene = "builtin:menger", .width = 96, .height = 96,
                                   .spp = multibounce_quality_of(ctx->quality)->bench_spp,
                                   .albedos = multibounce_settings_of(req)->albedo_count,
                                   .channels = multibounce_settings_of(req)->albedo_count + 1};
    scene s;
    if (scene_load(p->scene, &s, e) != 0)
        return -1;
    camera cam;
    multibounce_benchmark b;
    int rc = scene_choose_camera(&s, NULL, p->width, p->height, &cam, e);
    if (rc == 0)
        rc = multibounce_benchmark_run(&s, &cam, multibounce_settings_of(req), p->spp, ctx->threads, 1, &b, e);
    scene_free(&s);
    if (rc != 0)
        return -1;
    p->threads = b.threads;
    p->paths_per_s_1_thread = b.paths_per_s[0];
    p->rays_per_s_1_thread = b.rays_per_s[0];
    p->raw_intersect1_rays_per_s_1_thread = b.raw_intersect1[0];
    p->loop_to_raw_ratio = b.rays_per_s[0] / b.raw_intersect1[0];
    p->paths_per_s_threads = b.paths_per_s[1];
    p->one_pass_seconds = b.seconds_one_pass;
    p->separate_renders_seconds = b.seconds_separate;
    p->one_pass_speedup = b.seconds_separate / b.seconds_one_pass;
    p->fit_samples = st->data.count;
    p->fit_block = MBFIT_DEFAULT_BLOCK;
    p->joint_fit_solve_seconds = st->analysis->joint[MB_JOINT_LINEAR].solver.seconds;
    return 0;
}

/* ---- The study ---------------------------------------------------------------------------- */

static void free_state(multibounce_state *st)
{
    for (int k = 0; k < MULTIBOUNCE_STUDY_SCENES; ++k) {
        if (st->rendered[k])
            image_free(&st->refs[k]);
        if (st->split[k]) {
            image_free(&st->halves[k][0]);
            image_free(&st->halves[k][1]);
        }
    }
    multibounce_data_free(&st->data);
    free(st->analysis);
    free(st);
}

/* The sub-studies' request: the references', at the quality table's fixed
 * substudy_spp without a noise budget. */
static reference_request substudy_request(const study_context *ctx, const reference_request *req)
{
    reference_request sub = *req;
    sub.sampling.spp = multibounce_quality_of(ctx->quality)->substudy_spp;
    sub.sampling.target_stderr = 0.0;
    return sub;
}

/* Everything after the references: fit, rows, plot data, validation, performance. */
static int study_fit(const study_context *ctx, const reference_request *req, multibounce_state *st,
                     multibounce_study_result *out, gt_error *e)
{
    const reference_request sub = substudy_request(ctx, req);
    out->substudy_spp = sub.sampling.spp;
    char figures[2048];
    if (run_fit(ctx, st, e) != 0)
        return -1;
    multibounce_study_fit_rows(&st->data, st->analysis, out);
    if (study_make_dir(ctx, "figures", figures, sizeof figures, e) != 0 ||
        multibounce_write_plot_data(&st->data, st->analysis, figures, e) != 0 ||
        multibounce_validate(st, kScenes, kAlbedos, out, e) != 0 ||
        multibounce_study_clamp(&st->data, st->analysis, &out->clamp, e) != 0 ||
        multibounce_study_bounces(ctx, &sub, st, kScenes, &out->bounce_counts, e) != 0 ||
        multibounce_study_gtao(ctx, &sub, st, kScenes, &out->gtao_input, e) != 0 ||
        multibounce_study_contrast(ctx, &sub, st, kScenes, kAlbedos, &out->contrast, e) != 0 ||
        multibounce_study_colour(ctx, &sub, &out->colour, e) != 0)
        return -1;
    return measure_performance(ctx, req, st, &out->performance, e);
}

int multibounce_study(const study_context *ctx, multibounce_study_result *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    multibounce_state *st = calloc(1, sizeof *st);
    if (!st || !(st->analysis = malloc(sizeof *st->analysis))) {
        free(st);
        return gt_error_set(e, "multibounce", "out of memory");
    }
    multibounce_data_init(&st->data);
    multibounce_render_settings mb;
    const reference_request req = request(ctx, &mb);
    out->bounces = mb.multibounce.bounces;
    out->spp = req.sampling.spp;
    out->noise_budget = req.sampling.target_stderr;
    memcpy(out->albedo_values, kAlbedos, sizeof kAlbedos);
    int rc = multibounce_plan_init(&st->plan, &mb.multibounce, req.normals, e);
    if (rc == 0)
        rc = study_references(ctx, &req, st, out, e);
    if (rc == 0)
        rc = study_fit(ctx, &req, st, out, e);
    free_state(st);
    return rc;
}
