/* The model's premise (multibounce/multibounce_study.h, multibounce_contrast_study;
 * issue 25, item 1): albedo-contrast scenes against uniform ones, the
 * talk's f on both, and the neighbourhood-albedo correction held out. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/reference_schema.h"
#include "metrics/reference_halves.h"
#include "multibounce/multibounce_parts.h"
#include "multibounce/multibounce_quality.h"
#include "multibounce/multibounce_quantity.h"
#include "scene/scene_loaders.h"

/* Scenes with a floor (mesh 0) and objects (the other meshes). */
static const char *const kContrastScenes[MULTIBOUNCE_CONTRAST_SCENES] = {"sphere-on-plane", "menger", "boxes"};
/* {floor, objects}: dark on white, mid on white, white on dark, white on mid;
 * every albedo one of the study's, so each pixel has its uniform reference. */
static const float kPairs[MULTIBOUNCE_CONTRASTS][2] = {{0.9f, 0.1f}, {0.9f, 0.4f}, {0.1f, 0.9f}, {0.4f, 0.9f}};

typedef struct {
    float x, y, rho, rho_mean, weight;
    int scene, row;
} contrast_sample;

typedef struct {
    contrast_sample *items;
    size_t count, capacity;
} sample_list;

static int push_sample(sample_list *l, contrast_sample s)
{
    if (l->count == l->capacity) {
        size_t capacity = l->capacity ? 2 * l->capacity : 65536;
        contrast_sample *grown = realloc(l->items, capacity * sizeof *grown);
        if (!grown)
            return -1;
        l->items = grown;
        l->capacity = capacity;
    }
    l->items[l->count++] = s;
    return 0;
}

/* The talk's f(x, rho), bare (fit) or with the shader's max (scores). */
static double talk_f(double x, double rho, int with_max)
{
    const multibounce_model talk = multibounce_model_jimenez2016();
    const multibounce_cubic c = multibounce_cubic_at(&talk, rho);
    return with_max ? gtao_multibounce(&talk, x, rho) : multibounce_cubic_eval(&c, x);
}

/* ---- The contrast scenes ------------------------------------------------------------ */

/* `spec` with its floor (mesh 0) of albedo floor_albedo and every other mesh of object_albedo. */
static int load_contrast_scene(const char *spec, float floor_albedo, float object_albedo, scene *s, gt_error *e)
{
    const float floor_rgb[3] = {floor_albedo, floor_albedo, floor_albedo};
    const float objects_rgb[3] = {object_albedo, object_albedo, object_albedo};
    return multibounce_load_two_albedo_scene(spec, floor_rgb, objects_rgb, s, e);
}

/* The per-object-albedo reference of one contrast scene, as the study renders its own. */
static int render_contrast(const study_context *ctx, const reference_request *base, const char *spec,
                           const float pair[2], image *img, gt_error *e)
{
    multibounce_render_settings mb = {{QUANTITY_MULTIBOUNCE},
                                      {.scene_albedo = 1, .bounces = multibounce_settings_of(base)->bounces}};
    reference_request req = *base;
    req.settings = &mb.header;
    scene s;
    if (load_contrast_scene(spec, pair[0], pair[1], &s, e) != 0)
        return -1;
    camera cam;
    render_stats stats;
    int size = multibounce_quality_of(ctx->quality)->image_width;
    int rc = scene_choose_camera(&s, NULL, size, 0, &cam, e);
    if (rc == 0)
        rc = reference_render(&s, spec, &cam, &req, img, &stats, e);
    scene_free(&s);
    return rc;
}

/* Mean albedo over the covered pixels of the (2r+1)^2 box around pixel (x, y). */
static float neighbourhood_albedo(const image *img, const float *albedo, const float *mask, int x, int y, int r)
{
    double sum = 0.0;
    int n = 0;
    for (int j = y - r; j <= y + r; ++j)
        for (int i = x - r; i <= x + r; ++i) {
            if (i < 0 || j < 0 || i >= img->width || j >= img->height || mask[(size_t)j * img->width + i] == 0.0f)
                continue;
            sum += albedo[(size_t)j * img->width + i];
            ++n;
        }
    return (float)(sum / n);
}

static int albedo_index(const float *albedos, float albedo)
{
    for (int a = 0; a < MULTIBOUNCE_STUDY_ALBEDOS; ++a)
        if (albedos[a] == albedo)
            return a;
    return -1;
}

/* What one contrast scene's pixels need: its render and halves, and the uniform references. */
typedef struct {
    const image *img, *halves;           /* the contrast render and its halves */
    const multibounce_state *st;
    int k;                               /* the study's index of the scene */
    int uniform[2];                      /* albedo indices of floor and objects */
    float pair[2];
} contrast_view;

/* Pixel i: premise deviation, both f errors into row sums, and its fit sample. */
typedef struct {
    double premise[2], premise_n[2], contrast, uniform, n;
} row_sums;

static int add_pixel(const contrast_view *v, size_t i, float rho_mean, int scene, int row, row_sums *sums,
                     sample_list *samples)
{
    const multibounce_state *st = v->st;
    const float rho = image_channel_data(v->img, CH_ALBEDO_R)[i];
    const int on_floor = rho == v->pair[0], a = v->uniform[on_floor ? 0 : 1];
    const char *uniform_channel = st->plan.quantities[a].name;
    const double x = image_channel_data(&v->halves[0], CH_AO)[i];
    const double y = image_channel_data(&v->halves[1], CH_MULTIBOUNCE_R)[i];
    const double y_uniform = image_channel_data(&st->halves[v->k][1], uniform_channel)[i];
    const double x_uniform = image_channel_data(&st->halves[v->k][0], CH_AO)[i];
    const double premise = image_channel_data(v->img, CH_MULTIBOUNCE_R)[i] -
                           image_channel_data(&st->refs[v->k], uniform_channel)[i];
    sums->premise[on_floor] += premise * premise;
    sums->premise_n[on_floor] += 1.0;
    sums->contrast += (talk_f(x, rho, 1) - y) * (talk_f(x, rho, 1) - y);
    sums->uniform += (talk_f(x_uniform, rho, 1) - y_uniform) * (talk_f(x_uniform, rho, 1) - y_uniform);
    sums->n += 1.0;
    return push_sample(samples, (contrast_sample){(float)x, (float)y, rho, rho_mean, 1.0f, scene, row});
}

static void finish_row(const row_sums *s, size_t first, sample_list *samples, multibounce_contrast_row *row)
{
    row->premise_rms_floor = s->premise_n[1] > 0 ? sqrt(s->premise[1] / s->premise_n[1]) : 0.0;
    row->premise_rms_object = s->premise_n[0] > 0 ? sqrt(s->premise[0] / s->premise_n[0]) : 0.0;
    row->rmse_contrast = sqrt(s->contrast / s->n);
    row->rmse_uniform = sqrt(s->uniform / s->n);
    for (size_t i = first; i < samples->count; ++i)
        samples->items[i].weight = (float)(1.0 / s->n); /* every scene and contrast counts equally */
}

/* Every covered pixel of one contrast scene. */
static int scan_scene(const contrast_view *v, int scene, int row, int radius, sample_list *samples,
                      multibounce_contrast_row *out)
{
    const float *mask = image_channel_data(v->img, CH_MASK), *albedo = image_channel_data(v->img, CH_ALBEDO_R);
    row_sums sums;
    memset(&sums, 0, sizeof sums);
    const size_t first = samples->count;
    for (int y = 0; y < v->img->height; ++y)
        for (int x = 0; x < v->img->width; ++x) {
            size_t i = (size_t)y * v->img->width + x;
            if (mask[i] != 0.0f &&
                add_pixel(v, i, neighbourhood_albedo(v->img, albedo, mask, x, y, radius), scene, row, &sums,
                          samples) != 0)
                return -1;
        }
    finish_row(&sums, first, samples, out);
    return 0;
}

/* ---- The correction ----------------------------------------------------------------- */

/* w minimising sum weight (f(x, rho) + w (rho_mean - rho) df/drho - y)^2
 * over the samples not of scene `without` (-1: all); f is linear in rho. */
static double fit_weight(const sample_list *l, int without)
{
    double num = 0.0, den = 0.0;
    for (size_t i = 0; i < l->count; ++i) {
        const contrast_sample *s = &l->items[i];
        if (s->scene == without)
            continue;
        double d = (s->rho_mean - s->rho) * (talk_f(s->x, 1.0, 0) - talk_f(s->x, 0.0, 0));
        num += s->weight * d * (s->y - talk_f(s->x, s->rho, 0));
        den += s->weight * d * d;
    }
    return den > 0 ? num / den : 0.0;
}

/* rmse_corrected_held_out of every row: w fitted without the row's scene. */
static void score_correction(const sample_list *l, multibounce_contrast_study *out)
{
    double sum[MULTIBOUNCE_CONTRAST_SCENES * MULTIBOUNCE_CONTRASTS] = {0}, n[MULTIBOUNCE_CONTRAST_SCENES * MULTIBOUNCE_CONTRASTS] = {0};
    out->weight = fit_weight(l, -1);
    for (int s = 0; s < MULTIBOUNCE_CONTRAST_SCENES; ++s)
        out->weight_held_out[s] = fit_weight(l, s);
    for (size_t i = 0; i < l->count; ++i) {
        const contrast_sample *s = &l->items[i];
        double rho = s->rho + out->weight_held_out[s->scene] * (s->rho_mean - s->rho);
        double r = talk_f(s->x, rho, 1) - s->y;
        sum[s->row] += r * r;
        n[s->row] += 1.0;
    }
    for (int r = 0; r < out->count; ++r)
        out->rows[r].rmse_corrected_held_out = sqrt(sum[r] / n[r]);
}

/* Means over the rows of a field difference, and its jackknife over scenes. */
static void jackknife_mean(const multibounce_contrast_study *c, size_t field_a, size_t field_b, double *mean,
                           double *se)
{
    const int n = MULTIBOUNCE_CONTRAST_SCENES;
    double replica[MULTIBOUNCE_CONTRAST_SCENES] = {0}, rows_without = (double)(c->count - MULTIBOUNCE_CONTRASTS);
    *mean = 0.0;
    for (int r = 0; r < c->count; ++r) {
        const char *row = (const char *)&c->rows[r];
        double d = *(const double *)(row + field_a) - *(const double *)(row + field_b);
        *mean += d / c->count;
        for (int s = 0; s < n; ++s)
            replica[s] += r / MULTIBOUNCE_CONTRASTS == s ? 0.0 : d / rows_without;
    }
    double average = 0.0, ss = 0.0;
    for (int s = 0; s < n; ++s)
        average += replica[s] / n;
    for (int s = 0; s < n; ++s)
        ss += (replica[s] - average) * (replica[s] - average);
    *se = sqrt((n - 1.0) / n * ss);
}

static void summarise(multibounce_contrast_study *c)
{
    for (int r = 0; r < c->count; ++r) {
        c->mean_rmse_contrast += c->rows[r].rmse_contrast / c->count;
        c->mean_rmse_uniform += c->rows[r].rmse_uniform / c->count;
        c->mean_rmse_corrected += c->rows[r].rmse_corrected_held_out / c->count;
    }
    jackknife_mean(c, offsetof(multibounce_contrast_row, rmse_contrast),
                   offsetof(multibounce_contrast_row, rmse_uniform), &c->premise_cost, &c->premise_cost_se);
    jackknife_mean(c, offsetof(multibounce_contrast_row, rmse_corrected_held_out),
                   offsetof(multibounce_contrast_row, rmse_contrast), &c->correction_gain, &c->correction_gain_se);
}

/* ---- The study ------------------------------------------------------------------------ */

static int study_index(const char *const *scenes, const char *name)
{
    for (int k = 0; k < MULTIBOUNCE_STUDY_SCENES; ++k)
        if (strcmp(scenes[k], name) == 0)
            return k;
    return -1;
}

/* Scene s at contrast p: render, split, scan into row `row`. */
static int contrast_row(const study_context *ctx, const reference_request *req, const multibounce_state *st,
                        const char *const *scenes, const float *albedos, int s, int p, sample_list *samples,
                        multibounce_contrast_study *out, gt_error *e)
{
    char spec[128];
    snprintf(spec, sizeof spec, "builtin:%s", kContrastScenes[s]);
    contrast_view v = {.st = st, .k = study_index(scenes, kContrastScenes[s]),
                       .uniform = {albedo_index(albedos, kPairs[p][0]), albedo_index(albedos, kPairs[p][1])},
                       .pair = {kPairs[p][0], kPairs[p][1]}};
    if (v.k < 0 || v.uniform[0] < 0 || v.uniform[1] < 0)
        return gt_error_set(e, spec, "contrast scene without its uniform references");
    image img, halves[2];
    if (render_contrast(ctx, req, spec, kPairs[p], &img, e) != 0)
        return -1;
    if (reference_halves_split(&img, spec, halves, e) != 0) {
        image_free(&img);
        return -1;
    }
    multibounce_contrast_row *row = &out->rows[out->count];
    *row = (multibounce_contrast_row){.floor_albedo = kPairs[p][0], .object_albedo = kPairs[p][1]};
    snprintf(row->scene, sizeof row->scene, "%s", kContrastScenes[s]);
    v.img = &img;
    v.halves = halves;
    int rc = scan_scene(&v, s, out->count, out->radius_px, samples, row);
    if (rc != 0)
        gt_error_set(e, spec, "out of memory");
    else
        out->count++;
    image_free(&halves[0]);
    image_free(&halves[1]);
    image_free(&img);
    return rc;
}

int multibounce_study_contrast(const study_context *ctx, const reference_request *req, const multibounce_state *st,
                               const char *const *scenes, const float *albedos, multibounce_contrast_study *out,
                               gt_error *e)
{
    memset(out, 0, sizeof *out);
    out->radius_px = st->refs[0].width / 16;
    sample_list samples = {0};
    int rc = 0;
    for (int s = 0; s < MULTIBOUNCE_CONTRAST_SCENES && rc == 0; ++s)
        for (int p = 0; p < MULTIBOUNCE_CONTRASTS && rc == 0; ++p)
            rc = contrast_row(ctx, req, st, scenes, albedos, s, p, &samples, out, e);
    if (rc == 0) {
        score_correction(&samples, out);
        summarise(out);
    }
    free(samples.items);
    return rc;
}
