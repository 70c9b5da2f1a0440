/* A user's multi-bounce functions and plug-ins scored beside gtlab's own
 * (studies/multibounce_score.h). */
#define _GNU_SOURCE
#include "studies/multibounce_score.h"

#include <dirent.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/exr_io.h"
#include "core/path_name.h"
#include "core/reference_schema.h"
#include "fitters/fit_multibounce.h"
#include "gpu/function_shader.h"
#include "gpu/shader_compiler.h"
#include "metrics/reference_halves.h"
#include "realtime/multibounce.h"
#include "studies/multibounce_parts.h"
#include "studies/plugin.h"
#include "studies/specular_occlusion_score.h"

typedef enum { VARIANT_INPUT, VARIANT_MODEL, VARIANT_FUNCTION, VARIANT_PLUGIN } variant_kind;

typedef struct {
    variant_kind kind;
    multibounce_model model; /* VARIANT_MODEL */
    gtlab_plugin plugin;     /* VARIANT_PLUGIN */
    char *text;              /* VARIANT_FUNCTION: the file's text */
    const char *path;
} variant;

typedef struct {
    variant v[MB_SCORE_MAX_VARIANTS];
    int count;
    gpu_device *device; /* opened for the first function file */
    double timeout;
} variants;

static variant *add_variant(variants *vs, multibounce_score_result *out, variant_kind kind, const char *name,
                            const char *path)
{
    variant *v = &vs->v[vs->count];
    multibounce_score_variant *row = &out->variants[vs->count];
    *v = (variant){.kind = kind, .path = path};
    snprintf(row->name, sizeof row->name, "%s", name);
    row->kind = kind == VARIANT_FUNCTION ? "function" : kind == VARIANT_PLUGIN ? "plug-in" : "gtlab";
    out->variant_count = ++vs->count;
    return v;
}

/* The function file's text, checked against the contract now (before any work). */
static int load_function(const multibounce_score_request *rq, variants *vs, variant *v, multibounce_score_result *out,
                         gt_error *e)
{
    if (gpu_function_load(&gpu_function_multibounce, v->path, &v->text, e) != 0)
        return -1;
    if (!vs->device && gpu_device_open(rq->device, &vs->device, e) != 0)
        return -1;
    snprintf(out->device, sizeof out->device, "%s", gpu_device_name(vs->device));
    return 0;
}

static int load_variants(const multibounce_score_request *rq, variants *vs, multibounce_score_result *out,
                         gt_error *e)
{
    vs->timeout = rq->timeout > 0.0 ? rq->timeout : 10.0;
    add_variant(vs, out, VARIANT_INPUT, "V_d", NULL);
    add_variant(vs, out, VARIANT_MODEL, "talk", NULL)->model = multibounce_model_jimenez2016();
    for (int i = 0; i < rq->function_count; ++i) {
        const char *path = rq->functions[i];
        if (load_function(rq, vs, add_variant(vs, out, VARIANT_FUNCTION, path_file_name(path), path), out, e) != 0)
            return -1;
    }
    for (int i = 0; i < rq->plugin_count; ++i) {
        const char *path = rq->plugins[i];
        if (plugin_open(path, &add_variant(vs, out, VARIANT_PLUGIN, path_file_name(path), path)->plugin, e) != 0)
            return -1;
    }
    return 0;
}

static void free_variants(variants *vs)
{
    for (int i = 0; i < vs->count; ++i) {
        plugin_close(&vs->v[i].plugin);
        free(vs->v[i].text);
    }
    if (vs->device)
        gpu_device_close(vs->device);
}

/* Variant v's V'_d at the surface pixels, 0 in the background: multibounce_apply_model's contract. */
static int apply(const variants *vs, const variant *v, const float *visibility, const float *mask, size_t n,
                 float albedo, float *out, gt_error *e)
{
    switch (v->kind) {
    case VARIANT_INPUT:
        for (size_t i = 0; i < n; ++i)
            out[i] = mask[i] != 0.0f ? visibility[i] : 0.0f;
        return 0;
    case VARIANT_MODEL:
        multibounce_apply_model(&v->model, visibility, mask, n, albedo, out);
        return 0;
    case VARIANT_PLUGIN:
        return plugin_apply_multibounce(&v->plugin, v->path, visibility, mask, n, albedo, out, e);
    default: /* a function file at the surface pixels (their V_d and the albedo) */
        return gpu_function_eval_masked(vs->device, &gpu_function_multibounce, v->text, v->path,
                                        (const float *const[]){visibility, NULL}, (const float[]){0.0f, albedo}, mask,
                                        n, out, vs->timeout, e);
    }
}

/* One reference, split in halves, at one albedo: the floor and every variant. */
typedef struct {
    const image *img, *halves;
    const char *path, *channel;
    float albedo;
} scored_plane;

static int score_row(const variants *vs, const scored_plane *p, float *approx, multibounce_score_row *row,
                     gt_error *e)
{
    const image *img = p->img;
    const float *mask = image_channel_data(img, CH_MASK), *target = image_channel_data(&p->halves[1], p->channel);
    const float *visibility = image_channel_data(&p->halves[0], CH_AO);
    const char *scene = image_get_attribute(img, ATTR_SCENE);
    snprintf(row->scene, sizeof row->scene, "%s", scene ? scene : path_file_name(p->path));
    row->albedo = p->albedo;
    if (!mask || !target || !visibility)
        return gt_error_set(e, p->path, "no %s, %s or %s channel", CH_MASK, CH_AO, p->channel);
    if (multibounce_score_images(image_channel_data(&p->halves[0], p->channel), target, mask, img, p->path,
                                 &row->noise_floor_dssim, &row->noise_floor_rmse, e) != 0)
        return -1;
    size_t n = image_pixel_count(img);
    for (int k = 0; k < vs->count; ++k)
        if (apply(vs, &vs->v[k], visibility, mask, n, p->albedo, approx, e) != 0 ||
            multibounce_score_images(approx, target, mask, img, p->path, &row->dssim[k], &row->rmse[k], e) != 0)
            return -1;
    return 0;
}

/* The rows of one reference file, one per albedo. */
static int score_file(const variants *vs, const char *path, multibounce_score_result *out, gt_error *e)
{
    image img, halves[2];
    float albedos[MBFIT_MAX_ALBEDOS];
    char channels[MBFIT_MAX_ALBEDOS][64];
    int count;
    if (exr_read(path, &img, e) != 0)
        return -1;
    int rc = multibounce_image_albedos(&img, path, albedos, channels, &count, e);
    if (rc == 0 && count > MB_SCORE_MAX_ALBEDOS)
        rc = gt_error_set(e, path, "%d albedos; gtlab scores at most %d per file", count, MB_SCORE_MAX_ALBEDOS);
    if (rc == 0 && (rc = reference_halves_split(&img, path, halves, e)) == 0) {
        float *approx = malloc(image_pixel_count(&img) * sizeof *approx);
        rc = approx ? 0 : gt_error_set(e, path, "out of memory");
        for (int a = 0; a < count && rc == 0; ++a) {
            scored_plane p = {&img, halves, path, channels[a], albedos[a]};
            rc = score_row(vs, &p, approx, &out->rows[out->row_count++], e);
        }
        free(approx);
        image_free(&halves[0]), image_free(&halves[1]);
    }
    image_free(&img);
    return rc;
}

void multibounce_score_take_means(multibounce_score_result *out)
{
    multibounce_score_row *m = &out->mean;
    memset(m, 0, sizeof *m);
    snprintf(m->scene, sizeof m->scene, "mean");
    m->albedo = NAN;
    for (int r = 0; r < out->row_count; ++r) {
        const multibounce_score_row *row = &out->rows[r];
        m->noise_floor_dssim += row->noise_floor_dssim / out->row_count;
        m->noise_floor_rmse += row->noise_floor_rmse / out->row_count;
        for (int k = 0; k < out->variant_count; ++k)
            m->dssim[k] += row->dssim[k] / out->row_count, m->rmse[k] += row->rmse[k] / out->row_count;
    }
    for (int k = 0; k < out->variant_count; ++k) {
        multibounce_score_variant *v = &out->variants[k];
        v->dssim = m->dssim[k], v->rmse = m->rmse[k];
        v->dssim_floor = m->noise_floor_dssim, v->rmse_floor = m->noise_floor_rmse;
    }
}

int multibounce_score_check_files(const multibounce_score_request *rq, gt_error *e)
{
    if (rq->function_count + rq->plugin_count == 0)
        return gt_error_set(e, "shader score", "nothing to score: give --function F.glsl|F.hlsl or --plugin LIB.so");
    if (rq->function_count > MB_SCORE_MAX_FILES || rq->plugin_count > MB_SCORE_MAX_FILES)
        return gt_error_set(e, "shader score", "at most %d function files and %d plug-ins", MB_SCORE_MAX_FILES,
                            MB_SCORE_MAX_FILES);
    return 0;
}

int multibounce_score(const multibounce_score_request *rq, multibounce_score_result *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    if (rq->quantity && strcmp(rq->quantity, SO_SCORE_QUANTITY) == 0)
        return specular_occlusion_score(rq, out, e);
    if (rq->quantity && strcmp(rq->quantity, "multibounce") != 0)
        return gt_error_set(e, "--quantity", "'%s': gtlab scores multibounce and %s functions (so far)", rq->quantity,
                            SO_SCORE_QUANTITY);
    out->parameter = "albedo";
    out->caption = "V'_d of the odd-sample half against each variant fed V_d of the even half";
    if (multibounce_score_check_files(rq, e) != 0)
        return -1;
    if (rq->reference_count < 1 || rq->reference_count > MB_SCORE_MAX_FILES)
        return gt_error_set(e, "shader score", "%d references: 1 to %d multi-bounce renders expected",
                            rq->reference_count, MB_SCORE_MAX_FILES);
    variants *vs = calloc(1, sizeof *vs);
    int rc = vs ? load_variants(rq, vs, out, e) : gt_error_set(e, "shader score", "out of memory");
    for (int i = 0; i < rq->reference_count && rc == 0; ++i)
        rc = score_file(vs, rq->references[i], out, e);
    if (rc == 0)
        multibounce_score_take_means(out);
    if (vs)
        free_variants(vs);
    free(vs);
    return rc;
}

/* The parameter column's width: 6 ("albedo"), or its name's. */
static int parameter_width(const multibounce_score_result *r)
{
    int n = (int)strlen(r->parameter);
    return n > 6 ? n : 6;
}

static void print_row(FILE *f, const multibounce_score_result *r, const multibounce_score_row *row)
{
    int width = parameter_width(r);
    char albedo[32];
    snprintf(albedo, sizeof albedo, "%*s", width, "-");
    if (!isnan(row->albedo))
        snprintf(albedo, sizeof albedo, "%*.2f", width, row->albedo);
    fprintf(f, "%-20.20s %s  %12.3e", row->scene, albedo, row->noise_floor_dssim);
    for (int k = 0; k < r->variant_count; ++k)
        fprintf(f, " %12.3e", row->dssim[k]);
    fprintf(f, "  %12.5f", row->noise_floor_rmse);
    for (int k = 0; k < r->variant_count; ++k)
        fprintf(f, " %12.5f", row->rmse[k]);
    fputc('\n', f);
}

void multibounce_score_print(FILE *f, const multibounce_score_result *r)
{
    fprintf(f, "%s%s%s\n", r->caption, r->device[0] ? "; functions on " : "", r->device);
    fprintf(f, "%-20s %*s  %12s", "scene", parameter_width(r), r->parameter, "DSSIM floor");
    for (int k = 0; k < r->variant_count; ++k)
        fprintf(f, " %12.12s", r->variants[k].name);
    fprintf(f, "  %12s", "RMSE floor");
    for (int k = 0; k < r->variant_count; ++k)
        fprintf(f, " %12.12s", r->variants[k].name);
    fputc('\n', f);
    for (int i = 0; i < r->row_count; ++i)
        print_row(f, r, &r->rows[i]);
    print_row(f, r, &r->mean);
}

static int exr_file(const struct dirent *d)
{
    size_t n = strlen(d->d_name);
    return n > 4 && strcmp(d->d_name + n - 4, ".exr") == 0;
}

/* The references below <output>/MULTIBOUNCE_STUDY_DIR, in name order, into paths. */
static int find_references(const study_context *ctx, char paths[][4096], int *count, gt_error *e)
{
    char dir[2048];
    snprintf(dir, sizeof dir, "%s/%s", ctx->output_dir, MULTIBOUNCE_STUDY_DIR);
    struct dirent **list;
    int n = scandir(dir, &list, exr_file, alphasort);
    if (n < 0)
        return gt_error_set(e, dir, "cannot list the multi-bounce references (run the multibounce stage)");
    *count = n;
    for (int i = 0; i < n; ++i) {
        if (i < MB_SCORE_MAX_FILES)
            snprintf(paths[i], 4096, "%s/%s", dir, list[i]->d_name);
        free(list[i]);
    }
    free(list);
    if (n > MB_SCORE_MAX_FILES)
        return gt_error_set(e, dir, "%d references; at most %d are scored", n, MB_SCORE_MAX_FILES);
    return n > 0 ? 0 : gt_error_set(e, dir, "no multi-bounce references (*.exr; run the multibounce stage)");
}

int multibounce_score_project(const study_context *ctx, const char *const *functions, int function_count,
                              const char *const *plugins, int plugin_count, multibounce_score_result *out,
                              gt_error *e)
{
    memset(out, 0, sizeof *out);
    if (function_count + plugin_count == 0)
        return 0;
    static char paths[MB_SCORE_MAX_FILES][4096];
    const char *references[MB_SCORE_MAX_FILES];
    int count = 0;
    if (find_references(ctx, paths, &count, e) != 0)
        return -1;
    for (int i = 0; i < count; ++i)
        references[i] = paths[i];
    multibounce_score_request rq = {.quantity = "multibounce", .references = references, .reference_count = count,
                                    .functions = functions, .function_count = function_count, .plugins = plugins,
                                    .plugin_count = plugin_count, .timeout = 10.0};
    return multibounce_score(&rq, out, e);
}
