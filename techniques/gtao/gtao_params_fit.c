/* The GTAO parameter fit; see gtao_params_fit.h. The Jacobian comes from
 * finite differences at steps a float renderer resolves. */
#include "gtao/gtao_params_fit.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fitters/ceres_bridge.h"
#include "gtao/gtao.h"
#include "metrics/image_error.h"
#include "metrics/ssim.h"

enum { PARAM_RADIUS, PARAM_FALLOFF, PARAM_THICKNESS, PARAM_COUNT = GTAO_FIT_PARAMS, MAX_SCENES = GTAO_FIT_MAX_SCENES };
const char *const gtao_fit_param_names[GTAO_FIT_PARAMS] = {"radius_over_camera_distance", "falloff", "thickness"};
const char *const gtao_fit_objective_names[2] = {"dssim", "rmse"};

static const double lower[PARAM_COUNT] = {0.01, 0.0, 0.0}, upper[PARAM_COUNT] = {2.0, 1.0, 0.95};

int gtao_fit_at_bound(const gtao_fit_result *r, int k)
{
    return r->value[k] <= lower[k] ? -1 : r->value[k] >= upper[k] ? 1 : 0;
}
/* Finite-difference steps: GTAO renders in float, so Ceres' relative step
 * (1e-6) moves its output by less than its rounding and the derivatives come
 * out 0; steps of a percent of each parameter's range see the real slope. */
static const double fd_step[PARAM_COUNT] = {0.01, 0.01, 0.01};

/* A scene as the solver sees it. */
typedef struct {
    const gtao_fit_scene *in;
    gtao_params base;
    gtao_fit_objective objective;
    int residual_count; /* covered pixels (rmse) or SSIM windows inside the mask (dssim) */
    double weight;      /* 1/sqrt(residual_count): every scene counts equally */
} fit_scene;

static size_t pixel_count(const fit_scene *s) { return (size_t)s->in->g->width * s->in->g->height; }

static int run_gtao(const fit_scene *s, const double *p, float *ao)
{
    gtao_params q = s->base;
    q.radius = (float)p[PARAM_RADIUS] * s->in->camera_distance;
    q.falloff = (float)p[PARAM_FALLOFF];
    q.thickness = (float)p[PARAM_THICKNESS];
    return gtao_render(s->in->g, &q, ao, NULL);
}

/* Whether pixel (x, y) has a residual: inside the mask and, for DSSIM, the
 * centre of a full SSIM window. */
static int has_residual(const fit_scene *s, int x, int y)
{
    const ss_gbuffer *g = s->in->g;
    return g->mask[(size_t)y * g->width + x] >= 0.5f &&
           (s->objective == GTAO_FIT_RMSE || ssim_centre_valid(x, y, g->width, g->height));
}

/* The mask is fixed, so the residual count is too. */
static int residual_count(const fit_scene *s)
{
    int n = 0;
    for (int y = 0; y < s->in->g->height; ++y)
        for (int x = 0; x < s->in->g->width; ++x)
            n += has_residual(s, x, y);
    return n;
}

/* The objective's residuals for the parameters `params`, into r: GTAO minus
 * the reference at each covered pixel (rmse), or sqrt of each window's DSSIM
 * (dssim), both scaled by the scene's weight. `ao` and `map` are scratch
 * planes of the image's size. */
static int residuals_at(const fit_scene *s, const double *params, float *ao, float *map, double *r)
{
    if (run_gtao(s, params, ao) != 0)
        return -1;
    const float *ref = s->in->reference;
    int w = s->in->g->width, h = s->in->g->height;
    if (s->objective == GTAO_FIT_DSSIM) {
        ssim_result unused;
        gt_error e;
        if (ssim_compute(ao, ref, s->in->g->mask, w, h, s->in->name, map, &unused, &e) != 0)
            return -1;
    }
    size_t k = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            size_t i = (size_t)y * w + x;
            if (!has_residual(s, x, y))
                continue;
            if (s->objective == GTAO_FIT_RMSE)
                r[k++] = s->weight * ((double)ao[i] - ref[i]);
            else
                r[k++] = s->weight * sqrt(fmax(0.0, (1.0 - (double)map[i]) / 2.0));
        }
    return 0;
}

/* Column k of the Jacobian by central differences (one-sided at a bound). */
static int jacobian_column(const fit_scene *s, const double *params, int k, float *ao, float *map, double *plus,
                           double *minus, double *jacobian)
{
    double p_hi[PARAM_COUNT], p_lo[PARAM_COUNT];
    memcpy(p_hi, params, sizeof p_hi);
    memcpy(p_lo, params, sizeof p_lo);
    p_hi[k] = fmin(params[k] + fd_step[k], upper[k]);
    p_lo[k] = fmax(params[k] - fd_step[k], lower[k]);
    if (residuals_at(s, p_hi, ao, map, plus) != 0 || residuals_at(s, p_lo, ao, map, minus) != 0)
        return -1;
    for (int i = 0; i < s->residual_count; ++i)
        jacobian[i * PARAM_COUNT + k] = (plus[i] - minus[i]) / (p_hi[k] - p_lo[k]);
    return 0;
}

/* One scene's residual block and, if asked, its Jacobian. */
static int scene_residuals(void *user, const double *params, double *residuals, double *jacobian)
{
    const fit_scene *s = user;
    size_t n = pixel_count(s), m = (size_t)s->residual_count;
    float *ao = malloc(sizeof *ao * n), *map = malloc(sizeof *map * n);
    double *plus = malloc(sizeof *plus * m), *minus = malloc(sizeof *minus * m);
    int rc = ao && map && plus && minus ? residuals_at(s, params, ao, map, residuals) : -1;
    for (int k = 0; k < PARAM_COUNT && jacobian && rc == 0; ++k)
        rc = jacobian_column(s, params, k, ao, map, plus, minus, jacobian);
    free(ao);
    free(map);
    free(plus);
    free(minus);
    return rc;
}

/* RMSE and DSSIM of GTAO at parameters p against the scene's reference. */
static int score(const fit_scene *s, const double *p, double *rmse, double *dssim, gt_error *e)
{
    float *ao = malloc(sizeof *ao * pixel_count(s));
    if (!ao || run_gtao(s, p, ao) != 0) {
        free(ao);
        return gt_error_set(e, s->in->name, "out of memory");
    }
    const ss_gbuffer *g = s->in->g;
    image_error_stats st;
    ssim_result ss;
    int rc = image_error_compute(ao, s->in->reference, g->mask, g->width, g->height, s->in->name, &st, e) ||
             ssim_compute(ao, s->in->reference, g->mask, g->width, g->height, s->in->name, NULL, &ss, e);
    *rmse = st.rmse;
    *dssim = ss.dssim;
    free(ao);
    return rc ? -1 : 0;
}

/* The solver's view of `count` scenes. */
static int prepare_scenes(const gtao_fit_scene *in, int count, const gtao_params *base, gtao_fit_objective objective,
                          fit_scene *out, gt_error *e)
{
    if (count > MAX_SCENES)
        return gt_error_set(e, in[0].name, "at most %d scenes", MAX_SCENES);
    for (int i = 0; i < count; ++i) {
        fit_scene *s = &out[i];
        *s = (fit_scene){&in[i], *base, objective, 0, 0.0};
        if ((s->residual_count = residual_count(s)) == 0)
            return gt_error_set(e, in[i].name, "no covered pixel%s",
                                objective == GTAO_FIT_DSSIM ? " with a full SSIM window" : "");
        s->weight = 1.0 / sqrt((double)s->residual_count);
    }
    return 0;
}

/* Scores before and after of every scene of `scenes`, appended to out. */
static int score_scenes(const fit_scene *scenes, int count, int held_out, gtao_fit_result *out, gt_error *e)
{
    for (int i = 0; i < count; ++i) {
        gtao_fit_score *x = &out->scores[out->score_count++];
        snprintf(x->scene, sizeof x->scene, "%s", scenes[i].in->name);
        x->held_out = held_out;
        if (score(&scenes[i], out->start, &x->rmse_before, &x->dssim_before, e) != 0 ||
            score(&scenes[i], out->value, &x->rmse_after, &x->dssim_after, e) != 0)
            return -1;
    }
    return 0;
}

/* The standard errors, convergence and objective of a solved fit. */
static void read_solution(gt_fit *fit, const gt_fit_result *result, int n_train, gtao_fit_result *out)
{
    gt_error ce;
    out->have_se = gt_fit_covariance(fit, NULL, out->se, NULL, &ce) == 0;
    if (!out->have_se)
        gt_warn("gtao-params", "no standard errors: %s", ce.message);
    out->converged = result->success;
    out->iterations = result->iterations;
    /* cost = 1/2 sum r^2, and each scene's r^2 sum to its mean squared error or mean DSSIM */
    out->objective_per_scene = 2.0 * result->final_cost / n_train;
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
    if (rc == 0)
        read_solution(fit, &result, n_train, out);
    gt_fit_destroy(fit);
    return rc;
}

int gtao_params_fit(const gtao_fit_problem *problem, gtao_fit_result *out, gt_error *e)
{
    gtao_params base;
    if (gtao_preset(problem->preset, &base) != 0)
        return gt_error_set(e, "--preset", "unknown preset '%s'", problem->preset);
    if (problem->train_count == 0)
        return gt_error_set(e, "gtao-params", "no training scene");
    memset(out, 0, sizeof *out);
    out->start[PARAM_RADIUS] = 0.25, out->start[PARAM_FALLOFF] = base.falloff, out->start[PARAM_THICKNESS] = 0.1;
    fit_scene train[MAX_SCENES], test[MAX_SCENES];
    if (prepare_scenes(problem->train, problem->train_count, &base, problem->objective, train, e) != 0 ||
        prepare_scenes(problem->test, problem->test_count, &base, problem->objective, test, e) != 0 ||
        solve(train, problem->train_count, out, e) != 0 ||
        score_scenes(train, problem->train_count, 0, out, e) != 0 ||
        score_scenes(test, problem->test_count, 1, out, e) != 0)
        return -1;
    return 0;
}
