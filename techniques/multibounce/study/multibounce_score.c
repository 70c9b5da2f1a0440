/* A user's multi-bounce functions and plug-ins scored beside gtlab's own
 * (multibounce/multibounce_score.h): the references, rows and built-ins; the
 * rest is scoring/function_score.h's. */
#define _GNU_SOURCE
#include "multibounce/multibounce_score.h"

#include <dirent.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/exr_io.h"
#include "core/files/path_name.h"
#include "core/plugin_abi.h"
#include "core/reference_schema.h"
#include "metrics/reference_halves.h"
#include "multibounce/multibounce.h"
#include "multibounce/multibounce_fit.h"
#include "multibounce/multibounce_parts.h"

const function_score_quantity multibounce_scored_quantity = {"multi-bounce", &gpu_function_multibounce,
                                                             GTLAB_MULTIBOUNCE_V1_SYMBOL};

enum { VARIANT_INPUT, VARIANT_MODEL }; /* gtlab's own: V_d alone, the talk's GTAOMultiBounce */

typedef struct {
    multibounce_model talk;
    function_scorer *scorer; /* the function files and plug-ins */
} variants;

/* Variant k's V'_d at the surface pixels, 0 in the background: multibounce_apply_model's contract. */
static int apply(const variants *vs, int k, const float *visibility, const float *mask, size_t n, float albedo,
                 float *out, gt_error *e)
{
    switch (k) {
    case VARIANT_INPUT:
        for (size_t i = 0; i < n; ++i)
            out[i] = mask[i] != 0.0f ? visibility[i] : 0.0f;
        return 0;
    case VARIANT_MODEL:
        multibounce_apply_model(&vs->talk, visibility, mask, n, albedo, out);
        return 0;
    default: /* a function file or a plug-in at the surface pixels (their V_d and the albedo) */
        return function_scorer_apply(vs->scorer, k, (const float *const[]){visibility, NULL},
                                     (const float[]){0.0f, albedo}, mask, n, out, e);
    }
}

/* One reference, split in halves, at one albedo: the floor and every variant. */
typedef struct {
    const image *img, *halves;
    const char *path, *channel;
    float albedo;
} scored_plane;

static int score_row(const variants *vs, int count, const scored_plane *p, float *approx, function_score_row *row,
                     gt_error *e)
{
    const image *img = p->img;
    const float *mask = image_channel_data(img, CH_MASK), *target = image_channel_data(&p->halves[1], p->channel);
    const float *visibility = image_channel_data(&p->halves[0], CH_AO);
    const char *scene = image_get_attribute(img, ATTR_SCENE);
    snprintf(row->scene, sizeof row->scene, "%s", scene ? scene : path_file_name(p->path));
    row->value = p->albedo;
    if (!mask || !target || !visibility)
        return gt_error_set(e, p->path, "no %s, %s or %s channel", CH_MASK, CH_AO, p->channel);
    if (multibounce_score_images(image_channel_data(&p->halves[0], p->channel), target, mask, img, p->path,
                                 &row->noise_floor_dssim, &row->noise_floor_rmse, e) != 0)
        return -1;
    size_t n = image_pixel_count(img);
    for (int k = 0; k < count; ++k)
        if (apply(vs, k, visibility, mask, n, p->albedo, approx, e) != 0 ||
            multibounce_score_images(approx, target, mask, img, p->path, &row->dssim[k], &row->rmse[k], e) != 0)
            return -1;
    return 0;
}

/* The rows of one reference file, one per albedo. */
static int score_file(const variants *vs, const char *path, function_score_result *out, gt_error *e)
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
            rc = score_row(vs, out->variant_count, &p, approx, &out->rows[out->row_count++], e);
        }
        free(approx);
        image_free(&halves[0]), image_free(&halves[1]);
    }
    image_free(&img);
    return rc;
}

int multibounce_score(const multibounce_score_request *rq, function_score_result *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    out->parameter = "albedo";
    out->caption = "V'_d of the odd-sample half against each variant fed V_d of the even half";
    if (function_score_check_files(&rq->files, e) != 0)
        return -1;
    if (rq->reference_count < 1 || rq->reference_count > FUNCTION_SCORE_MAX_FILES)
        return gt_error_set(e, "shader score", "%d references: 1 to %d multi-bounce renders expected",
                            rq->reference_count, FUNCTION_SCORE_MAX_FILES);
    variants vs = {.talk = multibounce_model_jimenez2016()};
    function_score_add_builtin(out, "V_d");
    function_score_add_builtin(out, "talk");
    int rc = function_scorer_open(&multibounce_scored_quantity, &rq->files, out, &vs.scorer, e);
    for (int i = 0; i < rq->reference_count && rc == 0; ++i)
        rc = score_file(&vs, rq->references[i], out, e);
    if (rc == 0)
        function_score_take_means(out);
    function_scorer_close(vs.scorer);
    return rc;
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
        if (i < FUNCTION_SCORE_MAX_FILES)
            snprintf(paths[i], 4096, "%s/%s", dir, list[i]->d_name);
        free(list[i]);
    }
    free(list);
    if (n > FUNCTION_SCORE_MAX_FILES)
        return gt_error_set(e, dir, "%d references; at most %d are scored", n, FUNCTION_SCORE_MAX_FILES);
    return n > 0 ? 0 : gt_error_set(e, dir, "no multi-bounce references (*.exr; run the multibounce stage)");
}

int multibounce_score_project(const study_context *ctx, const char *const *functions, int function_count,
                              const char *const *plugins, int plugin_count, function_score_result *out,
                              gt_error *e)
{
    memset(out, 0, sizeof *out);
    if (function_count + plugin_count == 0)
        return 0;
    static char paths[FUNCTION_SCORE_MAX_FILES][4096];
    const char *references[FUNCTION_SCORE_MAX_FILES];
    int count = 0;
    if (find_references(ctx, paths, &count, e) != 0)
        return -1;
    for (int i = 0; i < count; ++i)
        references[i] = paths[i];
    multibounce_score_request rq = {.references = references, .reference_count = count,
                                    .files = {.functions = functions, .function_count = function_count,
                                              .plugins = plugins, .plugin_count = plugin_count, .timeout = 10.0}};
    return multibounce_score(&rq, out, e);
}
