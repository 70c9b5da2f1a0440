/* gtlab fit gtao-params: GTAO's world radius (as a fraction of the camera's
 * distance to its target), falloff and thickness fitted to 3-D ray-traced AO
 * references through the Ceres bridge (Jacobian by finite differences at
 * steps a float renderer resolves), scored before and after on held-out
 * scenes. Issue 4 asks for the parameters that minimise DSSIM, and the talk
 * tuned by image comparison too, so the default objective is DSSIM: one
 * residual per SSIM window, sqrt((1 - SSIM_w) / 2), whose squares sum to the
 * number of windows times the scene's DSSIM (Wang et al. 2004's mean over
 * windows). The per-pixel least-squares objective (RMSE) is an option. */
#include <cjson/cJSON.h>
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/approx_io.h"
#include "cli/cli.h"
#include "cli/fit_gtao_params.h"
#include "core/atomic_file.h"
#include "fitters/ceres_bridge.h"
#include "metrics/image_error.h"
#include "metrics/ssim.h"
#include "realtime/gtao.h"
#include "core/reference_schema.h"

enum { PARAM_RADIUS, PARAM_FALLOFF, PARAM_THICKNESS, PARAM_COUNT = GTAO_FIT_PARAMS, MAX_SCENES = GTAO_FIT_MAX_SCENES };
const char *const gtao_fit_param_names[GTAO_FIT_PARAMS] = {"radius_over_camera_distance", "falloff", "thickness"};
const char *const gtao_fit_objective_names[2] = {"dssim", "rmse"};


static void print_help(void)
{
    printf("usage: gtlab fit gtao-params --refs DIR --train A,B,.. --test C,.. [options] -o fit.json\n"
           "\n"
           "Fits GTAO's radius (a fraction of each camera's distance to its target), falloff\n"
           "and thickness so GTAO matches 3-D ray-traced AO references (Ceres, over the\n"
           "training scenes, each scene's residuals weighted equally; derivatives by finite\n"
           "differences of 0.01 in each parameter), and reports RMSE and DSSIM before and\n"
           "after on the training and the held-out scenes.\n"
           "\n"
           "  --refs DIR        folder of AO references <scene>.exr with their G-buffer and\n"
           "                    camera (e.g. the ao/ folder 'gtlab all' writes)\n"
           "  --train LIST      scenes to fit on, comma-separated (default boxes,corner,cornell)\n"
           "  --test LIST       held-out scenes (default menger,sphere-on-plane)\n"
           "  --preset P        GTAO preset (default high)\n"
           "  --objective O     dssim (default: the sum over scenes of each scene's mean\n"
           "                    DSSIM) or rmse (per-pixel least squares)\n"
           "  -o, --output F    fit JSON: values, standard errors, scores before and after\n"
           "  -h, --help\n");
}

typedef struct {
    approx_input in;
    char name[64];
    float distance;
    gtao_params base;
    gtao_fit_objective objective;
    int residual_count; /* covered pixels (rmse) or SSIM windows inside the mask (dssim) */
    double weight;      /* 1/sqrt(residual_count): every scene counts equally */
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

/* Residuals of the objective: pixels inside the mask (rmse) or valid SSIM
 * window centres inside it (dssim); the mask is fixed, so the count is too. */
static int residual_count(const fit_scene *s)
{
    int n = 0;
    for (int y = 0; y < s->in.img.height; ++y)
        for (int x = 0; x < s->in.img.width; ++x)
            n += s->in.g.mask[(size_t)y * s->in.img.width + x] >= 0.5f &&
                 (s->objective == GTAO_FIT_RMSE || ssim_centre_valid(x, y, s->in.img.width, s->in.img.height));
    return n;
}

static const double lower[PARAM_COUNT] = {0.01, 0.0, 0.0}, upper[PARAM_COUNT] = {2.0, 1.0, 0.95};
/* Finite-difference steps: GTAO renders in float, so Ceres' relative step
 * (1e-6) moves its output by less than its rounding and the derivatives come
 * out 0; steps of a percent of each parameter's range see the real slope. */
static const double fd_step[PARAM_COUNT] = {0.01, 0.01, 0.01};

/* The objective's residuals for the parameters `params`, into r: GTAO minus
 * the reference at each covered pixel (rmse), or sqrt of each window's DSSIM
 * (dssim), both scaled by the scene's weight. `ao` and `map` are scratch
 * planes of the image's size. */
static int residuals_at(const fit_scene *s, const double *params, float *ao, float *map, double *r)
{
    if (run_gtao(s, params, ao) != 0)
        return -1;
    const float *ref = image_channel_data(&s->in.img, CH_AO);
    int w = s->in.img.width, h = s->in.img.height;
    if (s->objective == GTAO_FIT_DSSIM) {
        ssim_result unused;
        gt_error e;
        if (ssim_compute(ao, ref, s->in.g.mask, w, h, s->name, map, &unused, &e) != 0)
            return -1;
    }
    size_t k = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            size_t i = (size_t)y * w + x;
            if (s->in.g.mask[i] < 0.5f)
                continue;
            if (s->objective == GTAO_FIT_RMSE)
                r[k++] = s->weight * ((double)ao[i] - ref[i]);
            else if (ssim_centre_valid(x, y, w, h))
                r[k++] = s->weight * sqrt(fmax(0.0, (1.0 - (double)map[i]) / 2.0));
        }
    return 0;
}

/* One scene's residual block; its Jacobian by central differences (one-sided
 * at a bound) with the steps above. */
static int scene_residuals(void *user, const double *params, double *residuals, double *jacobian)
{
    const fit_scene *s = user;
    size_t n = image_pixel_count(&s->in.img);
    int m = s->residual_count;
    float *ao = malloc(sizeof *ao * n), *map = malloc(sizeof *map * n);
    double *plus = malloc(sizeof *plus * (size_t)m), *minus = malloc(sizeof *minus * (size_t)m);
    int rc = ao && map && plus && minus ? residuals_at(s, params, ao, map, residuals) : -1;
    for (int k = 0; k < PARAM_COUNT && jacobian && rc == 0; ++k) {
        double p_hi[PARAM_COUNT], p_lo[PARAM_COUNT];
        memcpy(p_hi, params, sizeof p_hi);
        memcpy(p_lo, params, sizeof p_lo);
        p_hi[k] = fmin(params[k] + fd_step[k], upper[k]);
        p_lo[k] = fmax(params[k] - fd_step[k], lower[k]);
        rc = residuals_at(s, p_hi, ao, map, plus) || residuals_at(s, p_lo, ao, map, minus) ? -1 : 0;
        for (int i = 0; i < m && rc == 0; ++i)
            jacobian[i * PARAM_COUNT + k] = (plus[i] - minus[i]) / (p_hi[k] - p_lo[k]);
    }
    free(ao);
    free(map);
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
    const float *ref = image_channel_data(&s->in.img, CH_AO);
    image_error_stats st;
    ssim_result ss;
    int rc = image_error_compute(ao, ref, s->in.g.mask, s->in.img.width, s->in.img.height, s->name, &st, e) ||
             ssim_compute(ao, ref, s->in.g.mask, s->in.img.width, s->in.img.height, s->name, NULL, &ss, e);
    out->rmse = st.rmse;
    out->dssim = ss.dssim;
    free(ao);
    return rc ? -1 : 0;
}

static int load_scenes(const char *dir, const char *list, const gtao_params *base, gtao_fit_objective objective,
                       fit_scene *scenes, int *count, gt_error *e)
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
        if (!image_channel_data(&s->in.img, CH_AO))
            return gt_error_set(e, path, "not an AO reference: no ao.V");
        snprintf(s->name, sizeof s->name, "%s", tok);
        s->distance = v3_length(v3_sub(s->in.cam.target, s->in.cam.position));
        s->base = *base;
        s->objective = objective;
        if ((s->residual_count = residual_count(s)) == 0)
            return gt_error_set(e, path, "no covered pixel%s", objective == GTAO_FIT_DSSIM ? " with a full SSIM window" : "");
        s->weight = 1.0 / sqrt((double)s->residual_count);
    }
    return *count ? 0 : gt_error_set(e, list, "no scene named");
}

/* Scores before and after of every scene of `scenes`, appended to out. */
static int score_scenes(const fit_scene *scenes, int count, int held_out, const double *before, const double *after,
                        gtao_fit_result *out, gt_error *e)
{
    for (int i = 0; i < count; ++i) {
        gtao_fit_score *x = &out->scores[out->score_count++];
        fit_score b, a;
        if (score(&scenes[i], before, &b, e) != 0 || score(&scenes[i], after, &a, e) != 0)
            return -1;
        snprintf(x->scene, sizeof x->scene, "%s", scenes[i].name);
        x->held_out = held_out;
        x->rmse_before = b.rmse, x->rmse_after = a.rmse;
        x->dssim_before = b.dssim, x->dssim_after = a.dssim;
    }
    return 0;
}

/* The Ceres problem over the training scenes, solved from out->start into out->value. */
static int solve(fit_scene *train, int n_train, gtao_fit_result *out, gt_error *e)
{
    memcpy(out->value, out->start, sizeof out->value);
    gt_fit *fit = gt_fit_create(GTAO_FIT_PARAMS, out->value, e);
    gt_fit_block_options finite_differences = {GT_FIT_ANALYTIC, GT_FIT_LOSS_NONE, 0};
    int rc = fit ? 0 : -1;
    for (int k = 0; k < GTAO_FIT_PARAMS && rc == 0; ++k)
        rc = gt_fit_set_bounds(fit, k, lower[k], upper[k], e);
    for (int i = 0; i < n_train && rc == 0; ++i)
        rc = gt_fit_add_block(fit, train[i].residual_count, scene_residuals, &train[i], &finite_differences, e);
    gt_fit_options options = gt_fit_default_options();
    options.max_iterations = 30;
    options.function_tolerance = 1e-6; /* each evaluation renders every training scene */
    gt_fit_result result;
    if (rc == 0)
        rc = gt_fit_solve(fit, &options, &result, e);
    if (rc == 0) {
        gt_error ce;
        out->have_se = gt_fit_covariance(fit, NULL, out->se, NULL, &ce) == 0;
        if (!out->have_se)
            gt_warn("gtao-params", "no standard errors: %s", ce.message);
        out->converged = result.success;
        out->iterations = result.iterations;
        /* cost = 1/2 sum r^2, and each scene's r^2 sum to its mean squared error or mean DSSIM */
        out->objective_per_scene = 2.0 * result.final_cost / n_train;
    }
    gt_fit_destroy(fit);
    return rc;
}

int gtao_params_fit(const gtao_fit_request *rq, gtao_fit_result *out, gt_error *e)
{
    gtao_params base;
    if (gtao_preset(rq->preset, &base) != 0)
        return gt_error_set(e, "--preset", "unknown preset '%s'", rq->preset);
    memset(out, 0, sizeof *out);
    out->start[PARAM_RADIUS] = 0.25, out->start[PARAM_FALLOFF] = base.falloff, out->start[PARAM_THICKNESS] = 0.1;
    static fit_scene train[MAX_SCENES], test[MAX_SCENES];
    int n_train = 0, n_test = 0;
    int rc = load_scenes(rq->refs_dir, rq->train, &base, rq->objective, train, &n_train, e) != 0 ||
                     load_scenes(rq->refs_dir, rq->test, &base, rq->objective, test, &n_test, e) != 0 ||
                     solve(train, n_train, out, e) != 0 ||
                     score_scenes(train, n_train, 0, out->start, out->value, out, e) != 0 ||
                     score_scenes(test, n_test, 1, out->start, out->value, out, e) != 0
                 ? -1
                 : 0;
    for (int i = 0; i < n_train; ++i)
        approx_input_free(&train[i].in);
    for (int i = 0; i < n_test; ++i)
        approx_input_free(&test[i].in);
    return rc;
}

static cJSON *scores_json(const gtao_fit_result *r, int held_out)
{
    cJSON *list = cJSON_CreateArray();
    for (int i = 0; i < r->score_count; ++i) {
        const gtao_fit_score *x = &r->scores[i];
        if (x->held_out != held_out)
            continue;
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "scene", x->scene);
        cJSON_AddNumberToObject(o, "rmse_before", x->rmse_before);
        cJSON_AddNumberToObject(o, "rmse_after", x->rmse_after);
        cJSON_AddNumberToObject(o, "dssim_before", x->dssim_before);
        cJSON_AddNumberToObject(o, "dssim_after", x->dssim_after);
        cJSON_AddItemToArray(list, o);
    }
    return list;
}

cJSON *gtao_fit_json(const gtao_fit_request *rq, const gtao_fit_result *r)
{
    cJSON *root = cJSON_CreateObject();
    cJSON_AddStringToObject(root, "problem", "gtao-params");
    cJSON_AddStringToObject(root, "preset", rq->preset);
    cJSON_AddStringToObject(root, "objective", gtao_fit_objective_names[rq->objective]);
    cJSON_AddStringToObject(root, "train", rq->train);
    cJSON_AddStringToObject(root, "test", rq->test);
    cJSON *values = cJSON_AddObjectToObject(root, "values"), *errors = cJSON_AddObjectToObject(root, "standard_errors");
    cJSON *starts = cJSON_AddObjectToObject(root, "start");
    for (int k = 0; k < GTAO_FIT_PARAMS; ++k) {
        cJSON_AddNumberToObject(values, gtao_fit_param_names[k], r->value[k]);
        if (r->have_se)
            cJSON_AddNumberToObject(errors, gtao_fit_param_names[k], r->se[k]);
        else
            cJSON_AddNullToObject(errors, gtao_fit_param_names[k]);
        cJSON_AddNumberToObject(starts, gtao_fit_param_names[k], r->start[k]);
    }
    cJSON_AddBoolToObject(root, "converged", r->converged);
    cJSON_AddNumberToObject(root, "iterations", r->iterations);
    cJSON_AddNumberToObject(root, "objective_per_scene", r->objective_per_scene);
    cJSON_AddItemToObject(root, "train_scores", scores_json(r, 0));
    cJSON_AddItemToObject(root, "test_scores", scores_json(r, 1));
    return root;
}

static void print_fit(const gtao_fit_request *rq, const gtao_fit_result *r)
{
    printf("gtao-params (%s preset, %s objective): %s after %d iterations\n", rq->preset,
           gtao_fit_objective_names[rq->objective], r->converged ? "converged" : "not converged", r->iterations);
    for (int k = 0; k < GTAO_FIT_PARAMS; ++k)
        printf("  %-28s %.4f +- %.4f (start %.4f)\n", gtao_fit_param_names[k], r->value[k],
               r->have_se ? r->se[k] : NAN, r->start[k]);
    for (int held_out = 0; held_out <= 1; ++held_out) {
        printf("%s scenes:\n", held_out ? "held-out" : "training");
        for (int i = 0; i < r->score_count; ++i)
            if (r->scores[i].held_out == held_out)
                printf("  %-16s RMSE %.4f -> %.4f   DSSIM %.4f -> %.4f\n", r->scores[i].scene, r->scores[i].rmse_before,
                       r->scores[i].rmse_after, r->scores[i].dssim_before, r->scores[i].dssim_after);
    }
}

int fit_gtao_params(int argc, char **argv)
{
    static const struct option longs[] = {{"refs", required_argument, 0, 'r'},  {"train", required_argument, 0, 'T'},
                                          {"test", required_argument, 0, 'S'},  {"preset", required_argument, 0, 'p'},
                                          {"objective", required_argument, 0, 'j'}, {"output", required_argument, 0, 'o'},
                                          {"help", no_argument, 0, 'h'},        {0, 0, 0, 0}};
    gtao_fit_request rq = {NULL, "boxes,corner,cornell", "menger,sphere-on-plane", "high", GTAO_FIT_DSSIM};
    const char *output = NULL;
    int c;
    while ((c = getopt_long(argc, argv, "o:h", longs, NULL)) != -1) {
        switch (c) {
        case 'r': rq.refs_dir = optarg; break;
        case 'T': rq.train = optarg; break;
        case 'S': rq.test = optarg; break;
        case 'p': rq.preset = optarg; break;
        case 'j':
            if (strcmp(optarg, "dssim") != 0 && strcmp(optarg, "rmse") != 0)
                return cli_failf("--objective", "'%s' is neither dssim nor rmse", optarg);
            rq.objective = strcmp(optarg, "dssim") == 0 ? GTAO_FIT_DSSIM : GTAO_FIT_RMSE;
            break;
        case 'o': output = optarg; break;
        case 'h': print_help(); return EXIT_OK;
        default: return cli_usage_error("fit gtao-params");
        }
    }
    if (!rq.refs_dir || !output)
        return cli_failf("gtao-params", "give --refs DIR and -o fit.json (see 'gtlab fit gtao-params --help')");
    gt_error e;
    static gtao_fit_result r;
    if (gtao_params_fit(&rq, &r, &e) != 0)
        return cli_fail(&e);
    print_fit(&rq, &r);
    cJSON *root = gtao_fit_json(&rq, &r);
    char *text = cJSON_Print(root);
    int status = text && atomic_write_text(output, text, &e) == 0 ? EXIT_OK : cli_fail(&e);
    free(text);
    cJSON_Delete(root);
    return status;
}
