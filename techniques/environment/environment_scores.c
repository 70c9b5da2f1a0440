/* One case of the environment study: every combination's image, its error
 * split into the lighting's, the occlusion's and the total (environment_approx.h), and the side-by-side images. */
#include "environment/environment_parts.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/image_io.h"
#include "core/reference_schema.h"
#include "metrics/image_error.h"
#include "metrics/noise_corrected.h"
#include "metrics/ssim.h"
#include "specular_occlusion/specular_occlusion_inputs.h"

/* Scratch planes of one case: approximations (occluded, unoccluded), the
 * occlusion part's mix, and two luminance planes. */
typedef struct {
    int width, height;
    size_t n;
    const float *mask;
    float *block, *occ[3], *unocc[3], *mix[3], *lum_a, *lum_b;
} case_planes;

static int planes_init(case_planes *p, int width, int height, const float *mask)
{
    p->width = width, p->height = height, p->n = (size_t)width * height, p->mask = mask;
    p->block = calloc(11 * p->n, sizeof(float));
    if (!p->block)
        return -1;
    for (int c = 0; c < 3; ++c)
        p->occ[c] = p->block + c * p->n, p->unocc[c] = p->block + (3 + c) * p->n, p->mix[c] = p->block + (6 + c) * p->n;
    p->lum_a = p->block + 9 * p->n, p->lum_b = p->block + 10 * p->n;
    return 0;
}

static void luminance(const float *const rgb[3], size_t n, float *out)
{
    for (size_t i = 0; i < n; ++i)
        out[i] = 0.2126f * rgb[0][i] + 0.7152f * rgb[1][i] + 0.0722f * rgb[2][i];
}

static double masked_mean(const float *v, const float *mask, size_t n)
{
    double sum = 0.0;
    size_t count = 0;
    for (size_t i = 0; i < n; ++i)
        if (metrics_in_mask(mask, i))
            sum += v[i], count++;
    return count ? sum / count : 0.0;
}

/* Relative RMSE and DSSIM of approx against truth (luminance planes); approx is rescaled in place. */
static int score_luminance(const case_planes *p, float *truth, float *approx, const char *what, environment_score *s,
                           gt_error *e)
{
    double mean = masked_mean(truth, p->mask, p->n);
    image_error_stats err;
    ssim_result r;
    if (mean <= 0.0) {
        s->rmse = s->dssim = NAN;
        return 0;
    }
    if (image_error_compute(truth, approx, p->mask, p->width, p->height, what, &err, e) != 0)
        return -1;
    float scale = (float)(0.5 / mean);
    for (size_t i = 0; i < p->n; ++i)
        truth[i] *= scale, approx[i] *= scale;
    if (ssim_compute(truth, approx, p->mask, p->width, p->height, what, NULL, &r, e) != 0)
        return -1;
    s->rmse = err.rmse / mean, s->dssim = r.dssim;
    return 0;
}

static int score_rgb(const case_planes *p, const float *const truth[3], const float *const approx[3], const char *what,
                     environment_score *s, gt_error *e)
{
    luminance(truth, p->n, p->lum_a);
    luminance(approx, p->n, p->lum_b);
    return score_luminance(p, p->lum_a, p->lum_b, what, s, e);
}

/* The three parts from p->occ and p->unocc against the references. */
static int score_parts(case_planes *p, const float *const ref_occ[3], const float *const ref_unocc[3],
                       const char *what, environment_score parts[ENVIRONMENT_PARTS], gt_error *e)
{
    for (int c = 0; c < 3; ++c)
        for (size_t i = 0; i < p->n; ++i)
            p->mix[c][i] = p->unocc[c][i] > 0.0f ? ref_unocc[c][i] * (p->occ[c][i] / p->unocc[c][i]) : 0.0f;
    if (score_rgb(p, ref_unocc, (const float *const *)p->unocc, what, &parts[ENVIRONMENT_PART_LIGHTING], e) != 0 ||
        score_rgb(p, ref_occ, (const float *const *)p->mix, what, &parts[ENVIRONMENT_PART_OCCLUSION], e) != 0)
        return -1;
    return score_rgb(p, ref_occ, (const float *const *)p->occ, what, &parts[ENVIRONMENT_PART_TOTAL], e);
}

/* The RGB planes of a reference quantity (names from the schema). */
static int rgb_planes(const image *img, const char *const names[3], const char *what, const float *out[3], gt_error *e)
{
    for (int c = 0; c < 3; ++c)
        if (!(out[c] = image_channel_data(img, names[c])))
            return gt_error_set(e, what, "no channel %s", names[c]);
    return 0;
}

typedef struct {
    const float *direct[3], *bounces[3], *unoccluded[3], *specular[3], *specular_unoccluded[3], *albedo[3];
} case_references;

static int references(const environment_case *c, case_references *r, gt_error *e)
{
    static const char *const direct[3] = CH_ENV_DIFFUSE_DIRECT_RGB, *const bounces[3] = CH_ENV_DIFFUSE_RGB,
                             *const unocc[3] = CH_ENV_DIFFUSE_UNOCCLUDED_RGB, *const spec[3] = CH_ENV_SPECULAR_RGB,
                             *const spec_unocc[3] = CH_ENV_SPECULAR_UNOCCLUDED_RGB, *const albedo[3] = CH_ALBEDO_RGB;
    if (rgb_planes(c->diffuse, direct, c->what, r->direct, e) != 0 ||
        rgb_planes(c->diffuse, bounces, c->what, r->bounces, e) != 0 ||
        rgb_planes(c->diffuse, unocc, c->what, r->unoccluded, e) != 0 ||
        rgb_planes(c->specular, spec, c->what, r->specular, e) != 0 ||
        rgb_planes(c->specular, spec_unocc, c->what, r->specular_unoccluded, e) != 0)
        return -1;
    return rgb_planes(c->ao, albedo, c->what, r->albedo, e);
}

static int score_diffuse(const environment_case *c, const so_screen_buffers *b, const case_references *r, case_planes *p,
                         environment_case_scores *out, gt_error *e)
{
    for (int s = 0; s < ENVIRONMENT_IRRADIANCE_SOURCES; ++s) {
        environment_screen_diffuse(c->lighting, (environment_irradiance_source)s, ENVIRONMENT_DIFFUSE_UNOCCLUDED, b, r->albedo,
                                  p->unocc);
        for (int k = 1; k < ENVIRONMENT_DIFFUSE_KINDS; ++k) {
            int multibounce = k == ENVIRONMENT_DIFFUSE_MULTIBOUNCE_N || k == ENVIRONMENT_DIFFUSE_MULTIBOUNCE_BENT;
            environment_screen_diffuse(c->lighting, (environment_irradiance_source)s, (environment_diffuse_kind)k, b, r->albedo,
                                      p->occ);
            if (score_parts(p, multibounce ? r->bounces : r->direct, r->unoccluded, c->what,
                            out->diffuse[s][k - 1], e) != 0)
                return -1;
        }
    }
    return 0;
}

static int score_specular(const environment_case *c, const so_screen_buffers *b, vec3 eye, const case_references *r,
                          case_planes *p, environment_case_scores *out, gt_error *e)
{
    so_pixel_inputs in;
    if (so_inputs_from_images(c->ao, c->what, c->ao, c->what, -1.0, &in, e) != 0)
        return -1;
    double value, f0 = schema_get_real(c->specular, ATTR_F0, NULL, &value, NULL) == 1 ? value : 0.04;
    environment_screen_specular(c->lighting, b, &in, eye, f0, NULL, p->unocc);
    int rc = 0;
    for (int v = 0; v < ENVIRONMENT_STUDY_SO_VARIANTS && rc == 0; ++v) {
        environment_screen_specular(c->lighting, b, &in, eye, f0, &c->variants[v], p->occ);
        rc = score_parts(p, r->specular, r->specular_unoccluded, c->what, out->specular[v], e);
    }
    so_inputs_free(&in);
    return rc;
}

/* The direct diffuse reference's RMS standard error over its mean (green). */
static double reference_noise(const environment_case *c, const case_references *r, const float *mask)
{
    static const char *const direct[3] = CH_ENV_DIFFUSE_DIRECT_RGB;
    const float *se = schema_stderr_data(c->diffuse, direct[1]);
    size_t n = (size_t)c->diffuse->width * c->diffuse->height;
    double mean = masked_mean(r->direct[1], mask, n);
    return se && mean > 0.0 ? sqrt(noise_mean_variance(se, mask, n)) / mean : NAN;
}

int environment_case_score(const environment_case *c, environment_case_scores *out, gt_error *e)
{
    so_screen_buffers b;
    vec3 eye;
    case_references r;
    case_planes p;
    if (so_buffers_from_images(c->ao, c->what, c->ao, c->what, &b, &eye, e) != 0 || references(c, &r, e) != 0)
        return -1;
    if (planes_init(&p, b.width, b.height, b.mask) != 0)
        return gt_error_set(e, c->what, "out of memory");
    int rc = score_diffuse(c, &b, &r, &p, out, e);
    if (rc == 0)
        rc = score_specular(c, &b, eye, &r, &p, out, e);
    out->reference_noise = reference_noise(c, &r, b.mask);
    free(p.block);
    return rc;
}

/* Writes one RGB preview exposed so that the reference's mean luminance is 0.5. */
static int write_rgb(const char *dir, const char *stem, const char *suffix, const float *const rgb[3], int w, int h,
                     float exposure, gt_error *e)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s_%s.png", dir, stem, suffix);
    return image_write_preview(path, rgb, 3, w, h, exposure, e);
}

static int write_dssim_map(const char *dir, const char *stem, case_planes *p, const char *what, gt_error *e)
{
    float *map = malloc(sizeof(float) * p->n);
    ssim_result r;
    char path[4096];
    if (!map)
        return gt_error_set(e, what, "out of memory");
    int rc = ssim_compute(p->lum_a, p->lum_b, p->mask, p->width, p->height, what, map, &r, e);
    for (size_t i = 0; i < p->n; ++i)
        map[i] = isnan(map[i]) ? 0.0f : 0.5f * (1.0f - map[i]);
    snprintf(path, sizeof path, "%s/%s_dssim.png", dir, stem);
    if (rc == 0)
        rc = image_write_heatmap(path, map, p->mask, p->width, p->height, 0.5f, "inferno", e);
    free(map);
    return rc;
}

int environment_case_images(const environment_case *c, const char *dir, const char *stem, gt_error *e)
{
    so_screen_buffers b;
    vec3 eye;
    case_references r;
    case_planes p;
    if (so_buffers_from_images(c->ao, c->what, c->ao, c->what, &b, &eye, e) != 0 || references(c, &r, e) != 0)
        return -1;
    if (planes_init(&p, b.width, b.height, b.mask) != 0)
        return gt_error_set(e, c->what, "out of memory");
    environment_screen_diffuse(c->lighting, ENVIRONMENT_IRRADIANCE_MAP, ENVIRONMENT_DIFFUSE_AO_N, &b, r.albedo, p.occ);
    luminance(r.direct, p.n, p.lum_a);
    luminance((const float *const *)p.occ, p.n, p.lum_b);
    double mean = masked_mean(p.lum_a, p.mask, p.n);
    float exposure = mean > 0.0 ? (float)(0.5 / mean) : 1.0f;
    int rc = write_rgb(dir, stem, "ref", r.direct, p.width, p.height, exposure, e);
    if (rc == 0)
        rc = write_rgb(dir, stem, "approx", (const float *const *)p.occ, p.width, p.height, exposure, e);
    for (size_t i = 0; i < p.n; ++i)
        p.lum_a[i] *= exposure, p.lum_b[i] *= exposure;
    if (rc == 0)
        rc = write_dssim_map(dir, stem, &p, c->what, e);
    free(p.block);
    return rc;
}
