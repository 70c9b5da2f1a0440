/* `gtlab all` stage: the GTAO multi-bounce refit (Jimenez et al. 2016,
 * "Multiple Bounces" to "Shader Code"; issue 3). Multi-bounce references of
 * the built-in scenes at seven grey albedos (one pass per scene), the fit of
 * `gtlab fit multibounce` on them (results/fits/multibounce.*), validation
 * of V_d alone, the talk's polynomial and ours against each reference, the
 * leave-one-scene-out table, and gnuplot figures. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/all_stages.h"
#include "cli/gnuplot_plot.h"
#include "core/atomic_file.h"
#include "core/exr_io.h"
#include "fitters/fit_multibounce.h"
#include "metrics/image_error.h"
#include "metrics/ssim.h"
#include "raytracer/multibounce_throughput.h"
#include "raytracer/reference_render.h"
#include "scene/scene_loaders.h"

/* The plane is left out: V_d = V'_d = 1 everywhere, nothing to fit. */
static const char *const kScenes[] = {"sphere-on-plane", "corner", "menger", "boxes", "cornell"};
enum { SCENES = sizeof kScenes / sizeof kScenes[0] };
/* The talk used seven albedos from 0.1 to 0.9 without listing them; denser
 * at the low albedos it calls the most common in nature. */
static const float kAlbedos[] = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.7f, 0.9f};
enum { ALBEDOS = sizeof kAlbedos / sizeof kAlbedos[0], SCATTER_POINTS = 2500, CURVE_STEPS = 100 };

typedef struct {
    image refs[SCENES];
    image halves[SCENES][2]; /* means of the even- and odd-index samples */
    int rendered[SCENES], split[SCENES];
    render_stats stats[SCENES];
    multibounce_plan plan; /* the channel names */
    multibounce_data data;
    multibounce_analysis *analysis;
    char figures[2048];
} stage;

typedef struct {
    double noise_floor, rmse_floor; /* the even half of V'_d against the odd half */
    double dssim[4], rmse[4]; /* V_d, talk, ours, ours without this scene (leave-one-out) */
} validation;

/* ---- References ------------------------------------------------------------------------ */

static reference_request request(const all_context *ctx)
{
    int preview = ctx->quality == QUALITY_PREVIEW;
    reference_request req = {.quantity = QUANTITY_MULTIBOUNCE,
                             .sampling = {.spp = preview ? 128 : 2048, .seed = 1, .threads = ctx->threads},
                             .normals = NORMAL_SHADING,
                             .max_distance = INFINITY,
                             .multibounce = {.albedo_count = ALBEDOS, .bounces = 4}};
    memcpy(req.multibounce.albedos, kAlbedos, sizeof kAlbedos);
    return req;
}

static int split_halves(const image *img, const char *what, image halves[2], gt_error *e);

static int render_reference(const all_context *ctx, int k, const char *dir, stage *st, gt_error *e)
{
    char spec[128], path[4096];
    snprintf(spec, sizeof spec, "builtin:%s", kScenes[k]);
    scene s;
    if (scene_load(spec, &s, e) != 0)
        return -1;
    camera cam;
    const reference_request req = request(ctx);
    int size = ctx->quality == QUALITY_PREVIEW ? 128 : 384;
    int rc = scene_choose_camera(&s, NULL, size, 0, &cam, e);
    if (rc == 0)
        rc = reference_render(&s, spec, &cam, &req, &st->refs[k], &st->stats[k], e);
    scene_free(&s);
    if (rc != 0)
        return -1;
    st->rendered[k] = 1;
    snprintf(path, sizeof path, "%s/%s.exr", dir, kScenes[k]);
    if (exr_write(path, &st->refs[k], e) != 0)
        return -1;
    snprintf(path, sizeof path, "%s/%s.camera.json", dir, kScenes[k]);
    if (camera_write_json(path, &cam, e) != 0 || split_halves(&st->refs[k], spec, st->halves[k], e) != 0)
        return -1;
    st->split[k] = 1;
    return multibounce_data_add_image(&st->data, &st->refs[k], spec, e);
}

/* A table cell: room for a scene name (up to 255 characters) or a number. */
enum { CELL = 264 };

/* One table row from formatted cells. */
static void row_of(report *doc, int n, char cells[][CELL])
{
    const char *row[12];
    for (int i = 0; i < n; ++i)
        row[i] = cells[i];
    report_table_row(doc, row);
}

/* ---- Validation ------------------------------------------------------------------------ */

/* The means of the even- and of the odd-index samples of every quantity
 * (core/mc_film.h), background 0: two independent half-references. */
static int split_halves(const image *img, const char *what, image halves[2], gt_error *e)
{
    mc_film film;
    if (mc_film_read_channels(img, what, &film, e) != 0)
        return -1;
    const float *mask = image_channel_data(img, "mask.A");
    int rc = 0, made = 0;
    for (int h = 0; h < 2 && rc == 0; ++h) {
        if (image_init(&halves[h], img->width, img->height) != 0) {
            rc = gt_error_set(e, what, "out of memory");
            break;
        }
        ++made;
        if (mc_film_write_half_means(&film, h, &halves[h]) != 0)
            rc = gt_error_set(e, what, "out of memory");
        for (int c = 0; c < halves[h].channel_count && rc == 0; ++c)
            for (size_t i = 0; i < image_pixel_count(img); ++i)
                if (mask[i] == 0.0f)
                    halves[h].channels[c].data[i] = 0.0f;
    }
    mc_film_free(&film);
    if (rc != 0)
        for (int h = 0; h < made; ++h)
            image_free(&halves[h]);
    return rc;
}

/* model(V_d, rho) at the surface pixels, 0 in the background. */
static void apply_model(const float *vd, const float *mask, size_t n, const multibounce_model *m, float albedo,
                        float *out)
{
    for (size_t i = 0; i < n; ++i)
        out[i] = mask[i] != 0.0f ? (float)gtao_multibounce(m, vd[i], albedo) : 0.0f;
}

/* DSSIM and RMSE of `approx` against `target` over the mask. */
static int score(const float *approx, const float *target, const float *mask, const image *img, const char *what,
                 double *dssim, double *rmse, gt_error *e)
{
    ssim_result s;
    image_error_stats err;
    if (ssim_compute(approx, target, mask, img->width, img->height, what, NULL, &s, e) != 0 ||
        image_error_compute(approx, target, mask, img->width, img->height, what, &err, e) != 0)
        return -1;
    *dssim = s.dssim;
    *rmse = err.rmse;
    return 0;
}

/* Every approximation takes V_d from the even-sample half and is scored
 * against V'_d of the odd-sample half: V_d and V'_d of one half come from
 * the same paths, and their shared noise would let an approximation score
 * below the reference's noise floor. The floors are the two halves of V'_d
 * scored against each other, so every figure has the same noise in it. */
static int validate(const stage *st, int k, int a, validation *v, gt_error *e)
{
    const image *img = &st->refs[k];
    const image *even = &st->halves[k][0], *odd = &st->halves[k][1];
    const char *channel = st->plan.quantities[a].name;
    char what[256];
    snprintf(what, sizeof what, "%s %s", kScenes[k], channel);
    const float *mask = image_channel_data(img, "mask.A"), *target = image_channel_data(odd, channel);
    const float *vd = image_channel_data(even, "ao.V");
    size_t n = image_pixel_count(img);
    if (score(image_channel_data(even, channel), target, mask, img, what, &v->noise_floor, &v->rmse_floor, e) != 0)
        return -1;
    const multibounce_model talk = multibounce_model_jimenez2016();
    const multibounce_model *models[3] = {&talk, &st->analysis->joint[MB_JOINT_LINEAR].model, &st->analysis->heldout[k].model[MB_JOINT_LINEAR]};
    float *approx = malloc(n * sizeof *approx);
    if (!approx)
        return gt_error_set(e, what, "out of memory");
    int rc = score(vd, target, mask, img, what, &v->dssim[0], &v->rmse[0], e);
    for (int m = 1; m < 4 && rc == 0; ++m) {
        apply_model(vd, mask, n, models[m - 1], kAlbedos[a], approx);
        rc = score(approx, target, mask, img, what, &v->dssim[m], &v->rmse[m], e);
    }
    free(approx);
    return rc;
}

static int validation_section(all_context *ctx, const stage *st, cJSON *json, gt_error *e)
{
    report_heading(ctx->doc, 3, "Validation against the references");
    report_paragraph(ctx->doc,
                     "For each scene and albedo, the multi-bounce reference V'_d against: V_d alone (no "
                     "multi-bounce term), the talk's polynomial and our joint refit, each applied to V_d with the "
                     "shader's max(V_d, .), and our refit made without the scene (the out-of-sample figure). V_d "
                     "and V'_d of one render come from the same paths and share their noise, so the "
                     "approximations take V_d from the even-index samples and are scored against V'_d of the "
                     "odd-index samples; the noise floors (DSSIM and RMSE) score the even half of V'_d against the "
                     "odd half: the score of an estimate exact but for noise like the reference's. An "
                     "approximation whose input V_d is less noisy than V'_d (at high albedos) can score below it; "
                     "the floor says how finely this comparison can separate approximations.");
    static const char *const headers[11] = {"scene", "albedo", "DSSIM floor", "DSSIM V_d", "DSSIM talk",
                                            "DSSIM ours", "RMSE floor", "RMSE V_d", "RMSE talk", "RMSE ours",
                                            "RMSE ours (held out)"};
    report_table_begin(ctx->doc, 11, headers);
    double mean_dssim[5] = {0}, mean_rmse[5] = {0};
    for (int k = 0; k < SCENES; ++k)
        for (int a = 0; a < ALBEDOS; ++a) {
            validation v;
            if (validate(st, k, a, &v, e) != 0) {
                report_table_end(ctx->doc);
                return -1;
            }
            char cells[11][CELL];
            snprintf(cells[0], CELL, "%s", kScenes[k]);
            snprintf(cells[1], CELL, "%.1f", (double)kAlbedos[a]);
            snprintf(cells[2], CELL, "%.2e", v.noise_floor);
            for (int m = 0; m < 3; ++m)
                snprintf(cells[3 + m], CELL, "%.2e", v.dssim[m]);
            snprintf(cells[6], CELL, "%.4f", v.rmse_floor);
            for (int m = 0; m < 4; ++m)
                snprintf(cells[7 + m], CELL, "%.4f", v.rmse[m]);
            row_of(ctx->doc, 11, cells);
            cJSON *o = cJSON_CreateObject();
            cJSON_AddStringToObject(o, "scene", kScenes[k]);
            cJSON_AddNumberToObject(o, "albedo", (double)kAlbedos[a]);
            cJSON_AddNumberToObject(o, "noise_floor_dssim", v.noise_floor);
            cJSON_AddNumberToObject(o, "noise_floor_rmse", v.rmse_floor);
            static const char *const keys[4] = {"v_d", "talk", "ours", "ours_held_out"};
            for (int m = 0; m < 4; ++m) {
                char key[64];
                snprintf(key, sizeof key, "dssim_%s", keys[m]);
                cJSON_AddNumberToObject(o, key, v.dssim[m]);
                snprintf(key, sizeof key, "rmse_%s", keys[m]);
                cJSON_AddNumberToObject(o, key, v.rmse[m]);
                mean_dssim[m] += v.dssim[m] / (SCENES * ALBEDOS);
                mean_rmse[m] += v.rmse[m] / (SCENES * ALBEDOS);
            }
            mean_dssim[4] += v.noise_floor / (SCENES * ALBEDOS);
            mean_rmse[4] += v.rmse_floor / (SCENES * ALBEDOS);
            cJSON_AddItemToArray(json, o);
        }
    report_table_end(ctx->doc);
    report_paragraph(ctx->doc,
                     "Means over the %d scene-albedo pairs: DSSIM %.2e (floor), %.2e (V_d), %.2e (talk), %.2e "
                     "(ours), %.2e (ours, scene held out); RMSE %.4f (floor), %.4f, %.4f, %.4f, %.4f.",
                     SCENES * ALBEDOS, mean_dssim[4], mean_dssim[0], mean_dssim[1], mean_dssim[2], mean_dssim[3],
                     mean_rmse[4], mean_rmse[0], mean_rmse[1], mean_rmse[2], mean_rmse[3]);
    return 0;
}

/* ---- Fit tables -------------------------------------------------------------------------- */

static void coefficient_table(all_context *ctx, const multibounce_analysis *a)
{
    const multibounce_model talk = multibounce_model_jimenez2016();
    double ours[6], theirs[6];
    multibounce_model_to_vector(&a->joint[MB_JOINT_LINEAR].model, ours);
    multibounce_model_to_vector(&talk, theirs);
    static const char *const names[6] = {"a0", "a1 (x rho)", "b0", "b1 (x rho)", "c0", "c1 (x rho)"};
    static const char *const headers[6] = {"coefficient", "gtlab joint fit", "standard error (pixels)",
                                           "jackknife s.e. (scenes)", "talk", "talk - ours in jackknife s.e."};
    report_table_begin(ctx->doc, 6, headers);
    for (int i = 0; i < 6; ++i) {
        char cells[6][CELL];
        const double jk = a->jackknife_se[MB_JOINT_LINEAR][i];
        snprintf(cells[0], CELL, "%s", names[i]);
        snprintf(cells[1], CELL, "%.4f", ours[i]);
        snprintf(cells[2], CELL, "%.4f", a->joint[MB_JOINT_LINEAR].standard_errors[i]);
        snprintf(cells[3], CELL, "%.4f", jk);
        snprintf(cells[4], CELL, "%.4f", theirs[i]);
        snprintf(cells[5], CELL, "%.1f", (theirs[i] - ours[i]) / jk);
        row_of(ctx->doc, 6, cells);
    }
    report_table_end(ctx->doc);
}

static void per_albedo_table(all_context *ctx, const multibounce_data *d, const multibounce_analysis *a)
{
    const multibounce_model talk = multibounce_model_jimenez2016();
    static const char *const headers[9] = {"albedo", "a", "b", "c", "talk a, b, c", "RMSE own cubic",
                                           "RMSE joint", "RMSE talk", "talk cubic < V_d"};
    report_table_begin(ctx->doc, 9, headers);
    for (int k = 0; k < d->albedo_count; ++k) {
        const multibounce_albedo_result *r = &a->per_albedo[k];
        const multibounce_fit *f = &r->fit;
        multibounce_cubic t = multibounce_cubic_at(&talk, r->albedo);
        char cells[9][CELL];
        snprintf(cells[0], CELL, "%.1f", (double)r->albedo);
        snprintf(cells[1], CELL, "%.3f ± %.3f", f->model.a[0], f->standard_errors[0]);
        snprintf(cells[2], CELL, "%.3f ± %.3f", f->model.b[0], f->standard_errors[1]);
        snprintf(cells[3], CELL, "%.3f ± %.3f", f->model.c[0], f->standard_errors[2]);
        snprintf(cells[4], CELL, "%.3f, %.3f, %.3f", t.a, t.b, t.c);
        snprintf(cells[5], CELL, "%.4f", r->own.rmse);
        snprintf(cells[6], CELL, "%.4f", r->linear.rmse);
        snprintf(cells[7], CELL, "%.4f", r->talk.rmse);
        snprintf(cells[8], CELL, "%.1f%%", 100.0 * r->talk.below);
        row_of(ctx->doc, 9, cells);
    }
    report_table_end(ctx->doc);
}

static void heldout_table(all_context *ctx, const multibounce_data *d, const multibounce_analysis *a)
{
    static const char *const headers[6] = {"held-out scene", "RMSE joint linear", "RMSE joint quadratic",
                                           "RMSE joint anchored", "RMSE talk", "samples"};
    report_table_begin(ctx->doc, 6, headers);
    char cells[6][CELL];
    for (int i = 0; i <= a->heldout_count; ++i) {
        const int mean = i == a->heldout_count;
        const multibounce_heldout *h = &a->heldout[mean ? 0 : i];
        snprintf(cells[0], CELL, "%s", mean ? "mean" : d->scenes[h->scene]);
        for (int j = 0; j < MB_JOINT_COUNT; ++j)
            snprintf(cells[1 + j], CELL, a->has[j] ? "%.4f" : "n/a", mean ? a->heldout_mean[j] : h->err[j].rmse);
        snprintf(cells[4], CELL, "%.4f", mean ? a->heldout_mean_talk : h->talk.rmse);
        snprintf(cells[5], CELL, "%zu", mean ? d->count : h->talk.samples);
        row_of(ctx->doc, 6, cells);
    }
    report_table_end(ctx->doc);
}

/* ---- Figures ------------------------------------------------------------------------------ */

/* Per albedo (gnuplot index k): up to SCATTER_POINTS samples (V_d, V'_d),
 * taken at a regular stride over every scene. */
static int write_scatter_data(const multibounce_data *d, const char *path, gt_error *e)
{
    size_t size = (size_t)d->albedo_count * (SCATTER_POINTS + 8) * 32 + 1024, used = 0;
    char *text = malloc(size);
    if (!text)
        return gt_error_set(e, path, "out of memory");
    used += (size_t)snprintf(text, size, "# V_d V'_d, one block per albedo (gtlab all)\n");
    for (int k = 0; k < d->albedo_count; ++k) {
        size_t in_albedo = 0, taken = 0;
        for (size_t i = 0; i < d->count; ++i)
            in_albedo += d->samples[i].albedo_index == k;
        size_t stride = in_albedo / SCATTER_POINTS + 1, seen = 0;
        for (size_t i = 0; i < d->count && taken < SCATTER_POINTS; ++i) {
            const multibounce_sample *s = &d->samples[i];
            if (s->albedo_index != k || seen++ % stride != 0)
                continue;
            used += (size_t)snprintf(text + used, size - used, "%.5f %.5f\n", (double)s->visibility,
                                     (double)s->multibounce);
            ++taken;
        }
        used += (size_t)snprintf(text + used, size - used, "\n\n");
    }
    int rc = atomic_write_text(path, text, e);
    free(text);
    return rc;
}

/* Per albedo: x, the talk's curve, ours (joint), the albedo's own cubic — all
 * evaluated by realtime/multibounce.c, never re-typed in gnuplot. */
static int write_curve_data(const multibounce_data *d, const multibounce_analysis *a, const char *path, gt_error *e)
{
    size_t size = (size_t)d->albedo_count * (CURVE_STEPS + 4) * 64 + 256, used = 0;
    char *text = malloc(size);
    if (!text)
        return gt_error_set(e, path, "out of memory");
    const multibounce_model talk = multibounce_model_jimenez2016();
    used += (size_t)snprintf(text, size, "# V_d talk gtlab_joint per_albedo_cubic, one block per albedo\n");
    for (int k = 0; k < d->albedo_count; ++k) {
        float rho = d->albedos[k];
        for (int i = 0; i <= CURVE_STEPS; ++i) {
            double x = (double)i / CURVE_STEPS;
            used += (size_t)snprintf(text + used, size - used, "%.4f %.6f %.6f %.6f\n", x,
                                     gtao_multibounce(&talk, x, rho), gtao_multibounce(&a->joint[MB_JOINT_LINEAR].model, x, rho),
                                     gtao_multibounce(&a->per_albedo[k].fit.model, x, rho));
        }
        used += (size_t)snprintf(text + used, size - used, "\n\n");
    }
    int rc = atomic_write_text(path, text, e);
    free(text);
    return rc;
}

/* Block 0: per-albedo a, b, c with standard errors; block 1: the joint
 * models' a, b, c over rho in [0, 1] (ours linear, talk, ours quadratic,
 * ours anchored; a model the data cannot determine repeats the linear). */
static int write_coefficient_data(const multibounce_data *d, const multibounce_analysis *a, const char *path,
                                  gt_error *e)
{
    size_t size = (size_t)(d->albedo_count + CURVE_STEPS + 8) * 200, used = 0;
    char *text = malloc(size);
    if (!text)
        return gt_error_set(e, path, "out of memory");
    used += (size_t)snprintf(text, size, "# rho a se_a b se_b c se_c (per-albedo fits)\n");
    for (int k = 0; k < d->albedo_count; ++k) {
        const multibounce_fit *f = &a->per_albedo[k].fit;
        used += (size_t)snprintf(text + used, size - used, "%.3f %.6f %.6f %.6f %.6f %.6f %.6f\n",
                                 (double)d->albedos[k], f->model.a[0], f->standard_errors[0], f->model.b[0],
                                 f->standard_errors[1], f->model.c[0], f->standard_errors[2]);
    }
    used += (size_t)snprintf(text + used, size - used,
                             "\n\n# rho a b c (ours linear) a b c (talk) a b c (ours quadratic) a b c (ours anchored)\n");
    const multibounce_model talk = multibounce_model_jimenez2016();
    const multibounce_model *models[4] = {&a->joint[MB_JOINT_LINEAR].model, &talk,
                                          &a->joint[a->has[MB_JOINT_QUADRATIC] ? MB_JOINT_QUADRATIC : 0].model,
                                          &a->joint[MB_JOINT_ANCHORED].model};
    for (int i = 0; i <= CURVE_STEPS; ++i) {
        double rho = (double)i / CURVE_STEPS;
        used += (size_t)snprintf(text + used, size - used, "%.3f", rho);
        for (int m = 0; m < 4; ++m) {
            multibounce_cubic c = multibounce_cubic_at(models[m], rho);
            used += (size_t)snprintf(text + used, size - used, " %.6f %.6f %.6f", c.a, c.b, c.c);
        }
        used += (size_t)snprintf(text + used, size - used, "\n");
    }
    int rc = atomic_write_text(path, text, e);
    free(text);
    return rc;
}

static int plot_scatter(const stage *st, gt_error *e)
{
    char points[4096], curves[4096], png[4096], script[16384];
    snprintf(points, sizeof points, "%s/multibounce_scatter.dat", st->figures);
    snprintf(curves, sizeof curves, "%s/multibounce_curves.dat", st->figures);
    snprintf(png, sizeof png, "%s/multibounce_scatter.png", st->figures);
    if (write_scatter_data(&st->data, points, e) != 0 || write_curve_data(&st->data, st->analysis, curves, e) != 0)
        return -1;
    size_t used = (size_t)snprintf(script, sizeof script,
                                   "set multiplot layout 2,4 title \"V'_d against V_d, 4 bounces, %d scenes\"\n"
                                   "set xrange [0:1]\nset yrange [0:1]\nset key top left font ',8'\n"
                                   "set xlabel 'V_d'\nset ylabel \"V'_d\"\nset grid\n",
                                   st->data.scene_count);
    for (int k = 0; k < st->data.albedo_count; ++k)
        used += (size_t)snprintf(script + used, sizeof script - used,
                                 "set title 'albedo %.1f'\n"
                                 "plot '%s' index %d using 1:2 with points pt 7 ps 0.15 lc rgb '#a0a0a0' title "
                                 "'samples', '%s' index %d using 1:2 with lines lw 2 lc rgb '#d62728' title 'talk', "
                                 "'' index %d using 1:3 with lines lw 2 lc rgb '#1f77b4' title 'gtlab joint', "
                                 "'' index %d using 1:4 with lines lw 1 dt 2 lc rgb '#2ca02c' title 'own cubic', "
                                 "x with lines dt 3 lc rgb 'black' title 'V_d'\n",
                                 (double)st->data.albedos[k], points, k, curves, k, k, k);
    snprintf(script + used, sizeof script - used, "unset multiplot\n");
    return gnuplot_render(script, png, 1600, 850, e);
}

static int plot_coefficients(const stage *st, gt_error *e)
{
    char data[4096], png[4096], script[8192];
    snprintf(data, sizeof data, "%s/multibounce_coefficients.dat", st->figures);
    snprintf(png, sizeof png, "%s/multibounce_coefficients.png", st->figures);
    if (write_coefficient_data(&st->data, st->analysis, data, e) != 0)
        return -1;
    size_t used = (size_t)snprintf(script, sizeof script,
                                   "set multiplot layout 1,3 title 'cubic coefficients against the albedo'\n"
                                   "set xrange [0:1]\nset xlabel 'albedo'\nset grid\nset key bottom left font ',8'\n");
    for (int c = 0; c < 3; ++c)
        used += (size_t)snprintf(script + used, sizeof script - used,
                                 "set title '%c'\n"
                                 "plot '%s' index 0 using 1:%d:%d with yerrorbars pt 7 lc rgb 'black' title "
                                 "'per-albedo fit (± s.e.)', '' index 1 using 1:%d with lines lw 2 lc rgb "
                                 "'#1f77b4' title 'gtlab joint linear', '' index 1 using 1:%d with lines lw 2 "
                                 "lc rgb '#d62728' title 'talk', '' index 1 using 1:%d with lines dt 2 lc rgb "
                                 "'#2ca02c' title 'gtlab joint quadratic', '' index 1 using 1:%d with lines dt 4 "
                                 "lc rgb '#9467bd' title 'gtlab joint anchored'\n",
                                 "abc"[c], data, 2 + 2 * c, 3 + 2 * c, 2 + c, 5 + c, 8 + c, 11 + c);
    snprintf(script + used, sizeof script - used, "unset multiplot\n");
    return gnuplot_render(script, png, 1500, 500, e);
}

static void figures_section(all_context *ctx, const stage *st)
{
    if (!gnuplot_available()) {
        gt_warn("gtlab all", "gnuplot not found: multi-bounce plots skipped (Debian package gnuplot-nox)");
        report_paragraph(ctx->doc, "(Plots skipped: gnuplot was not found.)");
        return;
    }
    gt_error e;
    const char *paths[2] = {"figures/multibounce_scatter.png", "figures/multibounce_coefficients.png"};
    const char *captions[2] = {"per albedo: samples (V_d, V'_d) of every scene, the talk's curve, our joint "
                               "fit and the albedo's own cubic",
                               "a, b, c of the per-albedo cubics (± standard error) and the joint models"};
    if (plot_scatter(st, &e) != 0 || plot_coefficients(st, &e) != 0) {
        gt_warn("gtlab all", "plot failed: %s", e.message);
        report_paragraph(ctx->doc, "(Plots failed: %s)", e.message);
        return;
    }
    report_figures(ctx->doc, 1, &paths[0], &captions[0]);
    report_figures(ctx->doc, 1, &paths[1], &captions[1]);
}

/* ---- What the data show ------------------------------------------------------------------ */

/* The coefficient farthest from the talk's, in our standard errors
 * (per-pixel, or jackknife over scenes). */
static int farthest_coefficient(const multibounce_analysis *a, int by_scene, double *sigmas)
{
    const multibounce_model talk = multibounce_model_jimenez2016();
    double ours[6], theirs[6];
    multibounce_model_to_vector(&a->joint[MB_JOINT_LINEAR].model, ours);
    multibounce_model_to_vector(&talk, theirs);
    int worst = 0;
    *sigmas = 0.0;
    for (int i = 0; i < 6; ++i) {
        double z = fabs(theirs[i] - ours[i]) /
                   (by_scene ? a->jackknife_se[MB_JOINT_LINEAR][i] : a->joint[MB_JOINT_LINEAR].standard_errors[i]);
        if (z > *sigmas) {
            *sigmas = z;
            worst = i;
        }
    }
    return worst;
}

/* Largest difference between the joint linear coefficients and the talk's two-step lines. */
static double two_step_gap(const multibounce_analysis *a)
{
    double joint[6], lines[6], gap = 0.0;
    multibounce_model_to_vector(&a->joint[MB_JOINT_LINEAR].model, joint);
    multibounce_model_to_vector(&a->two_step, lines);
    for (int k = 0; k < 6; ++k)
        gap = fmax(gap, fabs(joint[k] - lines[k]));
    return gap;
}

static void findings(all_context *ctx, const stage *st)
{
    const multibounce_analysis *a = st->analysis;
    const multibounce_data *d = &st->data;
    static const char *const names[6] = {"a0", "a1", "b0", "b1", "c0", "c1"};
    double sigmas, scene_sigmas;
    int worst = farthest_coefficient(a, 0, &sigmas), scene_worst = farthest_coefficient(a, 1, &scene_sigmas);
    int talk_wins = 0;
    for (int i = 0; i < a->heldout_count; ++i)
        talk_wins += a->heldout[i].talk.rmse < a->heldout[i].err[MB_JOINT_LINEAR].rmse;
    const multibounce_model talk = multibounce_model_jimenez2016();
    float low = d->albedos[0];
    double ours_worst = -INFINITY, ours_worst_rho = 0.0;
    for (int k = 0; k < d->albedo_count; ++k)
        if (multibounce_max_shortfall(&a->joint[MB_JOINT_LINEAR].model, d->albedos[k]) > ours_worst) {
            ours_worst = multibounce_max_shortfall(&a->joint[MB_JOINT_LINEAR].model, d->albedos[k]);
            ours_worst_rho = d->albedos[k];
        }
    report_paragraph(
        ctx->doc,
        "What the data show. On %zu samples (%d scenes x %d albedos, every scene and albedo weighted equally) "
        "the talk's coefficients give a weighted RMSE of %.4f (max error %.3f); our joint refit of the same "
        "form gives %.4f (max %.3f), and one cubic per albedo %.4f at albedo %.1f to %.4f at %.1f. Our "
        "coefficients differ from the talk's by up to %.0f of their per-pixel standard errors (%s): on these "
        "scenes the talk's numbers are not the least-squares optimum, though the curves they give are close "
        "(a, b and c are strongly correlated). The per-pixel standard errors treat pixels as independent; "
        "the jackknife over scenes (from the leave-one-scene-out fits) measures how much the coefficients move "
        "with the content, and by it the talk's coefficients are at most %.1f standard errors (%s) from ours: "
        "within the spread of content. Generalisation: "
        "fitted without a scene and scored on it, our linear model's RMSE averages %.4f over the %d scenes "
        "against %.4f for the talk's (the talk's is better on %d of them): one curve does not serve all "
        "content to better than a few hundredths, and the scene-to-scene spread is larger than the difference "
        "between the two coefficient sets. Alternatives, held out the same way: a, b, c quadratic in the albedo "
        "%.4f, the anchored form (exact at albedo 0 and V_d = 0, 1, 4 parameters) %.4f; chosen: %s. The max(V_d, "
        ".): the talk's cubic falls below V_d by up to %.4f at albedo %.1f and by up to %.3f at albedo 0; on "
        "the data it is lower than V_d by more than 0.001 for %.1f%% of the weighted samples, and the max "
        "changes its RMSE from %.5f to %.5f. So the max is a guard for albedos below about 0.1, where the "
        "talk's linear coefficients fall short of V'_d >= V_d; at the talk's albedos it changes little. Our "
        "refit's cubic falls below V_d by up to %.4f (albedo %.1f) and %.3f at albedo 0. The largest errors are "
        "not noise: the talk's worst pixel (%s, albedo %.1f) has V_d = %.3f but V'_d = %.3f. Where a point sees "
        "little sky but much lit surface (contacts, crevices facing bright walls), V'_d is not a function of "
        "V_d, and no curve in V_d alone can follow it. The talk's own procedure (lines through the per-albedo "
        "coefficients) gives the joint fit's coefficients to %.1e here: when every albedo is rendered on the "
        "same pixels with the same weights, as one multi-bounce pass does, least squares decomposes that way "
        "exactly; a joint fit differs only where the albedos' samples differ.",
        d->count, d->scene_count, d->albedo_count, a->talk_err[1].rmse, a->talk_err[1].max_abs, a->joint_err[MB_JOINT_LINEAR][1].rmse,
        a->joint_err[MB_JOINT_LINEAR][1].max_abs, a->per_albedo[0].own.rmse, (double)low, a->per_albedo[d->albedo_count - 1].own.rmse,
        (double)d->albedos[d->albedo_count - 1], sigmas, names[worst], scene_sigmas, names[scene_worst],
        a->heldout_mean[MB_JOINT_LINEAR], a->heldout_count,
        a->heldout_mean_talk, talk_wins,
        a->heldout_mean[MB_JOINT_QUADRATIC], a->heldout_mean[MB_JOINT_ANCHORED], multibounce_joint_names[a->chosen],
        multibounce_max_shortfall(&talk, low), (double)low,
        multibounce_max_shortfall(&talk, 0.0), 100.0 * a->talk_err[0].below, a->talk_err[0].rmse, a->talk_err[1].rmse,
        ours_worst, ours_worst_rho, multibounce_max_shortfall(&a->joint[MB_JOINT_LINEAR].model, 0.0),
        d->scenes[a->talk_err[1].worst.scene], (double)a->talk_err[1].worst.albedo,
        (double)a->talk_err[1].worst.visibility, (double)a->talk_err[1].worst.multibounce, two_step_gap(a));
    const multibounce_model *ours = &a->joint[MB_JOINT_LINEAR].model;
    report_finding(ctx->doc, "GTAO multi-bounce",
                   "refit a = %.3f %+.3f rho, b = %.3f %+.3f rho, c = %.3f %+.3f rho; weighted RMSE %.4f against "
                   "the talk's %.4f on the same data; fitted without the scene scored, %.4f against %.4f (the "
                   "talk's better on %d of %d scenes); the talk's coefficients lie within %.1f jackknife standard "
                   "errors of ours.",
                   ours->a[0], ours->a[1], ours->b[0], ours->b[1], ours->c[0], ours->c[1],
                   a->joint_err[MB_JOINT_LINEAR][1].rmse, a->talk_err[1].rmse, a->heldout_mean[MB_JOINT_LINEAR],
                   a->heldout_mean_talk, talk_wins, a->heldout_count, scene_sigmas);
}

static void add_summary(all_context *ctx, const stage *st, cJSON *validation)
{
    const multibounce_analysis *a = st->analysis;
    cJSON *o = cJSON_AddObjectToObject(ctx->summary, "multibounce");
    cJSON_AddStringToObject(o, "fit", "fits/multibounce.json");
    cJSON_AddNumberToObject(o, "samples", (double)st->data.count);
    double p[6];
    multibounce_model_to_vector(&a->joint[MB_JOINT_LINEAR].model, p);
    cJSON_AddItemToObject(o, "joint_linear", cJSON_CreateDoubleArray(p, 6));
    cJSON_AddItemToObject(o, "joint_linear_standard_errors", cJSON_CreateDoubleArray(a->joint[MB_JOINT_LINEAR].standard_errors, 6));
    cJSON_AddNumberToObject(o, "rmse_ours", a->joint_err[MB_JOINT_LINEAR][1].rmse);
    cJSON_AddNumberToObject(o, "rmse_talk", a->talk_err[1].rmse);
    cJSON_AddNumberToObject(o, "rmse_talk_without_max", a->talk_err[0].rmse);
    cJSON_AddNumberToObject(o, "fraction_talk_cubic_below_v_d", a->talk_err[0].below);
    cJSON_AddNumberToObject(o, "heldout_mean_rmse_linear", a->heldout_mean[MB_JOINT_LINEAR]);
    cJSON_AddNumberToObject(o, "heldout_mean_rmse_quadratic", a->heldout_mean[MB_JOINT_QUADRATIC]);
    cJSON_AddNumberToObject(o, "heldout_mean_rmse_talk", a->heldout_mean_talk);
    cJSON_AddNumberToObject(o, "heldout_mean_rmse_anchored", a->heldout_mean[MB_JOINT_ANCHORED]);
    cJSON_AddStringToObject(o, "chosen", multibounce_joint_names[a->chosen]);
    cJSON *renders = cJSON_AddArrayToObject(o, "renders");
    for (int k = 0; k < SCENES; ++k) {
        cJSON *r = cJSON_CreateObject();
        cJSON_AddStringToObject(r, "scene", kScenes[k]);
        cJSON_AddNumberToObject(r, "seconds", st->stats[k].seconds);
        cJSON_AddNumberToObject(r, "paths", (double)st->stats[k].samples);
        cJSON_AddNumberToObject(r, "rays", (double)st->stats[k].rays);
        cJSON_AddItemToArray(renders, r);
    }
    cJSON_AddItemToObject(o, "validation", validation);
}

/* ---- Performance ------------------------------------------------------------------------ */

/* A short `gtlab bench multibounce` on one scene, and the fit's own times. */
static int performance(all_context *ctx, const stage *st, const reference_request *req, cJSON *json, gt_error *e)
{
    const char *spec = "builtin:menger";
    scene s;
    if (scene_load(spec, &s, e) != 0)
        return -1;
    camera cam;
    multibounce_benchmark b;
    int rc = scene_choose_camera(&s, NULL, 96, 96, &cam, e);
    if (rc == 0)
        rc = multibounce_benchmark_run(&s, &cam, &req->multibounce, 32, ctx->threads, 1, &b, e);
    scene_free(&s);
    if (rc != 0)
        return -1;
    const multibounce_fit *f = &st->analysis->joint[MB_JOINT_LINEAR];
    report_heading(ctx->doc, 3, "Performance");
    report_paragraph(ctx->doc,
                     "On %s (96x96, 32 paths per pixel, %d albedos; 'gtlab bench multibounce' measures the same "
                     "at any size): the multi-bounce loop traces %.3g paths/s and %.3g rays/s on one core, raw "
                     "Embree closest-hit queries (rtcIntersect1) on the paths' first rays %.3g rays/s: a ratio of "
                     "%.2f (the loop also samples directions, interpolates hit normals and accumulates %d channels). "
                     "With %d threads: %.3g paths/s. All %d albedos in one pass took %.2f s against %.2f s for one "
                     "render per albedo: %.1fx cheaper. The joint fit of this stage (%zu samples, blocks of %d) "
                     "solved in %.2f s; 'gtlab bench fit' times a million samples.",
                     spec, req->multibounce.albedo_count, b.paths_per_s[0], b.rays_per_s[0], b.raw_intersect1[0],
                     b.rays_per_s[0] / b.raw_intersect1[0], req->multibounce.albedo_count + 1, b.threads,
                     b.paths_per_s[1], req->multibounce.albedo_count, b.seconds_one_pass, b.seconds_separate,
                     b.seconds_separate / b.seconds_one_pass, st->data.count, MBFIT_DEFAULT_BLOCK, f->solver.seconds);
    cJSON_AddNumberToObject(json, "paths_per_s_1_thread", b.paths_per_s[0]);
    cJSON_AddNumberToObject(json, "rays_per_s_1_thread", b.rays_per_s[0]);
    cJSON_AddNumberToObject(json, "raw_intersect1_rays_per_s_1_thread", b.raw_intersect1[0]);
    cJSON_AddNumberToObject(json, "one_pass_seconds", b.seconds_one_pass);
    cJSON_AddNumberToObject(json, "separate_renders_seconds", b.seconds_separate);
    cJSON_AddNumberToObject(json, "joint_fit_solve_seconds", f->solver.seconds);
    return 0;
}

/* ---- The stage ----------------------------------------------------------------------------- */

static int run_fit(all_context *ctx, stage *st, gt_error *e)
{
    char fits[2048], json[4096], header[4096], hlsl[4096], glsl[4096];
    if (all_make_dir(ctx, "fits", fits, sizeof fits, e) != 0)
        return -1;
    snprintf(json, sizeof json, "%s/multibounce.json", fits);
    snprintf(header, sizeof header, "%s/multibounce.h", fits);
    snprintf(hlsl, sizeof hlsl, "%s/multibounce.hlsl", fits);
    snprintf(glsl, sizeof glsl, "%s/multibounce.glsl", fits);
    multibounce_data_weigh(&st->data);
    if (multibounce_analyse(&st->data, st->analysis, e) != 0)
        return -1;
    return multibounce_write_outputs(&st->data, st->analysis,
                                     ctx->quality == QUALITY_PREVIEW ? "gtlab all --quality preview"
                                                                     : "gtlab all --quality production",
                                     json, header, hlsl, glsl, e);
}

static void intro(all_context *ctx, const reference_request *req, const stage *st)
{
    report_heading(ctx->doc, 2, "Multi-bounce AO: references and the GTAO refit");
    double seconds = 0.0, paths = 0.0, rays = 0.0;
    for (int k = 0; k < SCENES; ++k) {
        seconds += st->stats[k].seconds;
        paths += (double)st->stats[k].samples;
        rays += (double)st->stats[k].rays;
    }
    report_paragraph(ctx->doc,
                     "Jimenez et al. 2016 ('Multiple Bounces'): V'_d = L / rho of a Lambertian surface of albedo rho "
                     "under a white dome, every surface of albedo rho, %d bounces (inter-reflections after the first "
                     "hit, the talk's 4), against the single-bounce V_d of the same paths. One pass per scene serves "
                     "all %d albedos (0.1 to 0.9; the talk does not list its seven). %d scenes at %dx%d, %d samples "
                     "per pixel: %.3g paths and %.3g rays in %.1f s. Fit (gtlab fit multibounce; "
                     "fits/multibounce.json, .h, .hlsl): per albedo V'_d = ((a V_d + b) V_d + c) V_d, and jointly "
                     "a, b, c linear in rho fitted to all samples at once through Ceres, each scene and albedo "
                     "weighted equally; standard errors from Ceres' covariance (pixels taken as independent) and, "
                     "more telling, the jackknife over scenes. At preview quality V_d itself carries Monte Carlo noise "
                     "(errors in the variable the fit takes as exact), which flattens fitted curves slightly; "
                     "production renders 2048 paths per pixel.",
                     req->multibounce.bounces, ALBEDOS, SCENES, st->refs[0].width, st->refs[0].height,
                     req->sampling.spp, paths, rays, seconds);
}

int all_stage_multibounce(all_context *ctx, gt_error *e)
{
    stage *st = calloc(1, sizeof *st);
    if (!st || !(st->analysis = malloc(sizeof *st->analysis))) {
        free(st);
        return gt_error_set(e, "multibounce", "out of memory");
    }
    multibounce_data_init(&st->data);
    const reference_request req = request(ctx);
    char dir[2048];
    int rc = multibounce_plan_init(&st->plan, &req.multibounce, req.normals, e);
    if (rc == 0)
        rc = all_make_dir(ctx, "multibounce", dir, sizeof dir, e);
    if (rc == 0)
        rc = all_make_dir(ctx, "figures", st->figures, sizeof st->figures, e);
    for (int k = 0; k < SCENES && rc == 0; ++k)
        rc = render_reference(ctx, k, dir, st, e);
    if (rc == 0)
        rc = run_fit(ctx, st, e);
    cJSON *validation = cJSON_CreateArray();
    if (rc == 0) {
        intro(ctx, &req, st);
        coefficient_table(ctx, st->analysis);
        report_heading(ctx->doc, 3, "Per albedo");
        per_albedo_table(ctx, &st->data, st->analysis);
        report_heading(ctx->doc, 3, "Leave one scene out");
        heldout_table(ctx, &st->data, st->analysis);
        findings(ctx, st);
        figures_section(ctx, st);
        rc = validation_section(ctx, st, validation, e);
    }
    if (rc == 0)
        add_summary(ctx, st, validation);
    if (rc == 0)
        rc = performance(ctx, st, &req, cJSON_GetObjectItem(ctx->summary, "multibounce"), e);
    else
        cJSON_Delete(validation);
    for (int k = 0; k < SCENES; ++k) {
        if (st->rendered[k])
            image_free(&st->refs[k]);
        if (st->split[k]) {
            image_free(&st->halves[k][0]);
            image_free(&st->halves[k][1]);
        }
    }
    multibounce_data_free(&st->data);
    free(st->analysis);
    free(st);
    return rc;
}
