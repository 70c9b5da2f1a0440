/* The outputs of the GTAO multi-bounce refit (multibounce_fit.h): the JSON a
 * person or a script reads, and the C header and HLSL/GLSL functions an engine
 * takes, all generated from the fitted numbers and written atomically. */
#define _GNU_SOURCE /* asprintf */
#include "multibounce/multibounce_fit.h"

#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/atomic_file.h"
#include "multibounce/multibounce_shader.h"

static const char *const kWeighting =
    "each (scene, albedo) group of pixels carries the same total weight, so every scene and every albedo "
    "counts equally whatever its pixel count; weights scaled to mean 1; residual sqrt(w) (cubic(V_d) - V'_d)";

/* An albedo as the short decimal it was given as (0.1, not 0.10000000149). */
static double albedo_value(float albedo)
{
    char text[32];
    snprintf(text, sizeof text, "%.7g", (double)albedo);
    return strtod(text, NULL);
}

static void add_errors(cJSON *o, const char *prefix, const multibounce_errors *err)
{
    char key[160];
    snprintf(key, sizeof key, "%srmse", prefix);
    cJSON_AddNumberToObject(o, key, err->rmse);
    snprintf(key, sizeof key, "%smax_abs_error", prefix);
    cJSON_AddNumberToObject(o, key, err->max_abs);
}

/* A model's a, b, c coefficients by name ("a0", "a1", ...). */
static cJSON *coefficients_json(const multibounce_model *m)
{
    multibounce_fit as_fit = {.model = *m};
    multibounce_model_to_vector(m, as_fit.params);
    cJSON *o = cJSON_CreateObject();
    for (int i = 0; i < multibounce_model_parameter_count(m->degree); ++i) {
        char name[8];
        multibounce_fit_parameter_name(&as_fit, i, name, sizeof name);
        cJSON_AddNumberToObject(o, name, as_fit.params[i]);
    }
    return o;
}

static cJSON *fit_json(const multibounce_fit *f)
{
    cJSON *o = cJSON_CreateObject();
    int n = f->parameter_count;
    cJSON *co = cJSON_AddObjectToObject(o, "coefficients"), *se = cJSON_AddObjectToObject(o, "standard_errors");
    cJSON *order = cJSON_AddArrayToObject(o, "parameter_order"), *cov = cJSON_AddArrayToObject(o, "covariance");
    for (int i = 0; i < n; ++i) {
        char name[8];
        multibounce_fit_parameter_name(f, i, name, sizeof name);
        cJSON_AddNumberToObject(co, name, f->params[i]);
        cJSON_AddNumberToObject(se, name, f->standard_errors[i]);
        cJSON_AddItemToArray(order, cJSON_CreateString(name));
        cJSON_AddItemToArray(cov, cJSON_CreateDoubleArray(f->covariance + i * n, n));
    }
    if (f->anchored) {
        cJSON_AddStringToObject(o, "form", "V'_d = V_d + V_d (1 - V_d) (rho (p1 + q1 V_d) + rho^2 (p2 + q2 V_d))");
        cJSON_AddItemToObject(o, "cubic_coefficients", coefficients_json(&f->model));
    }
    cJSON_AddNumberToObject(o, "residual_variance", f->residual_variance);
    cJSON *s = cJSON_AddObjectToObject(o, "solver");
    cJSON_AddBoolToObject(s, "converged", f->solver.success);
    cJSON_AddNumberToObject(s, "iterations", f->solver.iterations);
    cJSON_AddNumberToObject(s, "residuals", (double)f->solver.residual_count);
    return o;
}

/* Errors on all the data: with the shader's max (the function shipped) and
 * the bare cubic; and how far the cubic falls below V_d (what the max
 * changes) at albedo 0, 0.05 and the data's albedos. */
static void add_data_errors(cJSON *o, const multibounce_data *d, const multibounce_model *m,
                            const multibounce_errors err[2])
{
    add_errors(o, "", &err[1]);
    add_errors(o, "without_max_", &err[0]);
    cJSON_AddNumberToObject(o, "fraction_cubic_below_v_d_by_0.001", err[0].below);
    cJSON *worst = cJSON_AddObjectToObject(o, "max_error_sample");
    cJSON_AddStringToObject(worst, "scene", d->scenes[err[1].worst.scene]);
    cJSON_AddNumberToObject(worst, "albedo", albedo_value(err[1].worst.albedo));
    cJSON_AddNumberToObject(worst, "v_d", err[1].worst.visibility);
    cJSON_AddNumberToObject(worst, "v_prime_d", err[1].worst.multibounce);
    cJSON *list = cJSON_AddArrayToObject(o, "max_shortfall_below_v_d");
    for (int k = -2; k < d->albedo_count; ++k) {
        double rho = k == -2 ? 0.0 : k == -1 ? 0.05 : albedo_value(d->albedos[k]);
        cJSON *item = cJSON_CreateObject();
        cJSON_AddNumberToObject(item, "albedo", rho);
        cJSON_AddNumberToObject(item, "max_v_d_minus_cubic", multibounce_max_shortfall(m, rho));
        cJSON_AddItemToArray(list, item);
    }
}

static cJSON *data_json(const multibounce_data *d)
{
    cJSON *o = cJSON_CreateObject();
    cJSON *files = cJSON_AddArrayToObject(o, "files");
    for (int i = 0; i < d->file_count; ++i)
        cJSON_AddItemToArray(files, cJSON_CreateString(d->files[i]));
    cJSON_AddStringToObject(o, "bounces", d->bounces);
    cJSON_AddNumberToObject(o, "samples", (double)d->count);
    cJSON *albedos = cJSON_AddArrayToObject(o, "albedos");
    for (int a = 0; a < d->albedo_count; ++a)
        cJSON_AddItemToArray(albedos, cJSON_CreateNumber(albedo_value(d->albedos[a])));
    cJSON_AddStringToObject(o, "weighting", kWeighting);
    cJSON *scenes = cJSON_AddArrayToObject(o, "scenes");
    for (int s = 0; s < d->scene_count; ++s) {
        cJSON *sc = cJSON_CreateObject(), *groups = NULL;
        cJSON_AddStringToObject(sc, "scene", d->scenes[s]);
        groups = cJSON_AddArrayToObject(sc, "groups");
        for (int a = 0; a < d->albedo_count; ++a) {
            if (!d->group_count[s][a])
                continue;
            cJSON *g = cJSON_CreateObject();
            cJSON_AddNumberToObject(g, "albedo", albedo_value(d->albedos[a]));
            cJSON_AddNumberToObject(g, "samples", (double)d->group_count[s][a]);
            for (size_t i = 0; i < d->count; ++i)
                if (d->samples[i].scene == s && d->samples[i].albedo_index == a) {
                    cJSON_AddNumberToObject(g, "weight_per_sample", d->samples[i].weight);
                    break;
                }
            cJSON_AddItemToArray(groups, g);
        }
        cJSON_AddItemToArray(scenes, sc);
    }
    return o;
}

static cJSON *per_albedo_json(const multibounce_data *d, const multibounce_analysis *a)
{
    cJSON *list = cJSON_CreateArray();
    const multibounce_model talk = multibounce_model_jimenez2016();
    for (int k = 0; k < d->albedo_count; ++k) {
        const multibounce_albedo_result *r = &a->per_albedo[k];
        cJSON *o = fit_json(&r->fit);
        cJSON_AddNumberToObject(o, "albedo", albedo_value(r->albedo));
        cJSON_AddNumberToObject(o, "samples", (double)r->own.samples);
        add_errors(o, "", &r->own);
        add_errors(o, "joint_linear_", &r->linear);
        add_errors(o, "talk_", &r->talk);
        multibounce_cubic t = multibounce_cubic_at(&talk, r->albedo);
        cJSON *tc = cJSON_AddObjectToObject(o, "talk_coefficients");
        cJSON_AddNumberToObject(tc, "a", t.a);
        cJSON_AddNumberToObject(tc, "b", t.b);
        cJSON_AddNumberToObject(tc, "c", t.c);
        cJSON_AddItemToArray(list, o);
    }
    return list;
}

static cJSON *heldout_json(const multibounce_data *d, const multibounce_analysis *a)
{
    if (a->heldout_count == 0)
        return cJSON_CreateNull();
    cJSON *o = cJSON_CreateObject(), *means = cJSON_AddObjectToObject(o, "mean_rmse");
    for (int j = 0; j < MB_JOINT_COUNT; ++j)
        if (a->has[j])
            cJSON_AddNumberToObject(means, multibounce_joint_names[j], a->heldout_mean[j]);
    cJSON_AddNumberToObject(means, "talk", a->heldout_mean_talk);
    cJSON *list = cJSON_AddArrayToObject(o, "scenes");
    for (int i = 0; i < a->heldout_count; ++i) {
        const multibounce_heldout *h = &a->heldout[i];
        cJSON *s = cJSON_CreateObject();
        cJSON_AddStringToObject(s, "held_out", d->scenes[h->scene]);
        cJSON_AddNumberToObject(s, "samples", (double)h->talk.samples);
        for (int j = 0; j < MB_JOINT_COUNT; ++j) {
            char prefix[64];
            snprintf(prefix, sizeof prefix, "%s_", multibounce_joint_names[j]);
            if (a->has[j])
                add_errors(s, prefix, &h->err[j]);
        }
        add_errors(s, "talk_", &h->talk);
        cJSON_AddItemToObject(s, "joint_linear_coefficients", coefficients_json(&h->model[MB_JOINT_LINEAR]));
        cJSON_AddItemToArray(list, s);
    }
    return o;
}

static char *analysis_json(const multibounce_data *d, const multibounce_analysis *a, const char *command)
{
    cJSON *root = cJSON_CreateObject();
    cJSON_AddStringToObject(root, "gtlab_version", GTLAB_VERSION);
    cJSON_AddStringToObject(root, "command", command);
    cJSON_AddStringToObject(root, "model", "V'_d = max(V_d, ((a V_d + b) V_d + c) V_d), a = a0 + a1 rho (+ a2 rho^2), "
                                           "likewise b and c (Jimenez et al. 2016, GTAOMultiBounce); joint_anchored: "
                                           "the same cubic with 4 parameters, exact at rho = 0 and V_d = 0, 1");
    cJSON_AddStringToObject(root, "errors", "rmse weighted as the fit (scenes and albedos equal), max_abs_error over "
                                            "all samples; with the max(V_d, .) unless prefixed without_max_");
    cJSON_AddItemToObject(root, "data", data_json(d));
    for (int j = 0; j < MB_JOINT_COUNT; ++j) {
        if (!a->has[j]) {
            cJSON_AddNullToObject(root, multibounce_joint_names[j]);
            continue;
        }
        cJSON *o = fit_json(&a->joint[j]);
        if (a->heldout_count) {
            cJSON *jk = cJSON_AddObjectToObject(o, "jackknife_standard_errors_over_scenes");
            for (int k = 0; k < a->joint[j].parameter_count; ++k) {
                char name[8];
                multibounce_fit_parameter_name(&a->joint[j], k, name, sizeof name);
                cJSON_AddNumberToObject(jk, name, a->jackknife_se[j][k]);
            }
        }
        add_data_errors(o, d, &a->joint[j].model, a->joint_err[j]);
        cJSON_AddItemToObject(root, multibounce_joint_names[j], o);
    }
    const multibounce_model talk = multibounce_model_jimenez2016();
    cJSON *t = cJSON_CreateObject();
    cJSON_AddItemToObject(t, "coefficients", coefficients_json(&talk));
    add_data_errors(t, d, &talk, a->talk_err);
    cJSON_AddItemToObject(root, "talk_jimenez2016", t);
    cJSON_AddItemToObject(root, "per_albedo", per_albedo_json(d, a));
    cJSON *two = cJSON_AddObjectToObject(root, "two_step_talk_procedure");
    cJSON_AddStringToObject(two, "what", "the talk's procedure on our data: lines in rho fitted (unweighted) "
                                         "through the per-albedo a, b, c; for comparison with joint_linear");
    cJSON_AddItemToObject(two, "coefficients", coefficients_json(&a->two_step));
    add_errors(two, "", &a->two_step_err);
    cJSON_AddItemToObject(root, "leave_one_scene_out", heldout_json(d, a));
    cJSON *sel = cJSON_AddObjectToObject(root, "selection");
    cJSON_AddStringToObject(sel, "chosen", multibounce_joint_names[a->chosen]);
    cJSON_AddStringToObject(sel, "rule", a->heldout_count ? "lower mean leave-one-scene-out RMSE"
                                                          : "linear: held-out selection needs 2 or more scenes");
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    return text;
}

static const char *const kFunctionSuffix[MB_JOINT_COUNT] = {"Linear", "Quadratic", "Anchored"};
static const char *const kFunctionWhat[MB_JOINT_COUNT] = {
    "a, b, c linear in the albedo (the talk's form)", "a, b, c quadratic in the albedo",
    "anchored: V_d + V_d (1 - V_d) (albedo (p1 + q1 V_d) + albedo^2 (p2 + q2 V_d)), exact at albedo 0 and "
    "V_d = 0, 1"};

/* Names and comments of the functions, one per joint model fitted. */
typedef struct {
    char names[MB_JOINT_COUNT][64], comments[MB_JOINT_COUNT][512];
    multibounce_shader_function functions[MB_JOINT_COUNT];
    int count;
} generated_functions;

/* The joint models as functions: in C gtlab_multibounce_linear etc., in a
 * shader GTAOMultiBounce (the talk's linear form), GTAOMultiBounceQuadratic
 * and GTAOMultiBounceAnchored. */
static void list_functions(const multibounce_analysis *a, int c_names, generated_functions *g)
{
    g->count = 0;
    for (int j = 0; j < MB_JOINT_COUNT; ++j) {
        if (!a->has[j])
            continue;
        multibounce_shader_function *f = &g->functions[g->count];
        char *name = g->names[g->count], *comment = g->comments[g->count];
        if (c_names)
            snprintf(name, sizeof g->names[0], "gtlab_multibounce_%c%s", kFunctionSuffix[j][0] + 32,
                     kFunctionSuffix[j] + 1);
        else
            snprintf(name, sizeof g->names[0], "GTAOMultiBounce%s", j == MB_JOINT_LINEAR ? "" : kFunctionSuffix[j]);
        snprintf(comment, sizeof g->comments[0], "%s; weighted RMSE %.3g on the data.%s", kFunctionWhat[j],
                 a->joint_err[j][1].rmse, j == (int)a->chosen ? " Preferred by the leave-one-scene-out test." : "");
        *f = (multibounce_shader_function){.name = name, .comment = comment, .model = a->joint[j].model};
        g->count++;
    }
}

static char *header_text(const multibounce_analysis *a, const char *command)
{
    char *preamble = NULL;
    if (asprintf(&preamble,
                 "/* GTAO multi-bounce, refitted by gtlab %s:\n *   %s\n"
                 " * V'_d = max(V_d, ((a V_d + b) V_d + c) V_d) with a, b, c polynomials in the albedo\n"
                 " * (Jimenez et al. 2016). Generated file: edit the data, not the numbers. The formula is\n"
                 " * techniques/multibounce/multibounce.inc, the very text gtlab compiles as C, behind the definitions below. */\n",
                 GTLAB_VERSION, command) < 0)
        return NULL;
    generated_functions g;
    list_functions(a, 1, &g);
    char *text = multibounce_c_header_source(preamble, "GTLAB_MULTIBOUNCE_FIT_H", g.functions, g.count);
    free(preamble);
    return text;
}

/* The shader functions, HLSL or GLSL. */
static char *shader_text(const multibounce_analysis *a, const char *command, shader_language language)
{
    char *preamble = NULL;
    if (asprintf(&preamble,
                 "// GTAO multi-bounce, refitted by gtlab %s:\n//   %s\n"
                 "// Same form as GTAOMultiBounce (Jimenez et al. 2016), new coefficients. Generated file.\n"
                 "// The formula is techniques/multibounce/multibounce.inc, the very text gtlab compiles as C, behind the\n"
                 "// definitions below.\n",
                 GTLAB_VERSION, command) < 0)
        return NULL;
    generated_functions g;
    list_functions(a, 0, &g);
    char *text = multibounce_shader_source(language, preamble, g.functions, g.count);
    free(preamble);
    return text;
}

static int write_owned_text(const char *path, char *text, gt_error *e)
{
    if (!text)
        return gt_error_set(e, path, "out of memory");
    int rc = atomic_write_text(path, text, e);
    free(text);
    return rc;
}

int multibounce_write_outputs(const multibounce_data *d, const multibounce_analysis *a, const char *command,
                              const char *json_path, const char *header_path, const char *hlsl_path,
                              const char *glsl_path, gt_error *e)
{
    if (write_owned_text(json_path, analysis_json(d, a, command), e) != 0)
        return -1;
    if (header_path && write_owned_text(header_path, header_text(a, command), e) != 0)
        return -1;
    if (hlsl_path && write_owned_text(hlsl_path, shader_text(a, command, SHADER_HLSL), e) != 0)
        return -1;
    if (glsl_path && write_owned_text(glsl_path, shader_text(a, command, SHADER_GLSL), e) != 0)
        return -1;
    return 0;
}

/* json without a trailing ".json", with `extension` appended. */
static void sibling_path(const char *json, const char *extension, char *out, size_t size)
{
    size_t n = strlen(json);
    if (n > 5 && strcmp(json + n - 5, ".json") == 0)
        n -= 5;
    snprintf(out, size, "%.*s%s", (int)n, json, extension);
}

int multibounce_output_files_resolve(multibounce_output_files *f, gt_error *e)
{
    const char **paths[3] = {&f->header, &f->hlsl, &f->glsl}, *extensions[3] = {".h", ".hlsl", ".glsl"};
    for (int i = 0; i < 3; ++i)
        if (!*paths[i]) {
            sibling_path(f->json, extensions[i], f->sibling[i], sizeof f->sibling[i]);
            *paths[i] = f->sibling[i];
        }
    if (atomic_file_check_writable(f->json, e) != 0)
        return -1;
    for (int i = 0; i < 3; ++i)
        if (atomic_file_check_writable(*paths[i], e) != 0)
            return -1;
    return 0;
}

static void print_fit(FILE *out, const char *title, const multibounce_fit *f, const multibounce_errors *err)
{
    fprintf(out, "%s (RMSE %.4g, max |error| %.4g):\n ", title, err->rmse, err->max_abs);
    for (int i = 0; i < f->parameter_count; ++i) {
        char name[8];
        multibounce_fit_parameter_name(f, i, name, sizeof name);
        fprintf(out, " %s = %.5f (±%.5f)", name, f->params[i], f->standard_errors[i]);
    }
    fprintf(out, "\n");
}

void multibounce_analysis_print(FILE *out, const multibounce_data *d, const multibounce_analysis *a)
{
    fprintf(out, "%zu samples: %d scenes, %d albedos, --bounces %s\n", d->count, d->scene_count, d->albedo_count,
           d->bounces);
    for (int j = 0; j < MB_JOINT_COUNT; ++j)
        if (a->has[j])
            print_fit(out, multibounce_joint_names[j], &a->joint[j], &a->joint_err[j][1]);
    fprintf(out, "talk's coefficients on the same data: RMSE %.4g, max |error| %.4g\n", a->talk_err[1].rmse,
           a->talk_err[1].max_abs);
    if (a->heldout_count) {
        fprintf(out, "leave-one-scene-out mean RMSE:");
        for (int j = 0; j < MB_JOINT_COUNT; ++j)
            if (a->has[j])
                fprintf(out, " %s %.4g,", multibounce_joint_names[j], a->heldout_mean[j]);
        fprintf(out, " talk %.4g; chosen: %s\n", a->heldout_mean_talk, multibounce_joint_names[a->chosen]);
    }
}
