/* Colour (multibounce/multibounce_study.h, multibounce_colour_study; issue 25, item
 * 2): the talk's f per colour channel against coloured references. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/reference_schema.h"
#include "metrics/image_error.h"
#include "metrics/reference_halves.h"
#include "metrics/ssim.h"
#include "multibounce/multibounce_parts.h"
#include "multibounce/multibounce_quality.h"
#include "multibounce/multibounce_quantity.h"
#include "scene/scene_loaders.h"

/* The coloured scenes: the Cornell box as built, and two of the white
 * scenes coloured, one uniformly, one with floor and objects of different hues. */
typedef struct {
    const char *name;
    int recolour;
    float floor[3], objects[3];
} colour_scene;

static const colour_scene kScenes[MULTIBOUNCE_COLOUR_SCENES] = {
    {"cornell", 0, {0}, {0}},
    {"menger", 1, {0.8f, 0.5f, 0.2f}, {0.8f, 0.5f, 0.2f}},
    {"boxes", 1, {0.2f, 0.4f, 0.8f}, {0.8f, 0.3f, 0.1f}},
};

static const double kLuminance[3] = {MULTIBOUNCE_LUMINANCE_R, MULTIBOUNCE_LUMINANCE_G, MULTIBOUNCE_LUMINANCE_B};

static int load_colour_scene(const colour_scene *c, const char *spec, scene *s, gt_error *e)
{
    if (!c->recolour)
        return scene_load(spec, s, e);
    return multibounce_load_two_albedo_scene(spec, c->floor, c->objects, s, e);
}

static int render_colour(const study_context *ctx, const reference_request *base, const colour_scene *c,
                         const char *spec, image *img, gt_error *e)
{
    multibounce_render_settings mb = {{QUANTITY_MULTIBOUNCE},
                                      {.scene_albedo = 1, .bounces = multibounce_settings_of(base)->bounces}};
    reference_request req = *base;
    req.settings = &mb.header;
    scene s;
    if (load_colour_scene(c, spec, &s, e) != 0)
        return -1;
    camera cam;
    render_stats stats;
    int rc = scene_choose_camera(&s, NULL, multibounce_quality_of(ctx->quality)->image_width, 0, &cam, e);
    if (rc == 0)
        rc = reference_render(&s, spec, &cam, &req, img, &stats, e);
    scene_free(&s);
    return rc;
}

/* The images compared: per channel V'_c (approximation, odd half, even half),
 * and the luminances of rho_c V'_c. */
typedef struct {
    float *approx[3], *odd[3], *even[3];
    float *lum_approx, *lum_grey, *lum_odd, *lum_even;
} colour_planes;

static void fill_planes(const image *img, const image halves[2], colour_planes *p)
{
    const multibounce_model talk = multibounce_model_jimenez2016();
    const char *const albedo_names[3] = CH_ALBEDO_RGB, *const mb_names[3] = CH_MULTIBOUNCE_RGB;
    const float *mask = image_channel_data(img, CH_MASK), *vd = image_channel_data(&halves[0], CH_AO);
    for (size_t i = 0; i < image_pixel_count(img); ++i) {
        double rho[3], rho_y = 0.0, lum[4] = {0};
        for (int c = 0; c < 3; ++c)
            rho_y += kLuminance[c] * (rho[c] = image_channel_data(img, albedo_names[c])[i]);
        for (int c = 0; c < 3; ++c) {
            p->approx[c][i] = mask[i] != 0.0f ? (float)gtao_multibounce(&talk, vd[i], rho[c]) : 0.0f;
            p->odd[c][i] = image_channel_data(&halves[1], mb_names[c])[i];
            p->even[c][i] = image_channel_data(&halves[0], mb_names[c])[i];
            lum[0] += kLuminance[c] * rho[c] * p->approx[c][i];
            lum[1] += kLuminance[c] * rho[c] * (mask[i] != 0.0f ? gtao_multibounce(&talk, vd[i], rho_y) : 0.0);
            lum[2] += kLuminance[c] * rho[c] * p->odd[c][i];
            lum[3] += kLuminance[c] * rho[c] * p->even[c][i];
        }
        p->lum_approx[i] = (float)lum[0];
        p->lum_grey[i] = (float)lum[1];
        p->lum_odd[i] = (float)lum[2];
        p->lum_even[i] = (float)lum[3];
    }
}

static int dssim(const float *a, const float *b, const image *img, const char *what, double *out, gt_error *e)
{
    ssim_result s;
    if (ssim_compute(a, b, image_channel_data(img, CH_MASK), img->width, img->height, what, NULL, &s, e) != 0)
        return -1;
    *out = s.dssim;
    return 0;
}

static int rmse(const float *a, const float *b, const image *img, const char *what, double *out, gt_error *e)
{
    image_error_stats s;
    if (image_error_compute(a, b, image_channel_data(img, CH_MASK), img->width, img->height, what, &s, e) != 0)
        return -1;
    *out = s.rmse;
    return 0;
}

static int score_planes(const colour_planes *p, const image *img, const char *what, multibounce_colour_row *row,
                        gt_error *e)
{
    for (int c = 0; c < 3; ++c)
        if (dssim(p->approx[c], p->odd[c], img, what, &row->dssim_channel[c], e) != 0 ||
            dssim(p->even[c], p->odd[c], img, what, &row->noise_floor_dssim_channel[c], e) != 0)
            return -1;
    if (dssim(p->lum_approx, p->lum_odd, img, what, &row->dssim_luminance, e) != 0 ||
        dssim(p->lum_even, p->lum_odd, img, what, &row->noise_floor_dssim_luminance, e) != 0 ||
        dssim(p->lum_grey, p->lum_odd, img, what, &row->dssim_luminance_grey, e) != 0)
        return -1;
    return rmse(p->lum_approx, p->lum_odd, img, what, &row->rmse_luminance, e) != 0 ||
                   rmse(p->lum_grey, p->lum_odd, img, what, &row->rmse_luminance_grey, e) != 0
               ? -1
               : 0;
}

/* One coloured scene: render, split, score into row. */
static int colour_row(const study_context *ctx, const reference_request *req, const colour_scene *c,
                      multibounce_colour_row *row, gt_error *e)
{
    char spec[128];
    snprintf(spec, sizeof spec, "builtin:%s", c->name);
    snprintf(row->scene, sizeof row->scene, "%s%s", c->name, c->recolour ? " (coloured)" : "");
    image img, halves[2];
    if (render_colour(ctx, req, c, spec, &img, e) != 0)
        return -1;
    if (reference_halves_split(&img, spec, halves, e) != 0) {
        image_free(&img);
        return -1;
    }
    const size_t n = image_pixel_count(&img);
    float *buffer = calloc(13 * n, sizeof *buffer);
    int rc = buffer ? 0 : gt_error_set(e, spec, "out of memory");
    if (rc == 0) {
        colour_planes p = {{buffer, buffer + n, buffer + 2 * n}, {buffer + 3 * n, buffer + 4 * n, buffer + 5 * n},
                           {buffer + 6 * n, buffer + 7 * n, buffer + 8 * n}, buffer + 9 * n, buffer + 10 * n,
                           buffer + 11 * n, buffer + 12 * n};
        fill_planes(&img, halves, &p);
        rc = score_planes(&p, &img, spec, row, e);
    }
    free(buffer);
    image_free(&halves[0]);
    image_free(&halves[1]);
    image_free(&img);
    return rc;
}

int multibounce_study_colour(const study_context *ctx, const reference_request *req, multibounce_colour_study *out,
                             gt_error *e)
{
    memset(out, 0, sizeof *out);
    const int n = MULTIBOUNCE_COLOUR_SCENES;
    for (int k = 0; k < n; ++k) {
        if (colour_row(ctx, req, &kScenes[k], &out->rows[k], e) != 0)
            return -1;
        out->mean_dssim_luminance += out->rows[k].dssim_luminance / n;
        out->mean_noise_floor_dssim_luminance += out->rows[k].noise_floor_dssim_luminance / n;
        out->mean_dssim_luminance_grey += out->rows[k].dssim_luminance_grey / n;
    }
    double ss = 0.0;
    for (int k = 0; k < n; ++k)
        ss += (out->rows[k].dssim_luminance - out->mean_dssim_luminance) *
              (out->rows[k].dssim_luminance - out->mean_dssim_luminance);
    out->mean_dssim_luminance_se = sqrt(ss / (n - 1) / n);
    return 0;
}
