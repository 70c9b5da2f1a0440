/* gtlab fit sphere-light: refits Decima's sphere-light radius reduction and
 * normalisation (SIGGRAPH 2017, appendix "Spherical Area Lighting": "still
 * in flux ... to better match our reference") to gtlab's Monte Carlo
 * reference, and writes the constants for an engine. */
#define _GNU_SOURCE
#include "cli/fit_sphere_light.h"

#include <cjson/cJSON.h>
#include <getopt.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "core/atomic_file.h"
#include "core/progress.h"
#include "core/sobol.h"
#include "raytracer/sphere_light_reference.h"

#define SUN_SIN_SIGMA 0.00465 /* the sun seen from the earth */
#define MAX_SIN_SIGMA 0.5

static double uniform01(uint32_t seed, uint32_t i, uint32_t k)
{
    return hash_combine(hash_combine(seed, i), k) * 0x1p-32;
}

/* Configuration i of the realistic distribution: roughness uniform in
 * [0.05, 1], sin(sigma) log-uniform from the sun's to 0.5 (30 deg), n.v
 * uniform in [0.05, 1]; the light's centre 70% of the time within
 * 2 (alpha + sigma) of the mirror direction (where highlights are: a
 * uniform choice would fill the data with dark configurations), otherwise
 * cosine-distributed over the hemisphere; always 1 deg or more above the
 * horizon (Decima's term is 0 once the centre is below). */
static sphere_light_config realistic_config(uint32_t seed, uint32_t i)
{
    double roughness = 0.05 + 0.95 * uniform01(seed, i, 0);
    double sin_sigma = SUN_SIN_SIGMA * pow(MAX_SIN_SIGMA / SUN_SIN_SIGMA, uniform01(seed, i, 1));
    double n_dot_v = 0.05 + 0.95 * uniform01(seed, i, 2);
    double u4 = uniform01(seed, i, 4), u5 = uniform01(seed, i, 5);
    if (uniform01(seed, i, 3) < 0.7) {
        double delta = 2.0 * (roughness * roughness + asin(sin_sigma)) * sqrt(u4);
        return sphere_light_config_near_mirror(n_dot_v, delta, 2.0 * M_PI * u5, sin_sigma, roughness);
    }
    double theta = fmin(acos(sqrt(u4)), 0.5 * M_PI - M_PI / 180.0);
    return sphere_light_config_make(n_dot_v, theta, 2.0 * M_PI * u5, sin_sigma, roughness);
}

/* count configurations from index first, with their references. */
static int make_samples(uint32_t seed, uint32_t first, int count, uint32_t mc_samples, int threads,
                        sphere_light_sample **out, gt_error *e)
{
    sphere_light_sample *s = malloc((size_t)count * sizeof *s);
    if (!s)
        return gt_error_set(e, "fit sphere-light", "out of memory");
    progress bar;
    progress_begin(&bar, "sphere-light references", count);
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
    for (int i = 0; i < count; ++i) {
        sphere_light_config c = realistic_config(seed, first + (uint32_t)i);
        sphere_light_estimate est;
        sphere_light_reference(&c, mc_samples, hash_combine(seed ^ 0x9e3779b9u, first + (uint32_t)i), &est);
        double e_perp = sphere_light_normal_illuminance(c.sin_sigma);
        s[i].v = c.v, s[i].lc = c.lc;
        s[i].sin_sigma = (float)c.sin_sigma, s[i].alpha = (float)c.alpha;
        s[i].reference = est.spec / e_perp, s[i].reference_stderr = est.spec_stderr / e_perp;
        progress_advance(&bar, 1);
    }
    progress_end(&bar);
    *out = s;
    return 0;
}

static void add_errors(cJSON *parent, const char *name, const sphere_light_errors *x)
{
    cJSON *o = cJSON_AddObjectToObject(parent, name);
    cJSON_AddNumberToObject(o, "mean_abs_log_error", x->mean_abs);
    cJSON_AddNumberToObject(o, "mean_abs_log_error_stderr", x->mean_abs_stderr);
    cJSON_AddNumberToObject(o, "rms_log_error", x->rms);
    cJSON_AddNumberToObject(o, "rms_log_error_stderr", x->rms_stderr);
}

static const char *param_names[SPHERE_FIT_PARAMS] = {"radius_reduction", "norm_scale", "norm_alpha"};

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
    decima_sphere_constants pub = decima_sphere_published();
    const double pub_values[SPHERE_FIT_PARAMS] = {pub.radius_reduction, pub.norm_scale, pub.norm_alpha};
    cJSON *cov = cJSON_AddArrayToObject(root, "covariance");
    for (int j = 0; j < SPHERE_FIT_PARAMS; ++j) {
        cJSON_AddNumberToObject(values, param_names[j], o->fit.value[j]);
        cJSON_AddNumberToObject(errs, param_names[j], o->fit.stderr_[j]);
        cJSON_AddNumberToObject(published, param_names[j], pub_values[j]);
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
    cJSON *held = cJSON_AddObjectToObject(root, "held_out_errors");
    add_errors(held, "karis", &o->karis);
    add_errors(held, "decima_published", &o->published);
    add_errors(held, "decima_refit", &o->refit);
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    if (!text)
        return gt_error_set(e, path, "out of memory");
    int rc = atomic_write_text(path, text, e);
    free(text);
    return rc;
}

/* The corrected GetNoHSquared and EvaluateSphericalAreaGGX in HLSL; GLSL
 * gets the same text behind a few definitions. %1$s..%3$s: the constants. */
static const char shader_body[] =
    "// Generated by gtlab " GTLAB_VERSION " ('gtlab fit sphere-light'): Decima's EvaluateSphericalAreaGGX\n"
    "// (de Carpentier & Ishiyama, SIGGRAPH 2017, appendix 'Spherical Area Lighting') with its radius\n"
    "// reduction and normalisation refitted to Monte Carlo references, and GetNoHSquared's Newton\n"
    "// step as derived in gtlab (realtime/sphere_light.c; both transcriptions of the talk are garbled).\n"
    "static const float SPHERE_RADIUS_REDUCTION = %1$.9g;\n"
    "static const float SPHERE_NORM_SCALE = %2$.9g;\n"
    "static const float SPHERE_NORM_ALPHA = %3$.9g;\n"
    "static const float SPHERE_PI = 3.14159265;\n"
    "\n"
    "float GetNoHSquared(float radiusTan, float NoL, float NoV, float VoL)\n"
    "{\n"
    "    float radiusCos = rsqrt(1.0 + radiusTan * radiusTan);\n"
    "    float RoL = 2.0 * NoL * NoV - VoL;\n"
    "    if (RoL >= radiusCos)\n"
    "        return 1.0;\n"
    "    float rOverLengthT = radiusCos * radiusTan * rsqrt(max(1.0 - RoL * RoL, 1e-30));\n"
    "    float NoTr = rOverLengthT * (NoV - RoL * NoL);\n"
    "    float VoTr = rOverLengthT * (2.0 * NoV * NoV - 1.0 - RoL * VoL);\n"
    "    float triple = sqrt(saturate(1.0 - NoL * NoL - NoV * NoV - VoL * VoL + 2.0 * NoL * NoV * VoL));\n"
    "    float NoBr = rOverLengthT * triple, VoBr = rOverLengthT * (2.0 * triple * NoV);\n"
    "    float NoLVTr = NoL * radiusCos + NoV + NoTr, VoLVTr = VoL * radiusCos + 1.0 + VoTr;\n"
    "    float p = NoBr * VoLVTr, q = NoLVTr * VoLVTr, s = VoBr * NoLVTr;\n"
    "    float xNum = q * (-0.5 * p + 0.25 * VoBr * NoLVTr);\n"
    "    float xDenom = p * p + s * (s - 2.0 * p) + NoLVTr * ((NoL * radiusCos + NoV) * VoLVTr * VoLVTr\n"
    "                 + q * (-0.5 * (VoLVTr + VoL * radiusCos) - 0.5));\n"
    "    float twoX1 = 2.0 * xNum / max(xDenom * xDenom + xNum * xNum, 1e-30);\n"
    "    float sinTheta = twoX1 * xDenom;\n"
    "    float cosTheta = 1.0 - twoX1 * xNum;\n"
    "    NoTr = cosTheta * NoTr + sinTheta * NoBr;\n"
    "    VoTr = cosTheta * VoTr + sinTheta * VoBr;\n"
    "    float newNoL = NoL * radiusCos + NoTr;\n"
    "    float newVoL = VoL * radiusCos + VoTr;\n"
    "    float NoH = NoV + newNoL;\n"
    "    float HoH = 2.0 * newVoL + 2.0;\n"
    "    return max(0.0, NoH * NoH / HoH);\n"
    "}\n"
    "\n"
    "// Height-correlated Smith G2 / (4 n.l n.v).\n"
    "float GetGGXVisibility(float NoV, float NoL, float alpha)\n"
    "{\n"
    "    float a2 = alpha * alpha;\n"
    "    float lv = NoL * sqrt(NoV * NoV * (1.0 - a2) + a2);\n"
    "    float ll = NoV * sqrt(NoL * NoL * (1.0 - a2) + a2);\n"
    "    return 0.5 / (lv + ll);\n"
    "}\n"
    "\n"
    "// light_radius_over_distance = R / d of the sphere light; l_dot_h with h = normalize(l + v), l to the centre.\n"
    "float3 EvaluateSphericalAreaGGX(float n_dot_l, float n_dot_v, float v_dot_l, float l_dot_h,\n"
    "                                float light_radius_over_distance, float alpha, float3 fresnel0)\n"
    "{\n"
    "    if (n_dot_l <= 0.0 || n_dot_v <= 0.0)\n"
    "        return float3(0.0, 0.0, 0.0);\n"
    "    float radius_tan = max(0.001, light_radius_over_distance - SPHERE_RADIUS_REDUCTION * alpha);\n"
    "    float n_dot_h_squared = GetNoHSquared(radius_tan, n_dot_l, n_dot_v, v_dot_l);\n"
    "    float alpha_squared = alpha * alpha;\n"
    "    float partial_denom = n_dot_h_squared * (alpha_squared - 1.0) + 1.0;\n"
    "    float density = alpha_squared / (SPHERE_PI * partial_denom * partial_denom);\n"
    "    float visibility = GetGGXVisibility(n_dot_v, n_dot_l, alpha);\n"
    "    float m = 1.0 - l_dot_h, m2 = m * m;\n"
    "    float3 fresnel = fresnel0 + (1.0 - fresnel0) * (m2 * m2 * m);\n"
    "    float3 brdf = density * visibility * fresnel;\n"
    "    float alpha_squared_l_dot_h = alpha_squared * (l_dot_h + 0.001);\n"
    "    float normalization = alpha_squared_l_dot_h / (alpha_squared_l_dot_h + SPHERE_NORM_SCALE\n"
    "                        * light_radius_over_distance * (SPHERE_NORM_ALPHA * alpha + light_radius_over_distance));\n"
    "    return normalization * brdf * saturate(n_dot_l);\n"
    "}\n";

static const char glsl_preamble[] =
    "// GLSL: the HLSL below compiles behind these definitions.\n"
    "#define float3 vec3\n#define rsqrt inversesqrt\n#define static\n"
    "float saturate(float x) { return clamp(x, 0.0, 1.0); }\n\n";

static int write_shader(const char *path, const char *preamble, const double *v, gt_error *e)
{
    char *text = NULL;
    if (asprintf(&text, "%s", preamble) < 0)
        return gt_error_set(e, path, "out of memory");
    char *body = NULL;
    if (asprintf(&body, shader_body, v[0], v[1], v[2]) < 0) {
        free(text);
        return gt_error_set(e, path, "out of memory");
    }
    char *all = NULL;
    int rc = asprintf(&all, "%s%s", text, body) < 0 ? gt_error_set(e, path, "out of memory")
                                                     : atomic_write_text(path, all, e);
    free(text), free(body), free(all);
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

int sphere_fit_run(const sphere_fit_settings *s, const char *json_path, sphere_fit_outcome *out, gt_error *e)
{
    char header[4096], hlsl[4096], glsl[4096];
    sibling(json_path, ".h", header, sizeof header);
    sibling(json_path, ".hlsl", hlsl, sizeof hlsl);
    sibling(json_path, ".glsl", glsl, sizeof glsl);
    if (atomic_file_check_writable(json_path, e) != 0 || atomic_file_check_writable(header, e) != 0)
        return -1;
    double t0 = seconds_now();
    sphere_light_sample *train = NULL, *test = NULL;
    int rc = -1;
    if (make_samples(s->seed, 0, s->train, s->mc_samples, s->threads, &train, e) != 0 ||
        make_samples(s->seed, (uint32_t)s->train, s->test, s->mc_samples, s->threads, &test, e) != 0)
        goto done;
    decima_sphere_constants start = decima_sphere_published();
    if (sphere_light_fit(train, (size_t)s->train, &start, s->threads, &out->fit, e) != 0)
        goto done;
    sphere_light_measure(SPHERE_MODEL_KARIS, NULL, test, (size_t)s->test, &out->karis);
    sphere_light_measure(SPHERE_MODEL_DECIMA, &start, test, (size_t)s->test, &out->published);
    sphere_light_measure(SPHERE_MODEL_DECIMA, &out->fit.constants, test, (size_t)s->test, &out->refit);
    double rel = 0.0;
    for (int i = 0; i < s->test; ++i)
        rel += test[i].reference_stderr / (test[i].reference + SPHERE_FIT_FLOOR);
    out->mean_reference_rel_stderr = rel / s->test;
    out->seconds = seconds_now() - t0;
    const char *hlsl_preamble = "";
    if (write_json(json_path, s, out, e) != 0 || write_c_header(header, out, e) != 0 ||
        write_shader(hlsl, hlsl_preamble, out->fit.value, e) != 0 ||
        write_shader(glsl, glsl_preamble, out->fit.value, e) != 0)
        goto done;
    rc = 0;
done:
    free(train), free(test);
    return rc;
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
    sphere_fit_outcome o;
    gt_error e;
    if (sphere_fit_run(&s, output, &o, &e) != 0)
        return cli_fail(&e);
    decima_sphere_constants pub = decima_sphere_published();
    const double pub_values[SPHERE_FIT_PARAMS] = {pub.radius_reduction, pub.norm_scale, pub.norm_alpha};
    printf("fitted on %d configurations (%s, %d iterations):\n", s.train,
           o.fit.converged ? "converged" : "NOT converged", o.fit.iterations);
    for (int j = 0; j < SPHERE_FIT_PARAMS; ++j)
        printf("  %-17s %10.5g +- %-9.2g (published %g)\n", param_names[j], o.fit.value[j], o.fit.stderr_[j],
               pub_values[j]);
    printf("held-out error, ln((model + 0.01)/(reference + 0.01)) over %d configurations:\n", s.test);
    const char *names[3] = {"Karis", "Decima published", "Decima refit"};
    const sphere_light_errors *errs[3] = {&o.karis, &o.published, &o.refit};
    for (int m = 0; m < 3; ++m)
        printf("  %-17s mean |error| %.4f +- %.4f, RMS %.4f +- %.4f\n", names[m], errs[m]->mean_abs,
               errs[m]->mean_abs_stderr, errs[m]->rms, errs[m]->rms_stderr);
    printf("reference noise: mean relative standard error %.4f\n", o.mean_reference_rel_stderr);
    printf("written: %s and its .h, .hlsl, .glsl (%.1f s)\n", output, o.seconds);
    return EXIT_OK;
}
