/* gtlab fit sphere-light: refits Decima's sphere-light radius reduction and
 * normalisation (SIGGRAPH 2017, appendix "Spherical Area Lighting": "still
 * in flux ... to better match our reference") to gtlab's Monte Carlo
 * reference (studies/sphere_light.h), and writes the constants for an
 * engine: JSON, a C header, and HLSL/GLSL generated from the C's own source
 * (realtime/sphere_light_shader.h). */
#include "cli/fit_sphere_light.h"

#include <cjson/cJSON.h>
#include <getopt.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/report_table.h"
#include "core/atomic_file.h"
#include "realtime/sphere_light_shader.h"

static const report_column error_columns[] = {
    REPORT_REAL(NULL, "mean_abs_log_error", NULL, sphere_light_errors, mean_abs),
    REPORT_REAL(NULL, "mean_abs_log_error_stderr", NULL, sphere_light_errors, mean_abs_stderr),
    REPORT_REAL(NULL, "rms_log_error", NULL, sphere_light_errors, rms),
    REPORT_REAL(NULL, "rms_log_error_stderr", NULL, sphere_light_errors, rms_stderr),
};

static void add_held_out(cJSON *parent, const sphere_fit_outcome *o)
{
    for (int m = 0; m < SPHERE_FIT_MODELS; ++m)
        report_object(parent, o->held_out[m].key, error_columns, 4, &o->held_out[m].errors);
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
             " * (realtime/sphere_light.h). Standard errors in the comments. */\n"
             "#ifndef GTLAB_SPHERE_LIGHT_FIT_H\n#define GTLAB_SPHERE_LIGHT_FIT_H\n\n"
             "#include \"realtime/sphere_light.h\"\n\n"
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

static void print_outcome(const sphere_fit_settings *s, const sphere_fit_outcome *o)
{
    printf("fitted on %d configurations (%s, %d iterations):\n", s->train,
           o->fit.converged ? "converged" : "NOT converged", o->fit.iterations);
    for (int j = 0; j < SPHERE_FIT_PARAMS; ++j)
        printf("  %-17s %10.5g +- %-9.2g (published %g)\n", o->constants[j].name, o->constants[j].value,
               o->constants[j].stderr_, o->constants[j].published);
    printf("held-out error, ln((model + 0.01)/(reference + 0.01)) over %d configurations:\n", s->test);
    const char *names[SPHERE_FIT_MODELS] = {"Karis", "Decima published", "Decima refit"};
    for (int m = 0; m < SPHERE_FIT_MODELS; ++m) {
        const sphere_light_errors *x = &o->held_out[m].errors;
        printf("  %-17s mean |error| %.4f +- %.4f, RMS %.4f +- %.4f\n", names[m], x->mean_abs, x->mean_abs_stderr,
               x->rms, x->rms_stderr);
    }
    printf("reference noise: mean relative standard error %.4f\n", o->mean_reference_rel_stderr);
}

static void print_help(void)
{
    printf("usage: gtlab fit sphere-light -o fit.json [--train N] [--test N] [--samples S] [--seed S]\n"
           "                              [--threads T]\n"
           "\n"
           "Refits the radius reduction and the normalisation constants of Decima's\n"
           "EvaluateSphericalAreaGGX (SIGGRAPH 2017 appendix; published 0.25, 0.25, 3.0) to Monte\n"
           "Carlo references of a GGX surface under a uniform spherical light, over a realistic\n"
           "distribution of roughness (0.05-1), angular size (the sun's to 30 deg), view angle and\n"
           "light direction (mostly near the mirror direction, where highlights are). The error is\n"
           "ln((model + 0.01) / (reference + 0.01)) in 1/sr per unit normal illuminance: relative\n"
           "where the highlight is. Errors of Karis's, the published and the refitted constants are\n"
           "measured on held-out configurations, with standard errors. The radius reduction is\n"
           "profiled (held on a grid while the normalisation is fitted: the cost is rugged in it);\n"
           "its value and standard error come from a parabola through the profile. Writes\n"
           "  fit.json    values, standard errors, covariance, errors before/after, data used\n"
           "  fit.h       the constants for realtime/sphere_light.h (C)\n"
           "  fit.hlsl    GetNoHSquared (corrected) and EvaluateSphericalAreaGGX with the constants\n"
           "  fit.glsl    the same for GLSL\n"
           "\n"
           "  -o, --output F.json   where to write (the others beside it)\n"
           "  --train N     configurations fitted (default 8000)\n"
           "  --test N      held-out configurations (default 4000)\n"
           "  --samples S   MIS samples per reference (default 1024)\n"
           "  --seed S      seed of the configurations and samples (default 1)\n"
           "  --threads T   threads (default: all cores; results do not depend on it)\n");
}

int fit_sphere_light(int argc, char **argv)
{
    static const struct option longs[] = {
        {"output", required_argument, 0, 'o'}, {"train", required_argument, 0, 'n'},
        {"test", required_argument, 0, 'm'},   {"samples", required_argument, 0, 's'},
        {"seed", required_argument, 0, 'S'},   {"threads", required_argument, 0, 't'},
        {"help", no_argument, 0, 'h'},         {0, 0, 0, 0}};
    const char *output = NULL;
    long train = 8000, test = 4000, samples = 1024, threads = omp_get_num_procs();
    uint32_t seed = 1;
    int c;
    while ((c = getopt_long(argc, argv, "o:h", longs, NULL)) != -1) {
        switch (c) {
        case 'o': output = optarg; break;
        case 'n': if (cli_parse_int("--train", optarg, 16, 10000000, &train)) return EXIT_USER_ERROR; break;
        case 'm': if (cli_parse_int("--test", optarg, 16, 10000000, &test)) return EXIT_USER_ERROR; break;
        case 's': if (cli_parse_int("--samples", optarg, 2, 1 << 24, &samples)) return EXIT_USER_ERROR; break;
        case 'S': if (cli_parse_u32("--seed", optarg, &seed)) return EXIT_USER_ERROR; break;
        case 't': if (cli_parse_int("--threads", optarg, 1, 1024, &threads)) return EXIT_USER_ERROR; break;
        case 'h': print_help(); return EXIT_OK;
        default: return cli_usage_error("fit sphere-light");
        }
    }
    if (optind < argc)
        return cli_failf("fit sphere-light", "unexpected argument '%s'", argv[optind]);
    if (!output)
        return cli_failf("fit sphere-light", "no output given (-o fit.json)");
    sphere_fit_settings s = {(int)train, (int)test, (uint32_t)samples, seed, (int)threads};
    static sphere_fit_outcome o;
    gt_error e;
    if (sphere_fit_check_writable(output, &e) != 0 || sphere_fit_study(&s, &o, &e) != 0 ||
        sphere_fit_write(&s, &o, output, &e) != 0)
        return cli_fail(&e);
    print_outcome(&s, &o);
    printf("written: %s and its .h, .hlsl, .glsl (%.1f s)\n", output, o.seconds);
    return EXIT_OK;
}
