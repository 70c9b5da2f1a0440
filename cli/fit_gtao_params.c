/* gtlab fit gtao-params: GTAO's world radius (as a fraction of the camera's
 * distance to its target), falloff and thickness fitted to 3-D ray-traced AO
 * references through the Ceres bridge (Jacobian by finite differences at
 * steps a float renderer resolves), scored before
 * and after on held-out scenes. The residuals are per-pixel differences
 * (least squares, i.e. RMSE); DSSIM is reported beside it. */
#include <cjson/cJSON.h>
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/approx_io.h"
#include "cli/cli.h"
#include "core/atomic_file.h"
#include "fitters/ceres_bridge.h"
#include "metrics/image_error.h"
#include "metrics/ssim.h"
#include "realtime/gtao.h"

enum { PARAM_RADIUS, PARAM_FALLOFF, PARAM_THICKNESS, PARAM_COUNT, MAX_SCENES = 16 };
static const char *const param_names[PARAM_COUNT] = {"radius_over_camera_distance", "falloff", "thickness"};

static void print_help(void)
{
    printf("usage: gtlab fit gtao-params --refs DIR --train A,B,.. --test C,.. [options] -o fit.json\n"
           "\n"
           "Fits GTAO's radius (a fraction of each camera's distance to its target), falloff\n"
           "and thickness so GTAO matches 3-D ray-traced AO references (least squares over\n"
           "the pixels of the training scenes, Ceres; derivatives by finite differences of\n"
           "0.01 in each parameter), and reports\n"
           "RMSE and DSSIM before and after on the training and the held-out scenes.\n"
           "\n"
           "  --refs DIR        folder of AO references <scene>.exr with their G-buffer and\n"
           "                    camera (e.g. the ao/ folder 'gtlab all' writes)\n"
           "  --train LIST      scenes to fit on, comma-separated (default boxes,corner,cornell)\n"
           "  --test LIST       held-out scenes (default menger,sphere-on-plane)\n"
           "  --preset P        GTAO preset (default high)\n"
           "  -o, --output F    fit JSON: values, standard errors, scores before and after\n"
           "  -h, --help\n");
}

typedef struct {
    approx_input in;
    char name[64];
    float distance;
    gtao_params base;
} fit_scene;

static gtao_params scene_params(const fit_scene *s, const double *p)
{
    gtao_params q = s->base;
    q.radius = (float)p[PARAM_RADIUS] * s->distance;
    q.falloff = (float)p[PARAM_FALLOFF];
    q.thickness = (float)p[PARAM_THICKNESS];
    return q;
}

static int run_gtao(const fit_scene *s, const double *p, float *ao)
{
    gtao_params q = scene_params(s, p);
    return gtao_render(&s->in.g, &q, ao, NULL);
}

static int covered_count(const fit_scene *s)
{
    int n = 0;
    for (size_t i = 0; i < image_pixel_count(&s->in.img); ++i)
        n += s->in.g.mask[i] != 0.0f;
    return n;
}

static const double lower[PARAM_COUNT] = {0.01, 0.0, 0.0}, upper[PARAM_COUNT] = {2.0, 1.0, 0.95};
/* Finite-difference steps: GTAO renders in float, so Ceres' relative step
 * (1e-6) moves its output by less than its rounding and the derivatives come
 * out 0; steps of a percent of each parameter's range see the real slope. */
static const double fd_step[PARAM_COUNT] = {0.01, 0.01, 0.01};

/* GTAO minus the reference at the scene's covered pixels, into r. */
static int residuals_at(const fit_scene *s, const double *params, float *ao, double *r)
{
    if (run_gtao(s, params, ao) != 0)
        return -1;
    const float *ref = image_channel_data(&s->in.img, "ao.V");
    size_t k = 0;
    for (size_t i = 0; i < image_pixel_count(&s->in.img); ++i)
        if (s->in.g.mask[i] != 0.0f)
            r[k++] = (double)ao[i] - ref[i];
    return 0;
}

/* One scene's residual block; its Jacobian by central differences (one-sided
 * at a bound) with the steps above. */
static int scene_residuals(void *user, const double *params, double *residuals, double *jacobian)
{
    const fit_scene *s = user;
    size_t n = image_pixel_count(&s->in.img);
    int m = covered_count(s);
    float *ao = malloc(sizeof *ao * n);
    double *plus = malloc(sizeof *plus * (size_t)m), *minus = malloc(sizeof *minus * (size_t)m);
    int rc = ao && plus && minus ? residuals_at(s, params, ao, residuals) : -1;
    for (int k = 0; k < PARAM_COUNT && jacobian && rc == 0; ++k) {
        double p_hi[PARAM_COUNT], p_lo[PARAM_COUNT];
        memcpy(p_hi, params, sizeof p_hi);
        memcpy(p_lo, params, sizeof p_lo);
        p_hi[k] = fmin(params[k] + fd_step[k], upper[k]);
        p_lo[k] = fmax(params[k] - fd_step[k], lower[k]);
        rc = residuals_at(s, p_hi, ao, plus) || residuals_at(s, p_lo, ao, minus) ? -1 : 0;
        for (int i = 0; i < m && rc == 0; ++i)
            jacobian[i * PARAM_COUNT + k] = (plus[i] - minus[i]) / (p_hi[k] - p_lo[k]);
    }
    free(ao);
    free(plus);
    free(minus);
    return rc;
}

typedef struct {
    double rmse, dssim;
} fit_score;

static int score(const fit_scene *s, const double *p, fit_score *out, gt_error *e)
{
    size_t n = image_pixel_count(&s->in.img);
    float *ao = malloc(sizeof *ao * n);
    if (!ao || run_gtao(s, p, ao) != 0) {
        free(ao);
        return gt_error_set(e, s->name, "out of memory");
    }
    const float *ref = image_channel_data(&s->in.img, "ao.V");
    image_error_stats st;
    ssim_result ss;
    int rc = image_error_compute(ao, ref, s->in.g.mask, s->in.img.width, s->in.img.height, s->name, &st, e) ||
             ssim_compute(ao, ref, s->in.g.mask, s->in.img.width, s->in.img.height, s->name, NULL, &ss, e);
    out->rmse = st.rmse;
    out->dssim = ss.dssim;
    free(ao);
    return rc ? -1 : 0;
}

static int load_scenes(const char *dir, const char *list, const gtao_params *base, fit_scene *scenes, int *count,
                       gt_error *e)
{
    char copy[1024];
    snprintf(copy, sizeof copy, "%s", list);
    *count = 0;
    for (char *tok = strtok(copy, ","); tok; tok = strtok(NULL, ",")) {
        if (*count == MAX_SCENES)
            return gt_error_set(e, list, "at most %d scenes", MAX_SCENES);
        fit_scene *s = &scenes[*count];
        char path[4096];
        snprintf(path, sizeof path, "%s/%s.exr", dir, tok);
        if (approx_load(path, NULL, &s->in, e) != 0)
            return -1;
        ++*count;
        if (!image_channel_data(&s->in.img, "ao.V"))
            return gt_error_set(e, path, "not an AO reference: no ao.V");
        snprintf(s->name, sizeof s->name, "%s", tok);
        s->distance = v3_length(v3_sub(s->in.cam.target, s->in.cam.position));
        s->base = *base;
    }
    return *count ? 0 : gt_error_set(e, list, "no scene named");
}

static cJSON *scores_json(const fit_scene *scenes, int count, const double *before, const double *after, gt_error *e,
                          int *rc)
{
    cJSON *list = cJSON_CreateArray();
    for (int i = 0; i < count && *rc == 0; ++i) {
        fit_score b, a;
        if (score(&scenes[i], before, &b, e) != 0 || score(&scenes[i], after, &a, e) != 0) {
            *rc = -1;
            break;
        }
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "scene", scenes[i].name);
        cJSON_AddNumberToObject(o, "rmse_before", b.rmse);
        cJSON_AddNumberToObject(o, "rmse_after", a.rmse);
        cJSON_AddNumberToObject(o, "dssim_before", b.dssim);
        cJSON_AddNumberToObject(o, "dssim_after", a.dssim);
        cJSON_AddItemToArray(list, o);
        printf("  %-16s RMSE %.4f -> %.4f   DSSIM %.4f -> %.4f\n", scenes[i].name, b.rmse, a.rmse, b.dssim, a.dssim);
    }
    return list;
}

int fit_gtao_params(int argc, char **argv)
{
    static const struct option longs[] = {{"refs", required_argument, 0, 'r'},  {"train", required_argument, 0, 'T'},
                                          {"test", required_argument, 0, 'S'},  {"preset", required_argument, 0, 'p'},
                                          {"output", required_argument, 0, 'o'}, {"help", no_argument, 0, 'h'},
                                          {0, 0, 0, 0}};
    const char *dir = NULL, *train = "boxes,corner,cornell", *test = "menger,sphere-on-plane", *preset = "high",
               *output = NULL;
    int c;
    while ((c = getopt_long(argc, argv, "o:h", longs, NULL)) != -1) {
        switch (c) {
        case 'r': dir = optarg; break;
        case 'T': train = optarg; break;
        case 'S': test = optarg; break;
        case 'p': preset = optarg; break;
        case 'o': output = optarg; break;
        case 'h': print_help(); return EXIT_OK;
        default: return cli_usage_error("fit gtao-params");
        }
    }
    if (!dir || !output)
        return cli_failf("gtao-params", "give --refs DIR and -o fit.json (see 'gtlab fit gtao-params --help')");
    gtao_params base;
    if (gtao_preset(preset, &base) != 0)
        return cli_failf("--preset", "unknown preset '%s'", preset);
    gt_error e;
    static fit_scene train_s[MAX_SCENES], test_s[MAX_SCENES];
    int n_train = 0, n_test = 0, status = EXIT_OK;
    double start[PARAM_COUNT] = {0.25, base.falloff, 0.1}, p[PARAM_COUNT];
    memcpy(p, start, sizeof p);
    gt_fit *fit = NULL;
    cJSON *root = NULL;
    if (load_scenes(dir, train, &base, train_s, &n_train, &e) != 0 ||
        load_scenes(dir, test, &base, test_s, &n_test, &e) != 0) {
        status = cli_fail(&e);
        goto done;
    }
    fit = gt_fit_create(PARAM_COUNT, p, &e);
    gt_fit_block_options finite_differences = {GT_FIT_ANALYTIC, GT_FIT_LOSS_NONE, 0};
    int rc = fit ? 0 : -1;
    for (int k = 0; k < PARAM_COUNT && rc == 0; ++k)
        rc = gt_fit_set_bounds(fit, k, lower[k], upper[k], &e);
    for (int i = 0; i < n_train && rc == 0; ++i)
        rc = gt_fit_add_block(fit, covered_count(&train_s[i]), scene_residuals, &train_s[i], &finite_differences, &e);
    gt_fit_options options = gt_fit_default_options();
    options.max_iterations = 30;
    options.function_tolerance = 1e-6; /* each evaluation renders every training scene */
    gt_fit_result result;
    double se[PARAM_COUNT] = {0};
    if (rc == 0)
        rc = gt_fit_solve(fit, &options, &result, &e);
    int have_se = 0;
    if (rc == 0) {
        gt_error ce;
        have_se = gt_fit_covariance(fit, NULL, se, NULL, &ce) == 0;
        if (!have_se)
            gt_warn("gtao-params", "no standard errors: %s", ce.message);
    }
    if (rc != 0) {
        status = cli_fail(&e);
        goto done;
    }
    printf("gtao-params (%s preset): %s after %d iterations\n", preset, result.success ? "converged" : "not converged",
           result.iterations);
    root = cJSON_CreateObject();
    cJSON_AddStringToObject(root, "problem", "gtao-params");
    cJSON_AddStringToObject(root, "preset", preset);
    cJSON_AddStringToObject(root, "train", train);
    cJSON_AddStringToObject(root, "test", test);
    cJSON *values = cJSON_AddObjectToObject(root, "values"), *errors = cJSON_AddObjectToObject(root, "standard_errors");
    cJSON *starts = cJSON_AddObjectToObject(root, "start");
    for (int k = 0; k < PARAM_COUNT; ++k) {
        cJSON_AddNumberToObject(values, param_names[k], p[k]);
        if (have_se)
            cJSON_AddNumberToObject(errors, param_names[k], se[k]);
        else
            cJSON_AddNullToObject(errors, param_names[k]);
        cJSON_AddNumberToObject(starts, param_names[k], start[k]);
        printf("  %-28s %.4f +- %.4f (start %.4f)\n", param_names[k], p[k], have_se ? se[k] : NAN, start[k]);
    }
    cJSON_AddBoolToObject(root, "converged", result.success);
    cJSON_AddNumberToObject(root, "iterations", result.iterations);
    cJSON_AddNumberToObject(root, "residual_rmse", result.rmse);
    printf("training scenes:\n");
    rc = 0;
    cJSON_AddItemToObject(root, "train_scores", scores_json(train_s, n_train, start, p, &e, &rc));
    printf("held-out scenes:\n");
    cJSON_AddItemToObject(root, "test_scores", scores_json(test_s, n_test, start, p, &e, &rc));
    char *text = rc == 0 ? cJSON_Print(root) : NULL;
    if (rc != 0 || !text || atomic_write_text(output, text, &e) != 0)
        status = cli_fail(&e);
    free(text);
done:
    cJSON_Delete(root);
    gt_fit_destroy(fit);
    for (int i = 0; i < n_train; ++i)
        approx_input_free(&train_s[i].in);
    for (int i = 0; i < n_test; ++i)
        approx_input_free(&test_s[i].in);
    return status;
}
