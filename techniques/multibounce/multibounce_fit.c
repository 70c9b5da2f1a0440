/* The GTAO multi-bounce refit (Jimenez et al. 2016, "Fitting for a Fixed
 * Albedo" to "Finding a Symbolic Expression"); see multibounce_fit.h. The
 * talk fitted its joint model by lines through the per-albedo coefficients;
 * here the joint model is fitted to all samples at once (issue 3). */
#define _POSIX_C_SOURCE 200809L
#include "multibounce/multibounce_fit.h"
#include "core/reference_schema.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- Data ----------------------------------------------------------------------------- */

void multibounce_data_init(multibounce_data *d) { memset(d, 0, sizeof *d); }

void multibounce_data_free(multibounce_data *d)
{
    free(d->samples);
    for (int i = 0; i < d->file_count; ++i)
        free(d->files[i]);
    free(d->files);
    memset(d, 0, sizeof *d);
}

int multibounce_data_scene(multibounce_data *d, const char *name, gt_error *e)
{
    for (int i = 0; i < d->scene_count; ++i)
        if (strcmp(d->scenes[i], name) == 0)
            return i;
    gt_quoted q;
    if (d->scene_count == MBFIT_MAX_SCENES)
        return gt_error_set(e, gt_quote(name, &q), "more than %d scenes", MBFIT_MAX_SCENES);
    snprintf(d->scenes[d->scene_count], MBFIT_NAME_MAX, "%s", name);
    return d->scene_count++;
}

int multibounce_data_albedo(multibounce_data *d, float albedo, gt_error *e)
{
    for (int i = 0; i < d->albedo_count; ++i)
        if (d->albedos[i] == albedo)
            return i;
    if (d->albedo_count == MBFIT_MAX_ALBEDOS)
        return gt_error_set(e, "albedos", "more than %d distinct albedos", MBFIT_MAX_ALBEDOS);
    d->albedos[d->albedo_count] = albedo;
    return d->albedo_count++;
}

int multibounce_data_push(multibounce_data *d, int scene, int albedo_index, float visibility, float multibounce,
                          gt_error *e)
{
    if (d->count == d->capacity) {
        size_t capacity = d->capacity ? 2 * d->capacity : 4096;
        multibounce_sample *grown = realloc(d->samples, capacity * sizeof *grown);
        if (!grown)
            return gt_error_set(e, "multibounce fit", "out of memory for %zu samples", capacity);
        d->samples = grown;
        d->capacity = capacity;
    }
    multibounce_sample s = {visibility, multibounce, d->albedos[albedo_index], 1.0f, (short)scene,
                            (short)albedo_index};
    d->samples[d->count++] = s;
    d->group_count[scene][albedo_index]++;
    return 0;
}

void multibounce_data_weigh(multibounce_data *d)
{
    int groups = 0;
    for (int s = 0; s < d->scene_count; ++s)
        for (int a = 0; a < d->albedo_count; ++a)
            groups += d->group_count[s][a] > 0;
    for (size_t i = 0; i < d->count; ++i) {
        multibounce_sample *p = &d->samples[i];
        p->weight = (float)((double)d->count / ((double)groups * (double)d->group_count[p->scene][p->albedo_index]));
    }
}

static int add_file_name(multibounce_data *d, const char *path, gt_error *e)
{
    char **grown = realloc(d->files, (size_t)(d->file_count + 1) * sizeof *grown);
    if (!grown || !(grown[d->file_count] = strdup(path))) {
        if (grown)
            d->files = grown;
        return gt_error_set(e, path, "out of memory");
    }
    d->files = grown;
    d->file_count++;
    return 0;
}

int multibounce_data_select(const multibounce_data *d, int scene, int exclude, int albedo_index,
                            multibounce_data *out, gt_error *e)
{
    multibounce_data_init(out);
    out->scene_count = d->scene_count;
    out->albedo_count = d->albedo_count;
    memcpy(out->scenes, d->scenes, sizeof d->scenes);
    memcpy(out->albedos, d->albedos, sizeof d->albedos);
    memcpy(out->bounces, d->bounces, sizeof d->bounces);
    for (size_t i = 0; i < d->count; ++i) {
        const multibounce_sample *p = &d->samples[i];
        int scene_kept = scene < 0 || (exclude ? p->scene != scene : p->scene == scene);
        if (!scene_kept || (albedo_index >= 0 && p->albedo_index != albedo_index))
            continue;
        if (multibounce_data_push(out, p->scene, p->albedo_index, p->visibility, p->multibounce, e) != 0) {
            multibounce_data_free(out);
            return -1;
        }
    }
    multibounce_data_weigh(out);
    return 0;
}

/* The channel of albedo token `token` ("0.3") in a file of `count` albedos. */
static void albedo_channel(const char *token, int count, char *name, size_t size)
{
    if (count == 1)
        snprintf(name, size, CH_MULTIBOUNCE);
    else
        snprintf(name, size, "multibounce_%.31s.V", token);
}

/* Splits the gtlab.albedos attribute ("0.1 0.3 0.5") into albedos. */
static int parse_albedo_list(const char *text, const char *path, char tokens[][32], float *albedos, int *count,
                             gt_error *e)
{
    *count = 0;
    for (const char *p = text; *p;) {
        while (*p == ' ')
            ++p;
        if (!*p)
            break;
        size_t n = strcspn(p, " ");
        char *end;
        gt_quoted q;
        if (*count == MBFIT_MAX_ALBEDOS || n >= 32)
            return gt_error_set(e, path, "%s '%s' is not a list of albedos", ATTR_ALBEDOS, gt_quote(text, &q));
        memcpy(tokens[*count], p, n);
        tokens[*count][n] = '\0';
        albedos[*count] = strtof(tokens[*count], &end);
        if (*end != '\0' || !(albedos[*count] >= 0.0f && albedos[*count] <= 1.0f))
            return gt_error_set(e, path, "%s '%s' is not a list of albedos in [0, 1]", ATTR_ALBEDOS,
                                gt_quote(text, &q));
        ++*count;
        p += n;
    }
    return *count ? 0 : gt_error_set(e, path, "%s is empty", ATTR_ALBEDOS);
}

static int check_header(multibounce_data *d, const image *img, const char *path, gt_error *e)
{
    const char *quantity = image_get_attribute(img, ATTR_QUANTITY);
    const char *albedos = image_get_attribute(img, ATTR_ALBEDOS);
    const char *bounces = image_get_attribute(img, ATTR_BOUNCES);
    gt_quoted q;
    if (!quantity || strcmp(quantity, "multibounce") != 0 || !albedos || !bounces)
        return gt_error_set(e, path, "no multibounce channels (not made by 'gtlab render multibounce'%s%s)",
                            quantity ? "; it holds " : "", quantity ? gt_quote(quantity, &q) : "");
    if (strcmp(albedos, "scene") == 0)
        return gt_error_set(e, path, "coloured render (--albedo scene); the fit needs grey albedos "
                                     "(--albedo 0.1,0.2,...)");
    if (strlen(bounces) >= sizeof d->bounces)
        return gt_error_set(e, path, "%s '%s' is not a bounce count", ATTR_BOUNCES, gt_quote(bounces, &q));
    if (d->bounces[0] && strcmp(d->bounces, bounces) != 0)
        return gt_error_set(e, path, "rendered with --bounces %s, but %s with --bounces %s", gt_quote(bounces, &q),
                            d->files[0], d->bounces);
    snprintf(d->bounces, sizeof d->bounces, "%s", bounces);
    return 0;
}

int multibounce_image_albedos(const image *img, const char *path, float albedos[MBFIT_MAX_ALBEDOS],
                              char channels[MBFIT_MAX_ALBEDOS][64], int *count, gt_error *e)
{
    multibounce_data header = {.count = 0};
    char tokens[MBFIT_MAX_ALBEDOS][32];
    if (check_header(&header, img, path, e) != 0 ||
        parse_albedo_list(image_get_attribute(img, ATTR_ALBEDOS), path, tokens, albedos, count, e) != 0)
        return -1;
    for (int k = 0; k < *count; ++k)
        albedo_channel(tokens[k], *count, channels[k], sizeof channels[k]);
    return 0;
}

static const float *require_channel(const image *img, const char *name, const char *path, gt_error *e)
{
    const float *p = image_channel_data(img, name);
    if (!p)
        gt_error_set(e, path, "channel %s is missing", name);
    return p;
}

int multibounce_data_add_image(multibounce_data *d, const image *img, const char *path, gt_error *e)
{
    if (check_header(d, img, path, e) != 0)
        return -1;
    char tokens[MBFIT_MAX_ALBEDOS][32];
    float albedos[MBFIT_MAX_ALBEDOS];
    int count, index[MBFIT_MAX_ALBEDOS];
    const float *planes[MBFIT_MAX_ALBEDOS];
    if (parse_albedo_list(image_get_attribute(img, ATTR_ALBEDOS), path, tokens, albedos, &count, e) != 0)
        return -1;
    const float *mask = require_channel(img, CH_MASK, path, e), *vd = mask ? require_channel(img, CH_AO, path, e) : NULL;
    if (!vd)
        return -1;
    for (int k = 0; k < count; ++k) {
        char name[64];
        albedo_channel(tokens[k], count, name, sizeof name);
        if (!(planes[k] = require_channel(img, name, path, e)))
            return -1;
    }
    const char *scene_name = image_get_attribute(img, ATTR_SCENE);
    int scene = multibounce_data_scene(d, scene_name ? scene_name : path, e);
    if (scene < 0)
        return -1;
    for (int k = 0; k < count; ++k)
        if ((index[k] = multibounce_data_albedo(d, albedos[k], e)) < 0)
            return -1;
    size_t covered = 0;
    for (size_t i = 0; i < image_pixel_count(img); ++i) {
        if (mask[i] == 0.0f)
            continue;
        ++covered;
        for (int k = 0; k < count; ++k) {
            float v = vd[i], m = planes[k][i];
            if (!(v >= 0.0f && v <= 1.0f && m >= 0.0f && m <= 1.0f))
                return gt_error_set(e, path, "pixel (%zu, %zu): V_d = %g, V'_d = %g outside [0, 1]",
                                    i % (size_t)img->width, i / (size_t)img->width, (double)v, (double)m);
            if (multibounce_data_push(d, scene, index[k], v, m, e) != 0)
                return -1;
        }
    }
    if (covered == 0)
        return gt_error_set(e, path, "no surface pixel (mask.A is 0 everywhere)");
    return add_file_name(d, path, e);
}

/* ---- Fitting -------------------------------------------------------------------------- */

/* Every fitted form is affine in its parameters p: the model's coefficient
 * vector (degree-2 layout, a[0..2], b[0..2], c[0..2]) is offset + map p.
 * The map is read off the form's own function (multibounce/multibounce.c) at
 * p = 0 and at the unit vectors, exactly, so no formula is written twice. */
typedef struct {
    int count, degree; /* parameters; the form's degree in rho (names) */
    int anchored;
    double offset[MULTIBOUNCE_MAX_PARAMETERS];
    double map[MULTIBOUNCE_MAX_PARAMETERS][MULTIBOUNCE_MAX_PARAMETERS]; /* [coefficient][parameter] */
} model_form;

/* The model of the form at parameters p, as a degree-2 model. */
static multibounce_model form_model(const model_form *f, const double *p)
{
    multibounce_model m;
    if (f->anchored) {
        m = multibounce_model_anchored(p);
    } else {
        m = multibounce_model_from_vector(f->degree, p);
        m.degree = MULTIBOUNCE_MAX_DEGREE; /* higher coefficients are 0 */
    }
    return m;
}

static model_form make_form(int degree, int anchored)
{
    model_form f = {.count = anchored ? MULTIBOUNCE_ANCHORED_PARAMETERS : multibounce_model_parameter_count(degree),
                    .degree = anchored ? MULTIBOUNCE_MAX_DEGREE : degree,
                    .anchored = anchored};
    double p[MULTIBOUNCE_MAX_PARAMETERS] = {0}, at[MULTIBOUNCE_MAX_PARAMETERS];
    multibounce_model m0 = form_model(&f, p);
    multibounce_model_to_vector(&m0, f.offset);
    for (int j = 0; j < f.count; ++j) {
        p[j] = 1.0;
        multibounce_model mj = form_model(&f, p);
        multibounce_model_to_vector(&mj, at);
        for (int k = 0; k < MULTIBOUNCE_MAX_PARAMETERS; ++k)
            f.map[k][j] = at[k] - f.offset[k];
        p[j] = 0.0;
    }
    return f;
}

typedef struct {
    const multibounce_sample *samples;
    int count;
    const model_form *form;
} sample_block;

static int block_residuals(void *user, const double *params, double *residuals, double *jacobian)
{
    const sample_block *b = user;
    const model_form *f = b->form;
    const multibounce_model m = form_model(f, params);
    for (int i = 0; i < b->count; ++i) {
        const multibounce_sample *s = &b->samples[i];
        const double root_w = sqrt((double)s->weight);
        const multibounce_cubic c = multibounce_cubic_at(&m, s->albedo);
        residuals[i] = root_w * (multibounce_cubic_eval(&c, s->visibility) - s->multibounce);
        if (jacobian) {
            double g[MULTIBOUNCE_MAX_PARAMETERS];
            multibounce_model_gradient(MULTIBOUNCE_MAX_DEGREE, s->visibility, s->albedo, g);
            for (int j = 0; j < f->count; ++j) {
                double sum = 0.0;
                for (int k = 0; k < MULTIBOUNCE_MAX_PARAMETERS; ++k)
                    sum += g[k] * f->map[k][j];
                jacobian[(size_t)i * (size_t)f->count + (size_t)j] = root_w * sum;
            }
        }
    }
    return 0;
}

static int distinct_albedos(const multibounce_data *d)
{
    int n = 0;
    for (int a = 0; a < d->albedo_count; ++a)
        for (int s = 0; s < d->scene_count; ++s)
            if (d->group_count[s][a]) {
                ++n;
                break;
            }
    return n;
}

static int fit_form(const multibounce_data *d, const model_form *form, const multibounce_fit_options *options,
                    multibounce_fit *out, gt_error *e)
{
    const int block_size = options && options->block_size > 0 ? options->block_size : MBFIT_DEFAULT_BLOCK;
    const int n = form->count;
    if (d->count <= (size_t)n)
        return gt_error_set(e, "multibounce fit", "%zu samples cannot determine %d coefficients", d->count, n);
    size_t block_count = (d->count + (size_t)block_size - 1) / (size_t)block_size;
    sample_block *blocks = malloc(block_count * sizeof *blocks);
    if (!blocks)
        return gt_error_set(e, "multibounce fit", "out of memory");
    /* Start at V'_d = V_d where the form allows (c = 1; the anchored form
     * is there at p = 0): every form is linear in its parameters, so
     * Levenberg-Marquardt lands on the optimum from anywhere. */
    double params[MULTIBOUNCE_MAX_PARAMETERS] = {0};
    if (!form->anchored)
        params[2 * (form->degree + 1)] = 1.0;
    gt_fit_options so = gt_fit_default_options();
    so.linear_solver = GT_FIT_DENSE_NORMAL_CHOLESKY;
    gt_fit *fit = gt_fit_create(n, params, e);
    int rc = fit ? 0 : -1;
    for (size_t k = 0; k < block_count && rc == 0; ++k) {
        size_t first = k * (size_t)block_size;
        size_t count = d->count - first < (size_t)block_size ? d->count - first : (size_t)block_size;
        blocks[k] = (sample_block){d->samples + first, (int)count, form};
        rc = gt_fit_add_block(fit, (int)count, block_residuals, &blocks[k], NULL, e);
    }
    if (rc == 0)
        rc = gt_fit_solve(fit, &so, &out->solver, e);
    if (rc == 0 && !(options && options->skip_covariance))
        rc = gt_fit_covariance(fit, out->covariance, out->standard_errors, &out->residual_variance, e);
    if (rc == 0) {
        out->anchored = form->anchored;
        out->model = form->anchored ? multibounce_model_anchored(params)
                                    : multibounce_model_from_vector(form->degree, params);
        out->parameter_count = n;
        memcpy(out->params, params, sizeof params);
    }
    gt_fit_destroy(fit);
    free(blocks);
    return rc;
}

int multibounce_fit_model(const multibounce_data *d, int degree, const multibounce_fit_options *options,
                          multibounce_fit *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    if (degree < 0 || degree > MULTIBOUNCE_MAX_DEGREE)
        return gt_error_set(e, "multibounce fit", "degree %d outside [0, %d]", degree, MULTIBOUNCE_MAX_DEGREE);
    if (distinct_albedos(d) < degree + 1)
        return gt_error_set(e, "multibounce fit", "a, b, c of degree %d in the albedo need %d albedos, the data "
                            "have %d", degree, degree + 1, distinct_albedos(d));
    const model_form form = make_form(degree, 0);
    return fit_form(d, &form, options, out, e);
}

int multibounce_fit_anchored(const multibounce_data *d, const multibounce_fit_options *options,
                             multibounce_fit *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    if (distinct_albedos(d) < 2)
        return gt_error_set(e, "multibounce fit", "the anchored form needs 2 albedos, the data have %d",
                            distinct_albedos(d));
    const model_form form = make_form(MULTIBOUNCE_MAX_DEGREE, 1);
    return fit_form(d, &form, options, out, e);
}

void multibounce_fit_parameter_name(const multibounce_fit *f, int index, char *name, size_t size)
{
    int n = f->model.degree + 1;
    if (f->anchored)
        snprintf(name, size, "%c%d", "pq"[index % 2], index / 2 + 1);
    else if (f->model.degree == 0)
        snprintf(name, size, "%c", "abc"[index]);
    else
        snprintf(name, size, "%c%d", "abc"[index / n], index % n);
}

void multibounce_measure(const multibounce_data *d, const multibounce_model *m, int with_max, multibounce_errors *out)
{
    memset(out, 0, sizeof *out);
    double sum_w = 0.0, sum_wr2 = 0.0, max_abs = 0.0, below = 0.0;
    for (size_t i = 0; i < d->count; ++i) {
        const multibounce_sample *s = &d->samples[i];
        const multibounce_cubic c = multibounce_cubic_at(m, s->albedo);
        double cubic = multibounce_cubic_eval(&c, s->visibility);
        double model = with_max ? gtao_multibounce(m, s->visibility, s->albedo) : cubic;
        double r = model - s->multibounce;
        sum_w += s->weight;
        sum_wr2 += s->weight * r * r;
        if (fabs(r) > max_abs) {
            max_abs = fabs(r);
            out->worst = *s;
        }
        below += cubic < s->visibility - MBFIT_BELOW_MARGIN ? s->weight : 0.0;
    }
    out->samples = d->count;
    out->rmse = sum_w > 0 ? sqrt(sum_wr2 / sum_w) : 0.0;
    out->max_abs = max_abs;
    out->below = sum_w > 0 ? below / sum_w : 0.0;
}

double multibounce_max_shortfall(const multibounce_model *m, double albedo)
{
    const multibounce_cubic c = multibounce_cubic_at(m, albedo);
    double worst = -INFINITY;
    for (int i = 0; i <= 1000; ++i) {
        double x = i / 1000.0;
        worst = fmax(worst, x - multibounce_cubic_eval(&c, x));
    }
    return worst;
}

/* ---- The analysis ---------------------------------------------------------------------- */

const char *const multibounce_joint_names[MB_JOINT_COUNT] = {"joint_linear", "joint_quadratic", "joint_anchored"};

static int fit_joint(const multibounce_data *d, multibounce_joint j, const multibounce_fit_options *o,
                     multibounce_fit *out, gt_error *e)
{
    switch (j) {
    case MB_JOINT_LINEAR: return multibounce_fit_model(d, 1, o, out, e);
    case MB_JOINT_QUADRATIC: return multibounce_fit_model(d, 2, o, out, e);
    default: return multibounce_fit_anchored(d, o, out, e);
    }
}

static int analyse_albedo(const multibounce_data *d, int albedo_index, const multibounce_analysis *a,
                          multibounce_albedo_result *r, gt_error *e)
{
    multibounce_data one;
    if (multibounce_data_select(d, -1, 0, albedo_index, &one, e) != 0)
        return -1;
    r->albedo = d->albedos[albedo_index];
    const multibounce_model talk = multibounce_model_jimenez2016();
    int rc = multibounce_fit_model(&one, 0, NULL, &r->fit, e);
    if (rc == 0) {
        multibounce_measure(&one, &r->fit.model, 1, &r->own);
        multibounce_measure(&one, &a->joint[MB_JOINT_LINEAR].model, 1, &r->linear);
        multibounce_measure(&one, &talk, 1, &r->talk);
    }
    multibounce_data_free(&one);
    return rc;
}

/* Residuals of one albedo's per-albedo coefficients from lines in rho. */
static int line_residuals(void *user, const double *params, double *residuals, double *jacobian)
{
    const multibounce_albedo_result *r = user;
    const multibounce_model lines = multibounce_model_from_vector(1, params);
    const multibounce_cubic at = multibounce_cubic_at(&lines, r->albedo);
    const multibounce_cubic *own = &(const multibounce_cubic){r->fit.model.a[0], r->fit.model.b[0], r->fit.model.c[0]};
    residuals[0] = at.a - own->a;
    residuals[1] = at.b - own->b;
    residuals[2] = at.c - own->c;
    if (jacobian) {
        memset(jacobian, 0, 3 * 6 * sizeof *jacobian);
        for (int t = 0; t < 3; ++t) {
            jacobian[t * 6 + 2 * t] = 1.0;
            jacobian[t * 6 + 2 * t + 1] = r->albedo;
        }
    }
    return 0;
}

/* The talk's two-step procedure: a cubic per albedo, then a line through
 * each coefficient (seeds/001, "Finding a Symbolic Expression"). */
static int two_step(const multibounce_data *d, multibounce_analysis *a, gt_error *e)
{
    double params[6] = {0, 0, 0, 0, 1, 0};
    gt_fit *fit = gt_fit_create(6, params, e);
    int rc = fit ? 0 : -1;
    for (int k = 0; k < d->albedo_count && rc == 0; ++k)
        rc = gt_fit_add_block(fit, 3, line_residuals, &a->per_albedo[k], NULL, e);
    if (rc == 0)
        rc = gt_fit_solve(fit, NULL, NULL, e);
    gt_fit_destroy(fit);
    if (rc != 0)
        return -1;
    a->two_step = multibounce_model_from_vector(1, params);
    multibounce_measure(d, &a->two_step, 1, &a->two_step_err);
    return 0;
}

/* Fits every joint model on every scene but `scene`, measures on `scene`. */
static int hold_out(const multibounce_data *d, int scene, const int *has, multibounce_heldout *h, gt_error *e)
{
    multibounce_data train, test;
    if (multibounce_data_select(d, scene, 1, -1, &train, e) != 0)
        return -1;
    if (multibounce_data_select(d, scene, 0, -1, &test, e) != 0) {
        multibounce_data_free(&train);
        return -1;
    }
    h->scene = scene;
    const multibounce_model talk = multibounce_model_jimenez2016();
    multibounce_measure(&test, &talk, 1, &h->talk);
    const multibounce_fit_options model_only = {0, 1};
    int rc = 0;
    for (int j = 0; j < MB_JOINT_COUNT && rc == 0; ++j) {
        multibounce_fit fit;
        if (!has[j] || (rc = fit_joint(&train, (multibounce_joint)j, &model_only, &fit, e)) != 0)
            continue;
        h->model[j] = fit.model;
        memcpy(h->params[j], fit.params, sizeof fit.params);
        multibounce_measure(&test, &h->model[j], 1, &h->err[j]);
    }
    multibounce_data_free(&train);
    multibounce_data_free(&test);
    if (rc != 0) {
        char why[sizeof e->message];
        snprintf(why, sizeof why, "%s", e->message);
        return gt_error_set(e, d->scenes[scene], "leave-one-scene-out fit without it: %s", why);
    }
    return 0;
}

static void jackknife(multibounce_analysis *a)
{
    const double s = a->heldout_count;
    for (int j = 0; j < MB_JOINT_COUNT; ++j)
        for (int k = 0; k < a->joint[j].parameter_count; ++k) {
            double mean = 0.0, sum_sq = 0.0;
            for (int i = 0; i < a->heldout_count; ++i)
                mean += a->heldout[i].params[j][k] / s;
            for (int i = 0; i < a->heldout_count; ++i)
                sum_sq += (a->heldout[i].params[j][k] - mean) * (a->heldout[i].params[j][k] - mean);
            a->jackknife_se[j][k] = sqrt((s - 1.0) / s * sum_sq);
        }
}

static int leave_one_scene_out(const multibounce_data *d, multibounce_analysis *a, gt_error *e)
{
    a->heldout_count = 0;
    for (int s = 0; s < d->scene_count; ++s) {
        multibounce_heldout *h = &a->heldout[a->heldout_count];
        if (hold_out(d, s, a->has, h, e) != 0)
            return -1;
        for (int j = 0; j < MB_JOINT_COUNT; ++j)
            a->heldout_mean[j] += h->err[j].rmse / d->scene_count;
        a->heldout_mean_talk += h->talk.rmse / d->scene_count;
        a->heldout_count++;
    }
    jackknife(a);
    return 0;
}

int multibounce_analyse(const multibounce_data *d, multibounce_analysis *a, gt_error *e)
{
    memset(a, 0, sizeof *a);
    if (distinct_albedos(d) < 2)
        return gt_error_set(e, "--data", "the joint model needs samples at 2 or more albedos (render with "
                                         "--albedo 0.1,0.2,...)");
    const multibounce_model talk = multibounce_model_jimenez2016();
    a->has[MB_JOINT_LINEAR] = a->has[MB_JOINT_ANCHORED] = 1;
    a->has[MB_JOINT_QUADRATIC] = distinct_albedos(d) >= 3;
    for (int j = 0; j < MB_JOINT_COUNT; ++j) {
        if (!a->has[j])
            continue;
        if (fit_joint(d, (multibounce_joint)j, NULL, &a->joint[j], e) != 0)
            return -1;
        for (int with_max = 0; with_max < 2; ++with_max)
            multibounce_measure(d, &a->joint[j].model, with_max, &a->joint_err[j][with_max]);
    }
    for (int with_max = 0; with_max < 2; ++with_max)
        multibounce_measure(d, &talk, with_max, &a->talk_err[with_max]);
    for (int k = 0; k < d->albedo_count; ++k)
        if (analyse_albedo(d, k, a, &a->per_albedo[k], e) != 0)
            return -1;
    if (two_step(d, a, e) != 0)
        return -1;
    a->chosen = MB_JOINT_LINEAR;
    if (d->scene_count >= 2) {
        if (leave_one_scene_out(d, a, e) != 0)
            return -1;
        for (int j = 0; j < MB_JOINT_COUNT; ++j)
            if (a->has[j] && a->heldout_mean[j] < a->heldout_mean[a->chosen])
                a->chosen = (multibounce_joint)j;
    }
    return 0;
}
