/* The files of the sphere-light refit (fit_sphere_light_outputs.h): JSON,
 * C header, HLSL and GLSL, written atomically. */
#include "sphere_light/sphere_light_fit_outputs.h"

#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/atomic_file.h"
#include "sphere_light/sphere_light_shader.h"

/* Each model's held-out errors as an object under its key. */
static void add_held_out(cJSON *parent, const sphere_fit_outcome *o)
{
    for (int m = 0; m < SPHERE_FIT_MODELS; ++m) {
        const sphere_light_errors *x = &o->held_out[m].errors;
        cJSON *row = cJSON_AddObjectToObject(parent, o->held_out[m].key);
        cJSON_AddNumberToObject(row, "mean_abs_log_error", x->mean_abs);
        cJSON_AddNumberToObject(row, "mean_abs_log_error_stderr", x->mean_abs_stderr);
        cJSON_AddNumberToObject(row, "rms_log_error", x->rms);
        cJSON_AddNumberToObject(row, "rms_log_error_stderr", x->rms_stderr);
    }
}

static int write_json(const char *path, const sphere_fit_settings *s, const sphere_fit_outcome *o, gt_error *e)
{
    cJSON *root = cJSON_CreateObject();
    cJSON_AddStringToObject(root, "problem", "sphere-light");
    cJSON_AddStringToObject(root, "gtlab_version", GTLAB_VERSION);
    cJSON_AddStringToObject(root, "model",
                            "EvaluateSphericalAreaGGX (Decima 2017): radius_tan = max(0.001, R/d - radius_reduction "
                            "alpha); normalization = a2 (l.h + 0.001) / (a2 (l.h + 0.001) + norm_scale R/d "
                            "(norm_alpha alpha + R/d)); GetNoHSquared with one Newton step");
    cJSON_AddStringToObject(root, "residual", "ln((model + 0.01) / (reference + 0.01)), both in 1/sr per unit "
                                              "normal illuminance, white specular");
    cJSON *values = cJSON_AddObjectToObject(root, "values"), *errs = cJSON_AddObjectToObject(root, "standard_errors");
    cJSON *published = cJSON_AddObjectToObject(root, "published_values");
    cJSON *cov = cJSON_AddArrayToObject(root, "covariance");
    for (int j = 0; j < SPHERE_FIT_PARAMS; ++j) {
        const sphere_fit_constant *k = &o->constants[j];
        cJSON_AddNumberToObject(values, k->name, k->value);
        cJSON_AddNumberToObject(errs, k->name, k->stderr_);
        cJSON_AddNumberToObject(published, k->name, k->published);
        cJSON *row = cJSON_CreateDoubleArray(o->fit.covariance + j * SPHERE_FIT_PARAMS, SPHERE_FIT_PARAMS);
        cJSON_AddItemToArray(cov, row);
    }
    cJSON_AddStringToObject(root, "method",
                            "the radius reduction is profiled (held on a grid, the normalisation fitted; coarse "
                            "0..0.45 by 0.05, then by 0.01 around the best): its value and standard error are the "
                            "vertex and curvature of a least-squares parabola through the fine points (the cost is "
                            "not smooth in it: Levenberg-Marquardt stops in small local minima); the "
                            "normalisation's constants and standard errors are Ceres' with it held there");
    cJSON *profile = cJSON_AddArrayToObject(root, "radius_reduction_profile");
    for (int k = 0; k < SPHERE_FIT_PROFILE; ++k) {
        cJSON *point = cJSON_CreateObject();
        cJSON_AddNumberToObject(point, "radius_reduction", o->fit.profile_reduction[k]);
        cJSON_AddNumberToObject(point, "cost", o->fit.profile_cost[k]);
        cJSON_AddItemToArray(profile, point);
    }
    cJSON_AddNumberToObject(root, "residual_rmse", o->fit.rmse);
    cJSON_AddNumberToObject(root, "iterations", o->fit.iterations);
    cJSON_AddBoolToObject(root, "converged", o->fit.converged);
    cJSON *data = cJSON_AddObjectToObject(root, "data");
    cJSON_AddNumberToObject(data, "train_configurations", s->train);
    cJSON_AddNumberToObject(data, "test_configurations", s->test);
    cJSON_AddNumberToObject(data, "mc_samples_per_configuration", s->mc_samples);
    cJSON_AddNumberToObject(data, "seed", s->seed);
    cJSON_AddStringToObject(data, "distribution",
                            "roughness U[0.05,1]; sin(sigma) log-uniform [0.00465, 0.5]; n.v U[0.05,1]; light centre "
                            "70% within 2(alpha+sigma) of R, 30% cosine-distributed; centre >= 1 deg above horizon");
    cJSON_AddNumberToObject(data, "mean_reference_relative_stderr", o->mean_reference_rel_stderr);
    add_held_out(cJSON_AddObjectToObject(root, "held_out_errors"), o);
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    if (!text)
        return gt_error_set(e, path, "out of memory");
    int rc = atomic_write_text(path, text, e);
    free(text);
    return rc;
}

static int write_shader(const char *path, shader_language language, const decima_sphere_constants *k, gt_error *e)
{
    char *text = sphere_light_shader_source(language, k, "gtlab " GTLAB_VERSION " ('gtlab fit sphere-light')");
    int rc = text ? atomic_write_text(path, text, e) : gt_error_set(e, path, "out of memory");
    free(text);
    return rc;
}

static int write_c_header(const char *path, const sphere_fit_outcome *o, gt_error *e)
{
    char text[2048];
    const double *v = o->fit.value, *se = o->fit.stderr_;
    snprintf(text, sizeof text,
             "/* Generated by gtlab %s ('gtlab fit sphere-light'): Decima's sphere-light radius reduction and\n"
             " * normalisation refitted to Monte Carlo references; use with decima_sphere_ggx()\n"
             " * (techniques/sphere_light/sphere_light.h). Standard errors in the comments. */\n"
             "#ifndef GTLAB_SPHERE_LIGHT_FIT_H\n#define GTLAB_SPHERE_LIGHT_FIT_H\n\n"
             "#include \"sphere_light/sphere_light.h\"\n\n"
             "static const decima_sphere_constants gtlab_sphere_light_fit = {\n"
             "    %.9gf, /* radius_reduction, +- %.2g */\n"
             "    %.9gf, /* norm_scale, +- %.2g */\n"
             "    %.9gf, /* norm_alpha, +- %.2g */\n"
             "    0.001f, 0.001f /* norm_eps, min_radius_tan: as published */\n};\n\n#endif\n",
             GTLAB_VERSION, v[0], se[0], v[1], se[1], v[2], se[2]);
    return atomic_write_text(path, text, e);
}

/* path with its extension (after the last '.' of the file name) replaced. */
static void sibling(const char *path, const char *ext, char *out, size_t size)
{
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    int stem = dot && (!slash || dot > slash) ? (int)(dot - path) : (int)strlen(path);
    snprintf(out, size, "%.*s%s", stem, path, ext);
}

int sphere_fit_check_writable(const char *json_path, gt_error *e)
{
    char header[4096];
    sibling(json_path, ".h", header, sizeof header);
    return atomic_file_check_writable(json_path, e) != 0 || atomic_file_check_writable(header, e) != 0 ? -1 : 0;
}

int sphere_fit_write(const sphere_fit_settings *s, const sphere_fit_outcome *o, const char *json_path, gt_error *e)
{
    char header[4096], hlsl[4096], glsl[4096];
    sibling(json_path, ".h", header, sizeof header);
    sibling(json_path, ".hlsl", hlsl, sizeof hlsl);
    sibling(json_path, ".glsl", glsl, sizeof glsl);
    if (write_json(json_path, s, o, e) != 0 || write_c_header(header, o, e) != 0 ||
        write_shader(hlsl, SHADER_HLSL, &o->fit.constants, e) != 0 ||
        write_shader(glsl, SHADER_GLSL, &o->fit.constants, e) != 0)
        return -1;
    return 0;
}
