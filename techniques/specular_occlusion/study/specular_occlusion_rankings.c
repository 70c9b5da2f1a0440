#include "specular_occlusion/specular_occlusion_rankings.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/reference_schema.h"
#include "metrics/silhouette_region.h"
#include "metrics/ssim.h"
#include "scene/camera.h"

/* |P - eye| per pixel from the reference's position channels. */
static int view_distance(const image *ref, const char *what, float *depth, gt_error *e)
{
    const float *p[3] = {image_channel_data(ref, CH_P_X), image_channel_data(ref, CH_P_Y),
                         image_channel_data(ref, CH_P_Z)};
    const char *json = image_get_attribute(ref, ATTR_CAMERA);
    camera cam;
    if (!p[0] || !p[1] || !p[2] || !json)
        return gt_error_set(e, what, "no positions or camera (not a gtlab reference?)");
    if (camera_parse_json(json, what, &cam, e) != 0)
        return -1;
    for (size_t i = 0; i < image_pixel_count(ref); ++i)
        depth[i] = (float)v3_length(v3_sub(v3(p[0][i], p[1][i], p[2][i]), cam.position));
    return 0;
}

static long count_inside(const float *mask, size_t n)
{
    long count = 0;
    for (size_t i = 0; i < n; ++i)
        count += mask[i] >= 0.5f;
    return count;
}

int so_regions_from_reference(const image *ref, const char *what, so_regions *r, gt_error *e)
{
    size_t n = image_pixel_count(ref);
    const float *mask = image_channel_data(ref, CH_MASK);
    float *depth = malloc(sizeof(float) * n);
    *r = (so_regions){ref->width, ref->height, {malloc(sizeof(float) * n), malloc(sizeof(float) * n)}, {0}};
    int rc = depth && r->mask[0] && r->mask[1] ? 0 : gt_error_set(e, what, "out of memory");
    if (rc == 0 && !mask)
        rc = gt_error_set(e, what, "no channel %s", CH_MASK);
    if (rc == 0)
        rc = view_distance(ref, what, depth, e);
    if (rc == 0 && silhouette_region(depth, mask, ref->width, ref->height, SO_SILHOUETTE_RADIUS, SO_SILHOUETTE_JUMP,
                                     r->mask[SO_REGION_SILHOUETTE], r->mask[SO_REGION_INTERIOR]) != 0)
        rc = gt_error_set(e, what, "out of memory");
    for (int k = 0; k < SO_REGIONS && rc == 0; ++k)
        r->pixels[k] = count_inside(r->mask[k], n);
    free(depth);
    if (rc != 0)
        so_regions_free(r);
    return rc;
}

void so_regions_free(so_regions *r)
{
    for (int k = 0; k < SO_REGIONS; ++k) {
        free(r->mask[k]);
        r->mask[k] = NULL;
    }
}

/* Whether some SSIM window centre lies inside mask. */
static int has_centre(const float *mask, int width, int height)
{
    for (int y = SSIM_RADIUS; y < height - SSIM_RADIUS; ++y)
        for (int x = SSIM_RADIUS; x < width - SSIM_RADIUS; ++x)
            if (mask[(size_t)y * width + x] >= 0.5f)
                return 1;
    return 0;
}

static double mean_signed_error(const float *truth, const float *approx, const float *mask, size_t n)
{
    double sum = 0.0;
    long count = 0;
    for (size_t i = 0; i < n; ++i)
        if (mask[i] >= 0.5f)
            sum += (double)approx[i] - truth[i], count++;
    return count ? sum / count : NAN;
}

int so_region_scores(const float *truth, const float *approx, const so_regions *r, const char *what,
                     so_region_score out[SO_REGIONS], gt_error *e)
{
    size_t n = (size_t)r->width * r->height;
    for (int k = 0; k < SO_REGIONS; ++k) {
        out[k].bias = mean_signed_error(truth, approx, r->mask[k], n);
        out[k].dssim = NAN;
        ssim_result s;
        if (!has_centre(r->mask[k], r->width, r->height))
            continue;
        if (ssim_compute(truth, approx, r->mask[k], r->width, r->height, what, NULL, &s, e) != 0)
            return -1;
        out[k].dssim = s.dssim;
    }
    return 0;
}

/* Scene s's difference a - b: the mean over its roughnesses or one of them. */
static double scene_difference(const double *a, const double *b, int stride, int s, int roughness)
{
    double sum = 0.0;
    int count = 0;
    for (int k = 0; k < SO_STUDY_ROUGHNESSES; ++k) {
        size_t i = (size_t)(s * SO_STUDY_ROUGHNESSES + k) * stride;
        double d = a[i] - b[i];
        if ((roughness < 0 || k == roughness) && !isnan(d))
            sum += d, count++;
    }
    return count ? sum / count : NAN;
}

so_paired_difference so_paired_over_scenes(const double *a, const double *b, int stride, int scenes, int roughness)
{
    double sum = 0.0, sum_sq = 0.0;
    int n = 0;
    for (int s = 0; s < scenes; ++s) {
        double d = scene_difference(a, b, stride, s, roughness);
        if (!isnan(d))
            sum += d, sum_sq += d * d, n++;
    }
    so_paired_difference out = {NAN, NAN, n};
    if (n < 2)
        return out;
    out.mean = sum / n;
    out.standard_error = sqrt(fmax(0.0, (sum_sq - n * out.mean * out.mean) / (n - 1)) / n);
    return out;
}

void so_ranking_scores_init(so_ranking_scores *s, const so_lut *lobe_lut)
{
    static const char *const texts[SO_RANK_VARIANTS] = {"ao", "lagarde", "cone-exact:exp2-alpha", "cone-exact:drobot",
                                                        "lut"};
    memset(s, 0, sizeof *s);
    for (int v = 0; v < SO_RANK_VARIANTS; ++v)
        so_variant_parse(texts[v], &s->variants[v]);
    s->variants[SO_RANK_LOBE].lut = lobe_lut;
}

int so_ranking_scores_add(so_ranking_scores *s, const so_pixel_inputs *in, const float *reference,
                          const so_regions *regions, const char *what, gt_error *e)
{
    if (s->cases >= SO_RANK_CASES)
        return gt_error_set(e, what, "more than %d specular-occlusion cases", SO_RANK_CASES);
    float *approx = malloc(sizeof(float) * (size_t)in->width * in->height);
    int rc = approx ? 0 : gt_error_set(e, what, "out of memory");
    for (int v = 0; v < SO_RANK_VARIANTS && rc == 0; ++v) {
        ssim_result all;
        so_approx_evaluate(in, &s->variants[v], approx);
        rc = ssim_compute(reference, approx, in->mask, in->width, in->height, what, NULL, &all, e);
        s->dssim[v][s->cases] = all.dssim;
        if (rc == 0)
            rc = so_region_scores(reference, approx, regions, what, s->region[v][s->cases], e);
    }
    free(approx);
    s->cases += rc == 0;
    return rc;
}

/* A variant's region scores, means over the cases that have them. */
static so_region_score region_mean(const so_ranking_scores *s, int v, so_region region)
{
    so_region_score m = {0.0, 0.0};
    int nd = 0, nb = 0;
    for (int i = 0; i < s->cases; ++i) {
        const so_region_score *c = &s->region[v][i][region];
        if (!isnan(c->dssim))
            m.dssim += c->dssim, nd++;
        if (!isnan(c->bias))
            m.bias += c->bias, nb++;
    }
    m.dssim = nd ? m.dssim / nd : NAN, m.bias = nb ? m.bias / nb : NAN;
    return m;
}

/* a minus b of a region score, the DSSIM (bias 0) or the signed error (1). */
static so_paired_difference paired_region(const so_ranking_scores *s, int a, int b, so_region region, int bias,
                                          int scenes)
{
    const so_region_score *sa = &s->region[a][0][region], *sb = &s->region[b][0][region];
    int stride = SO_REGIONS * (int)(sizeof(so_region_score) / sizeof(double));
    return so_paired_over_scenes(bias ? &sa->bias : &sa->dssim, bias ? &sb->bias : &sb->dssim, stride, scenes, -1);
}

void so_ranking_setting_compute(const so_ranking_scores *s, int scenes, so_ranking_setting *out)
{
    out->cone_minus_ao = so_paired_over_scenes(s->dssim[SO_RANK_CONE], s->dssim[SO_RANK_AO], 1, scenes, -1);
    out->cone_minus_lagarde = so_paired_over_scenes(s->dssim[SO_RANK_CONE], s->dssim[SO_RANK_LAGARDE], 1, scenes, -1);
    for (int g = 0; g < SO_REGIONS; ++g) {
        out->cone[g] = region_mean(s, SO_RANK_CONE, g), out->lobe_score[g] = region_mean(s, SO_RANK_LOBE, g);
        out->lobe_minus_cone[g] = paired_region(s, SO_RANK_LOBE, SO_RANK_CONE, g, 0, scenes);
        out->lobe_minus_cone_bias[g] = paired_region(s, SO_RANK_LOBE, SO_RANK_CONE, g, 1, scenes);
    }
    for (int k = 0; k < SO_STUDY_ROUGHNESSES; ++k) {
        out->talk_minus_drobot[k] = so_paired_over_scenes(s->dssim[SO_RANK_CONE], s->dssim[SO_RANK_DROBOT], 1, scenes, k);
        out->noise_floor_dssim[k] = scenes ? s->floor_sum[k] / scenes : NAN;
    }
}
