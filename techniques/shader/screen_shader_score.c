/* The project's screen-space shaders beside gtlab's GTAO; see
 * screen_shader_score.h. */
#include "shader/screen_shader_score.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ao/ao_references.h"
#include "core/files/path_name.h"
#include "core/reference_schema.h"
#include "core/statistics/sample_mean.h"
#include "gpu/screen_pass.h"
#include "gtao/gtao.h"
#include "gtao/gtao_scene_refs.h"
#include "shader/shader_run.h"

enum { DEVICE_TIMEOUT_SECONDS = 10 }; /* per frame, as `gtlab shader run` */

/* gtlab's C GTAO in the configuration of techniques/gtao/gtao.glsl at its
 * defaults. */
static void c_gtao(const gtao_scene_refs *s, float *ao)
{
    const gtao_params p = gtao_params_shader_port();
    gtao_frame(&s->in.g, &p, 0, ao, NULL);
}

/* What one run of the stage holds. */
typedef struct {
    const study_project *project;
    screen_shader_program programs[PROJECT_MAX_FILES];
    int prepared;
    gpu_device *device;
    float *c, *planes; /* the C GTAO; the shader's outputs */
} stage_state;

/* The largest |a - b| over the mask, folded into *worst. */
static void fold_max_diff(const gtao_scene_refs *s, const float *a, const float *b, double *worst)
{
    for (size_t i = 0; i < (size_t)s->width * (size_t)s->height; ++i)
        if (s->mask[i] != 0.0f)
            *worst = fmax(*worst, fabs((double)a[i] - (double)b[i]));
}

/* Variant v (>= 1: the shader v - 1) on one scene, scored into its row. */
static int run_shader(stage_state *st, const gtao_scene_refs *s, const gpu_screen_input *in, int v,
                      screen_shader_score_result *out, gt_error *e)
{
    const screen_shader_program *p = &st->programs[v - 1];
    const char *path = st->project->screen_shaders[v - 1].path;
    if (gpu_screen_pass(st->device, &p->spirv, path, in, p->interface.param_value, p->interface.param_count,
                        p->interface.output_count, st->planes, DEVICE_TIMEOUT_SECONDS, NULL, e) != 0)
        return -1;
    const float *ao = st->planes + (size_t)p->plane * (size_t)s->width * (size_t)s->height;
    fold_max_diff(s, ao, st->c, &out->variants[v].max_diff_vs_c);
    return ao_image_score_compute(s, ao, st->c, &out->scores[out->scene_count][v], e);
}

/* Every variant on one loaded scene. */
static int score_scene(stage_state *st, const gtao_scene_refs *s, const char *path, screen_shader_score_result *out,
                       gt_error *e)
{
    size_t n = (size_t)s->width * (size_t)s->height;
    gpu_screen_input in;
    st->c = malloc(n * sizeof *st->c);
    st->planes = malloc(n * GPU_MAX_OUTPUTS * sizeof *st->planes);
    if (!st->c || !st->planes)
        return gt_error_set(e, path, "out of memory");
    if (gpu_screen_input_from_image(&s->in.img, path, &in, e) != 0)
        return -1;
    shader_run_camera_globals(&s->in.g.camera, &in.globals);
    in.globals.frames = 1;
    c_gtao(s, st->c);
    if (ao_image_score_compute(s, st->c, st->c, &out->scores[out->scene_count][0], e) != 0)
        return -1;
    for (int v = 1; v < out->variant_count; ++v)
        if (run_shader(st, s, &in, v, out, e) != 0)
            return -1;
    return 0;
}

/* Scene i's reference loaded and scored. */
static int study_scene(stage_state *st, const char *refs, const char *label, screen_shader_score_result *out,
                       gt_error *e)
{
    gtao_scene_refs s;
    char path[4096 + 64];
    snprintf(path, sizeof path, "%s/%s.exr", refs, label);
    if (gtao_scene_refs_load_3d(refs, label, &s, e) != 0)
        return -1;
    int rc = score_scene(st, &s, path, out, e);
    free(st->c);
    free(st->planes);
    st->c = st->planes = NULL;
    gtao_scene_refs_free(&s);
    return rc;
}

/* The rows' names, and each shader compiled: a bad one fails before any reference is read. */
static int prepare_all(stage_state *st, screen_shader_score_result *out, gt_error *e)
{
    const study_project *p = st->project;
    snprintf(out->variants[0].name, sizeof out->variants[0].name, "GTAO (C)");
    out->variants[0].kind = "gtlab";
    for (; st->prepared < p->screen_shader_count; ++st->prepared) {
        screen_shader_variant *v = &out->variants[1 + st->prepared];
        snprintf(v->name, sizeof v->name, "%s", path_file_name(p->screen_shaders[st->prepared].path));
        v->kind = "shader";
        if (study_screen_shader_prepare(&p->screen_shaders[st->prepared], &st->programs[st->prepared], e) != 0)
            return -1;
    }
    out->variant_count = 1 + p->screen_shader_count;
    return 0;
}

/* Pooled over the scenes: RMSE and the paired difference (ao_image_score_pool), mean DSSIM and FLIP. */
static void pool(screen_shader_score_result *r)
{
    for (int v = 0; v < r->variant_count; ++v) {
        screen_shader_variant *x = &r->variants[v];
        ao_image_score_pool(&r->scores[0][v], sizeof r->scores[0], r->scene_count, &x->vs_gtao, &x->rmse);
        for (int s = 0; s < r->scene_count; ++s) {
            x->dssim += r->scores[s][v].dssim_3d / r->scene_count;
            x->flip += r->scores[s][v].flip_3d / r->scene_count;
        }
    }
}

static int run_stage(stage_state *st, const study_context *ctx, screen_shader_score_result *out, gt_error *e)
{
    char refs[4096];
    snprintf(refs, sizeof refs, "%s/%s", ctx->output_dir, AO_REFERENCES_DIR);
    if (prepare_all(st, out, e) != 0 || gpu_device_open(NULL, &st->device, e) != 0)
        return -1;
    snprintf(out->device, sizeof out->device, "%s", gpu_device_name(st->device));
    int scenes = study_scene_count(ctx) < SCREEN_SCORE_MAX_SCENES ? study_scene_count(ctx) : SCREEN_SCORE_MAX_SCENES;
    for (; out->scene_count < scenes; ++out->scene_count)
        if (study_scene(st, refs, study_scene_at(ctx, out->scene_count)->label, out, e) != 0)
            return -1;
    pool(out);
    return 0;
}

int screen_shader_score_project(const study_context *ctx, screen_shader_score_result *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    if (!ctx->project || ctx->project->screen_shader_count == 0)
        return 0;
    stage_state *st = calloc(1, sizeof *st);
    if (!st)
        return gt_error_set(e, "screen-shaders", "out of memory");
    st->project = ctx->project;
    int rc = run_stage(st, ctx, out, e);
    for (int k = 0; k < st->prepared; ++k)
        screen_shader_program_free(&st->programs[k]);
    gpu_device_close(st->device);
    free(st);
    if (rc != 0)
        out->variant_count = 0;
    return rc;
}
