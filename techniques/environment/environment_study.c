/* The environment study: the environments and their lighting
 * precomputations, the references of every scene under each, the cases
 * scored (environment/environment_scores.c), the means, the specular-occlusion
 * rankings against the white dome's and the talk's claim. */
#include "environment/environment_study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ao/ao_quantity.h"
#include "core/optics/environment_map.h"
#include "core/progress.h"
#include "core/roughness_setting.h"
#include "environment/environment_light.h"
#include "environment/environment_quality.h"
#include "environment/environment_quantity.h"
#include "raytracer/reference_render.h"
#include "project/scene_list.h"
#include "environment/environment_lighting.h"
#include "environment/environment_parts.h"

#define ENVIRONMENT_STUDY_DIR "environment"
#define ENVIRONMENT_IMAGE_SCENE "cornell"

static const char *const blender_preview[] = {"sunset", "interior"};
static const char *const blender_all[] = {"city",   "courtyard", "forest", "interior",
                                          "night", "studio",    "sunrise", "sunset"};
static const char *const preview_scenes[] = {"sphere-on-plane", "boxes", "cornell"};

typedef struct {
    char spec[ENVIRONMENT_NAME_MAX]; /* what the references are given: "white", "sky", "sun" or the file */
    environment_map map;
    environment_precomputed lighting;
} study_environment;

typedef struct {
    const study_context *ctx;
    environment_study_result *out;
    char dir[2048];
    dfg_lut dfg;
    so_lut lut;
    so_variant variants[ENVIRONMENT_STUDY_SO_VARIANTS];
    study_environment envs[ENVIRONMENT_STUDY_MAX_ENVIRONMENTS];
    environment_case_scores sums[ENVIRONMENT_STUDY_MAX_ENVIRONMENTS];
} env_state;

/* ---- the environments ------------------------------------------------------------ */

static int load_environment(env_state *st, const char *name, const char *file, gt_error *e)
{
    environment_study_environment *row = &st->out->environments[st->out->environment_count];
    study_environment *env = &st->envs[st->out->environment_count];
    static const float white[3] = {1.0f, 1.0f, 1.0f};
    environment_sun sun = environment_sun_default();
    int rc = file                           ? environment_map_load(&env->map, file, e)
             : strcmp(name, "white") == 0 ? environment_map_constant(&env->map, "white", white, e)
             : strcmp(name, "sky") == 0   ? environment_map_sky(&env->map, e)
                                          : environment_map_sun(&env->map, &sun, e);
    if (rc != 0)
        return -1;
    snprintf(env->spec, sizeof env->spec, "%.*s", (int)sizeof env->spec - 1, file ? file : name);
    snprintf(row->name, sizeof row->name, "%.*s", (int)sizeof row->name - 1, name);
    st->out->environment_count++;
    environment_settings s = environment_default_settings(st->ctx->quality);
    if (environment_precompute(&env->map, &s, &st->dfg, st->ctx->threads, &env->lighting, e) != 0)
        return -1;
    row->sh_seconds = env->lighting.sh_seconds, row->map_seconds = env->lighting.map_seconds;
    row->prefiltered_seconds = env->lighting.prefiltered_seconds;
    return 0;
}

static int load_environments(env_state *st, gt_error *e)
{
    static const char *const builtin[3] = {"white", "sky", "sun"};
    int all = environment_quality_of(st->ctx->quality)->all_blender_environments;
    const char *const *blender = all ? blender_all : blender_preview;
    int count = all ? (int)(sizeof blender_all / sizeof blender_all[0])
                    : (int)(sizeof blender_preview / sizeof blender_preview[0]);
    for (int i = 0; i < 3; ++i)
        if (load_environment(st, builtin[i], NULL, e) != 0)
            return -1;
    for (int i = 0; i < count; ++i) {
        char path[512];
        snprintf(path, sizeof path, ENVIRONMENT_BLENDER_WORLDS "%s.exr", blender[i]);
        if (load_environment(st, blender[i], path, e) != 0)
            return -1;
    }
    return 0;
}

/* The DFG table and the GTSO LUT every environment shares, and the variants. */
static int shared_tables(env_state *st, gt_error *e)
{
    if (dfg_lut_build(&st->dfg, 64, st->ctx->threads) != 0 ||
        so_lut_build(&st->lut, 32, SO_LOBE_GGX, SO_AXES_ANGLES, st->ctx->threads) != 0)
        return gt_error_set(e, "environment study", "out of memory building the DFG and GTSO tables");
    for (int v = 0; v < ENVIRONMENT_STUDY_SO_VARIANTS; ++v) {
        so_variant_parse(environment_study_so_label(v), &st->variants[v]);
        st->variants[v].lut = &st->lut;
    }
    return 0;
}

/* ---- the references -------------------------------------------------------------- */

static int render(const env_state *st, const scene *s, const char *spec, const camera *cam, reference_quantity q,
                  const char *environment, image *out, gt_error *e)
{
    environment_render_settings light;
    environment_render_settings_default(&light, q);
    snprintf(light.environment, sizeof light.environment, "%s", environment ? environment : "white");
    light.f0 = 0.04f;
    light.roughness = ROUGHNESS_OF_MATERIAL;
    light.multibounce = (multibounce_settings){.scene_albedo = 1, .bounces = st->out->bounces};
    reference_request req = {.quantity = q,
                             .sampling = {.spp = st->out->spp, .seed = 1, .threads = st->ctx->threads},
                             .normals = NORMAL_SHADING, .settings = environment ? &light.header : NULL};
    render_stats stats;
    return reference_render(s, spec, cam, &req, out, &stats, e);
}

/* Adds a case's scores to the environment's sums and per-scene arrays. */
static void accumulate(env_state *st, int env, int scene, const environment_case_scores *c)
{
    environment_case_scores *sum = &st->sums[env];
    environment_study_environment *row = &st->out->environments[env];
    for (int s = 0; s < ENVIRONMENT_IRRADIANCE_SOURCES; ++s)
        for (int k = 0; k < ENVIRONMENT_STUDY_OCCLUDED_KINDS; ++k)
            for (int p = 0; p < ENVIRONMENT_PARTS; ++p) {
                sum->diffuse[s][k][p].rmse += c->diffuse[s][k][p].rmse;
                sum->diffuse[s][k][p].dssim += c->diffuse[s][k][p].dssim;
            }
    for (int v = 0; v < ENVIRONMENT_STUDY_SO_VARIANTS; ++v) {
        for (int p = 0; p < ENVIRONMENT_PARTS; ++p) {
            sum->specular[v][p].rmse += c->specular[v][p].rmse;
            sum->specular[v][p].dssim += c->specular[v][p].dssim;
        }
        row->specular_case[v][scene] = c->specular[v][ENVIRONMENT_PART_TOTAL].rmse;
    }
    for (int p = 0; p < ENVIRONMENT_PARTS; ++p)
        row->ao_n_case[p][scene] = c->diffuse[ENVIRONMENT_IRRADIANCE_MAP][ENVIRONMENT_DIFFUSE_AO_N - 1][p].rmse;
    sum->reference_noise += c->reference_noise;
    row->noise_case[scene] = c->reference_noise;
}

/* One environment on one scene: its two references, scored (and imaged for the image scene). */
static int run_case(env_state *st, int env, int scene_index, const scene *s, const char *spec, const camera *cam,
                    const image *ao, const char *scene_name, gt_error *e)
{
    image diffuse = {0}, specular = {0};
    char what[256];
    snprintf(what, sizeof what, "environment %s, scene %s", st->out->environments[env].name, scene_name);
    int rc = render(st, s, spec, cam, &reference_quantity_env_diffuse, st->envs[env].spec, &diffuse, e);
    if (rc == 0)
        rc = render(st, s, spec, cam, &reference_quantity_env_specular, st->envs[env].spec, &specular, e);
    environment_case c = {ao, &diffuse, &specular, &st->envs[env].lighting.lighting, st->variants, what};
    environment_case_scores scores;
    memset(&scores, 0, sizeof scores);
    if (rc == 0)
        rc = environment_case_score(&c, &scores, e);
    if (rc == 0)
        accumulate(st, env, scene_index, &scores);
    if (rc == 0 && strcmp(scene_name, st->out->image_scene) == 0) {
        char stem[128];
        snprintf(stem, sizeof stem, "%s_%s", st->out->environments[env].name, scene_name);
        rc = environment_case_images(&c, st->dir, stem, e);
    }
    image_free(&diffuse);
    image_free(&specular);
    return rc;
}

static int run_scene(env_state *st, const study_scene_entry *entry, gt_error *e)
{
    const char *spec = entry->spec, *name = entry->label;
    scene s;
    camera cam;
    image ao = {0};
    if (study_scene_view(entry, st->out->size, st->out->size, &s, &cam, e) != 0)
        return -1;
    int scene_index = st->out->scene_count;
    int rc = render(st, &s, spec, &cam, QUANTITY_AO, NULL, &ao, e);
    for (int env = 0; env < st->out->environment_count && rc == 0; ++env)
        rc = run_case(st, env, scene_index, &s, spec, &cam, &ao, name, e);
    if (rc == 0)
        snprintf(st->out->scenes[st->out->scene_count++], sizeof st->out->scenes[0], "%s", name);
    image_free(&ao);
    scene_free(&s);
    return rc;
}

static int run_scenes(env_state *st, gt_error *e)
{
    if (!environment_quality_of(st->ctx->quality)->all_scenes && !study_scenes_from_project(st->ctx)) { /* a project's run all */
        for (size_t i = 0; i < sizeof preview_scenes / sizeof preview_scenes[0]; ++i)
            if (run_scene(st, study_scene_find(st->ctx, preview_scenes[i]), e) != 0)
                return -1;
        return 0;
    }
    for (int i = 0; i < study_scene_count(st->ctx) && i < ENVIRONMENT_STUDY_MAX_SCENES; ++i)
        if (run_scene(st, study_scene_at(st->ctx, i), e) != 0)
            return -1;
    return 0;
}

/* ---- the results ----------------------------------------------------------------- */

static void average(env_state *st)
{
    double n = st->out->scene_count;
    for (int env = 0; env < st->out->environment_count; ++env) {
        environment_study_environment *row = &st->out->environments[env];
        const environment_case_scores *sum = &st->sums[env];
        for (int s = 0; s < ENVIRONMENT_IRRADIANCE_SOURCES; ++s)
            for (int k = 0; k < ENVIRONMENT_STUDY_OCCLUDED_KINDS; ++k)
                for (int p = 0; p < ENVIRONMENT_PARTS; ++p) {
                    row->diffuse[s][k][p].rmse = sum->diffuse[s][k][p].rmse / n;
                    row->diffuse[s][k][p].dssim = sum->diffuse[s][k][p].dssim / n;
                }
        for (int v = 0; v < ENVIRONMENT_STUDY_SO_VARIANTS; ++v)
            for (int p = 0; p < ENVIRONMENT_PARTS; ++p) {
                row->specular[v][p].rmse = sum->specular[v][p].rmse / n;
                row->specular[v][p].dssim = sum->specular[v][p].dssim / n;
            }
        row->reference_noise = sum->reference_noise / n;
    }
}

static void free_state(env_state *st)
{
    for (int env = 0; env < ENVIRONMENT_STUDY_MAX_ENVIRONMENTS; ++env) {
        environment_precomputed_free(&st->envs[env].lighting);
        environment_map_free(&st->envs[env].map);
    }
    dfg_lut_free(&st->dfg);
    so_lut_free(&st->lut);
}

int environment_study(const study_context *ctx, environment_study_result *out, gt_error *e)
{
    double t0 = seconds_now();
    const environment_quality *q = environment_quality_of(ctx->quality);
    memset(out, 0, sizeof *out);
    snprintf(out->image_scene, sizeof out->image_scene, "%s",
             study_scenes_from_project(ctx) ? study_scene_at(ctx, 0)->label : ENVIRONMENT_IMAGE_SCENE);
    out->size = q->image_size, out->spp = q->reference_spp, out->bounces = 3;
    env_state *st = calloc(1, sizeof *st);
    if (!st)
        return gt_error_set(e, "environment study", "out of memory");
    st->ctx = ctx, st->out = out;
    int rc = study_make_dir(ctx, ENVIRONMENT_STUDY_DIR, st->dir, sizeof st->dir, e);
    if (rc == 0)
        rc = shared_tables(st, e);
    if (rc == 0)
        rc = load_environments(st, e);
    if (rc == 0)
        rc = run_scenes(st, e);
    if (rc == 0) {
        average(st);
        for (int env = 0; env < out->environment_count; ++env)
            environment_study_rank(out, env);
        environment_study_claim(out);
    }
    free_state(st);
    free(st);
    out->seconds = seconds_now() - t0;
    return rc;
}
