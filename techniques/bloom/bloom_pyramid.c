/* Pyramids of an HDR render with the bloom kernels: see bloom_pyramid.h. */
#include "bloom/bloom_pyramid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bloom/bloom_kernels.h"
#include "core/reference_schema.h"
#include "metrics/ssim.h"
#include "sphere_light/sphere_light_hdr_test_image.h"

enum { CHAIN_TARGET, CHAIN_NINE, CHAIN_POLICY, CHAINS };

static int compare_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

static double exposure_of(const float *v, size_t n)
{
    float *s = malloc(n * sizeof(float));
    if (!s)
        return 1.0;
    memcpy(s, v, n * sizeof(float));
    qsort(s, n, sizeof(float), compare_float);
    double p = s[(size_t)(0.99 * (double)(n - 1))];
    free(s);
    return p > 0.0 ? 1.0 / p : 1.0;
}

static int tone_mapped_dssim(const float *a, const float *b, int w, int h, double exposure, double *dssim, gt_error *e)
{
    size_t n = (size_t)w * h;
    float *ta = malloc(n * sizeof(float)), *tb = malloc(n * sizeof(float));
    int rc = ta && tb ? 0 : gt_error_set(e, "bloom", "out of memory");
    for (size_t i = 0; i < n && rc == 0; ++i) {
        double x = exposure * a[i], y = exposure * b[i];
        ta[i] = (float)(x / (1.0 + x)), tb[i] = (float)(y / (1.0 + y));
    }
    ssim_result r;
    rc = rc == 0 ? ssim_compute(ta, tb, NULL, w, h, "bloom pyramid", NULL, &r, e) : rc;
    *dssim = rc == 0 ? r.dssim : 0.0;
    free(ta), free(tb);
    return rc;
}

static void downsample(int chain, int exact, int target, double sigma, const bloom_tap *taps, const float *src, int sw,
                       int sh, float *dst, int dw, int dh)
{
    if (chain == CHAIN_NINE || (chain == CHAIN_POLICY && exact))
        bloom_downsample(src, sw, sh, dst, dw, dh, taps, BLOOM_FIT_TAPS);
    else
        bloom_target_downsample(target, sigma, src, sw, sh, dst, dw, dh);
}

/* One target's three chains from the render, scored level by level. */
static int pyramid(int f, const float *hdr, const bloom_request *rq, double exposure, bloom_result *out,
                   gt_error *e)
{
    float *prev[CHAINS], *next[CHAINS];
    int w = rq->width, h = rq->height, rc = 0;
    for (int c = 0; c < CHAINS; ++c)
        prev[c] = malloc((size_t)w * h * sizeof(float)), next[c] = malloc((size_t)w * h * sizeof(float));
    for (int c = 0; c < CHAINS; ++c)
        if (!prev[c] || !next[c])
            rc = gt_error_set(e, "bloom", "out of memory");
    for (int c = 0; c < CHAINS && rc == 0; ++c)
        memcpy(prev[c], hdr, (size_t)w * h * sizeof(float));
    for (int l = 0; l < out->level_count && rc == 0; ++l) {
        bloom_level_result *lv = &out->levels[l];
        for (int c = 0; c < CHAINS; ++c) {
            downsample(c, lv->exact_half, out->targets[f].reference, out->gaussian_sigma, out->targets[f].fit.taps,
                       prev[c], w, h, next[c], lv->width, lv->height);
            float *t = prev[c];
            prev[c] = next[c], next[c] = t;
        }
        w = lv->width, h = lv->height;
        rc = tone_mapped_dssim(prev[CHAIN_NINE], prev[CHAIN_TARGET], w, h, exposure, &lv->dssim[f], e) ||
             tone_mapped_dssim(prev[CHAIN_POLICY], prev[CHAIN_TARGET], w, h, exposure, &lv->dssim_policy[f], e);
    }
    for (int c = 0; c < CHAINS; ++c)
        free(prev[c]), free(next[c]);
    return rc ? -1 : 0;
}

static void level_sizes(const bloom_request *rq, bloom_result *out)
{
    int w = rq->width, h = rq->height;
    out->level_count = 0;
    while (out->level_count < rq->levels && out->level_count < BLOOM_MAX_LEVELS && w / 2 >= SSIM_WINDOW &&
           h / 2 >= SSIM_WINDOW) {
        bloom_level_result *lv = &out->levels[out->level_count++];
        lv->width = w / 2, lv->height = h / 2;
        lv->exact_half = w == 2 * lv->width && h == 2 * lv->height;
        w /= 2, h /= 2;
    }
}

int bloom_pyramids(const study_context *ctx, const bloom_request *rq, bloom_result *out, gt_error *e)
{
    image ref;
    if (hdr_test_image_sphere_light(ctx, rq->width, rq->height, rq->spp, rq->seed, &ref, e) != 0)
        return -1;
    const float *hdr = image_channel_data(&ref, CH_SPHERE_G);
    level_sizes(rq, out);
    double exposure = exposure_of(hdr, image_pixel_count(&ref));
    int rc = 0;
    for (int f = 0; f < BLOOM_FITS && rc == 0; ++f)
        rc = pyramid(f, hdr, rq, exposure, out, e);
    image_free(&ref);
    return rc;
}
