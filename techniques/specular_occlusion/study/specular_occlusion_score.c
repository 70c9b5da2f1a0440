/* A user's specular-occlusion functions and plug-ins scored beside gtlab's
 * own variants (specular_occlusion/specular_occlusion_score.h): the references, rows
 * and built-ins; the rest is scoring/function_score.h's. */
#include "specular_occlusion/specular_occlusion_score.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ao/ao_quantity.h"
#include "core/files/exr_io.h"
#include "core/files/path_name.h"
#include "core/plugin_abi.h"
#include "core/reference_schema.h"
#include "core/roughness_setting.h"
#include "specular_occlusion/specular_occlusion_study.h"
#include "specular_occlusion/specular_occlusion_inputs.h"
#include "specular_occlusion/specular_occlusion_quantity.h"
#include "project/scene_list.h"

/* gtlab's own rows (so_variant_parse's texts). */
static const char *const kBuiltins[] = {"ao", "lagarde", "cone-exact:exp2-alpha", "cone-oat:exp2-alpha", "sg"};
enum { BUILTINS = (int)(sizeof kBuiltins / sizeof kBuiltins[0]) };

const function_score_quantity specular_occlusion_scored_quantity = {
    "specular occlusion", &gpu_function_specular_occlusion, GTLAB_SPECULAR_OCCLUSION_V1_SYMBOL};

typedef struct {
    const specular_occlusion_score_request *rq;
    so_variant builtin[BUILTINS];
    function_scorer *scorer; /* the function files and plug-ins */
} so_variants;

/* gtlab's variants, then each function file (checked against the contract) and plug-in. */
static int load(so_variants *vs, function_score_result *out, gt_error *e)
{
    for (int k = 0; k < BUILTINS; ++k) {
        so_variant_parse(kBuiltins[k], &vs->builtin[k]);
        function_score_add_builtin(out, kBuiltins[k]);
    }
    return function_scorer_open(&specular_occlusion_scored_quantity, &vs->rq->files, out, &vs->scorer, e);
}

/* Variant k's V_s at every pixel, 0 outside the mask: so_approx_evaluate's contract. */
static int apply(const so_variants *vs, int k, const so_pixel_inputs *in, float *out, gt_error *e)
{
    if (k < BUILTINS) {
        so_approx_evaluate(in, &vs->builtin[k], out);
        return 0;
    }
    /* a function file or a plug-in at the surface pixels (their ao, beta, roughness, n.v) */
    const float *const planes[4] = {in->ao_cosine, in->beta, in->roughness, in->n_dot_v};
    const float constants[4] = {0};
    return function_scorer_apply(vs->scorer, k, planes, constants, in->mask, (size_t)in->width * (size_t)in->height,
                                 out, e);
}

/* One reference's row: its noise floor and every variant, as the study scores them. */
static int score_row(const so_variants *vs, const image *ref, const aperture_case *c, const char *path, int count,
                     function_score_row *row, gt_error *e)
{
    const char *scene = image_get_attribute(ref, ATTR_SCENE);
    snprintf(row->scene, sizeof row->scene, "%s", scene ? scene : path_file_name(path));
    double roughness = so_reference_roughness(ref);
    row->value = roughness_is_material(roughness) ? NAN : roughness;
    if (so_study_ratio_noise_floor(ref, path, CH_SPECOCC, &row->noise_floor_dssim, &row->noise_floor_rmse, e) != 0)
        return -1;
    const so_pixel_inputs *in = &c->inputs;
    float *approx = malloc((size_t)in->width * (size_t)in->height * sizeof *approx);
    int rc = approx ? 0 : gt_error_set(e, path, "out of memory");
    for (int k = 0; k < count && rc == 0; ++k)
        if ((rc = apply(vs, k, in, approx, e)) == 0)
            rc = so_study_add_scores(c->reference, approx, in->mask, in->width, in->height, path, &row->dssim[k],
                                     &row->rmse[k], NULL, e);
    free(approx);
    return rc;
}

static int score_reference(const so_variants *vs, int i, function_score_result *out, gt_error *e)
{
    image ref, ao;
    aperture_case c;
    int loaded = 0;
    const specular_occlusion_score_request *rq = vs->rq;
    int rc = aperture_cases_load(&rq->references[i], &rq->aos[i], 1, CH_SPECOCC, &ref, &ao, &c, &loaded, e);
    if (rc == 0)
        rc = score_row(vs, &ref, &c, rq->references[i], out->variant_count, &out->rows[out->row_count++], e);
    aperture_cases_free(&ref, &ao, &c, loaded);
    return rc;
}

static int check_request(const specular_occlusion_score_request *rq, gt_error *e)
{
    if (function_score_check_files(&rq->files, e) != 0)
        return -1;
    if (rq->reference_count < 1 || rq->reference_count > FUNCTION_SCORE_MAX_ROWS || rq->ao_count != rq->reference_count)
        return gt_error_set(e, "shader score", "%d references and %d --ao files: 1 to %d specular-occlusion "
                            "references expected, each with one --ao (its view's 'gtlab render ao')",
                            rq->reference_count, rq->ao_count, FUNCTION_SCORE_MAX_ROWS);
    return 0;
}

int specular_occlusion_score(const specular_occlusion_score_request *rq, function_score_result *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    out->parameter = "roughness";
    out->caption = "specocc.V against each variant on the AO reference's inputs (ao.V, bent normal)";
    if (check_request(rq, e) != 0)
        return -1;
    so_variants vs = {.rq = rq};
    int rc = load(&vs, out, e);
    for (int i = 0; i < rq->reference_count && rc == 0; ++i)
        rc = score_reference(&vs, i, out, e);
    if (rc == 0)
        function_score_take_means(out);
    function_scorer_close(vs.scorer);
    return rc;
}

/* Renders one reference of the study (so_study_render) into path. */
static int render_file(const study_context *ctx, const scene *s, const study_scene_entry *b, const camera *cam,
                       reference_quantity q, float roughness, const char *path, gt_error *e)
{
    image img;
    render_stats stats;
    if (so_study_render(ctx, s, b->spec, cam, q, roughness, &img, &stats, e) != 0)
        return -1;
    int rc = exr_write(path, &img, e);
    image_free(&img);
    return rc;
}

typedef struct {
    char references[FUNCTION_SCORE_MAX_ROWS][4096], aos[FUNCTION_SCORE_MAX_ROWS][4096];
    int count;
} so_reference_files;

/* One scene's AO reference and its specular-occlusion references at the study's roughnesses. */
static int render_scene(const study_context *ctx, const study_scene_entry *b, const char *dir, so_reference_files *f,
                        gt_error *e)
{
    int size, spp;
    so_study_resolution(ctx, &size, &spp);
    scene s;
    camera cam;
    if (study_scene_view(b, size, 0, &s, &cam, e) != 0)
        return -1;
    char ao[4096];
    snprintf(ao, sizeof ao, "%s/%s_ao.exr", dir, b->label);
    int rc = render_file(ctx, &s, b, &cam, QUANTITY_AO, -1.0f, ao, e);
    for (int r = 0; r < SO_STUDY_ROUGHNESSES && rc == 0; ++r) {
        if (f->count == FUNCTION_SCORE_MAX_ROWS) {
            rc = gt_error_set(e, b->label, "more than %d specular-occlusion references", FUNCTION_SCORE_MAX_ROWS);
            break;
        }
        snprintf(f->aos[f->count], sizeof f->aos[0], "%s", ao);
        snprintf(f->references[f->count], sizeof f->references[0], "%s/%s_r%.2f.exr", dir, b->label,
                 (double)so_study_roughness_values[r]);
        rc = render_file(ctx, &s, b, &cam, QUANTITY_SPECULAR_OCCLUSION, so_study_roughness_values[r],
                         f->references[f->count++], e);
    }
    scene_free(&s);
    return rc;
}

int specular_occlusion_score_project(const study_context *ctx, const char *const *functions, int function_count,
                                     const char *const *plugins, int plugin_count, function_score_result *out,
                                     gt_error *e)
{
    memset(out, 0, sizeof *out);
    if (function_count + plugin_count == 0)
        return 0;
    static so_reference_files f;
    static const char *references[FUNCTION_SCORE_MAX_ROWS], *aos[FUNCTION_SCORE_MAX_ROWS];
    char dir[2048];
    f.count = 0;
    int rc = study_make_dir(ctx, SO_SCORE_DIR, dir, sizeof dir, e);
    for (int i = 0; i < study_scene_count(ctx) && rc == 0; ++i)
        rc = render_scene(ctx, study_scene_at(ctx, i), dir, &f, e);
    for (int i = 0; i < f.count; ++i)
        references[i] = f.references[i], aos[i] = f.aos[i];
    specular_occlusion_score_request rq = {.references = references, .reference_count = f.count, .aos = aos,
                                           .ao_count = f.count,
                                           .files = {.functions = functions, .function_count = function_count,
                                                     .plugins = plugins, .plugin_count = plugin_count,
                                                     .timeout = 10.0}};
    return rc != 0 ? -1 : specular_occlusion_score(&rq, out, e);
}
