/* INSIDE's AO decals against the AO reference on the sphere over a plane: see ao_decals.h. */
#include "studies/ao_decals.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/reference_schema.h"
#include "metrics/ssim.h"
#include "raytracer/reference_render.h"
#include "realtime/ao_decals.h"
#include "scene/scene_loaders.h"

#define DECAL_RADIUS 3.0f

static const char *const variant_names[AO_DECAL_VARIANTS] = {
    "exact sphere", "Quilez sphere", "point decal, published sign", "point decal, light's sign", "point decal, refit"};

ao_decals_request ao_decals_default_request(study_quality quality)
{
    ao_decals_request rq = {quality == QUALITY_PRODUCTION ? 128 : 48, quality == QUALITY_PRODUCTION ? 1024 : 256, 3,
                            quality == QUALITY_PRODUCTION ? 256 : 96};
    return rq;
}

typedef struct {
    image img;
    vec3 *p, *n;
    float *v, *stderr_, *floor_mask;
    size_t count; /* floor pixels */
    ao_decal_samples samples;
} decal_view;

static int render_view(const study_context *ctx, const ao_decals_request *rq, int view, decal_view *dv, gt_error *e)
{
    scene s;
    camera cam = {view ? v3(-3.5f, 2.0f, -4.0f) : v3(4.5f, 4.0f, 6.0f), v3(0, 0.8f, 0), v3(0, 1, 0),
                  (float)(45.0 * M_PI / 180.0), rq->size, rq->size};
    if (scene_load("builtin:sphere-on-plane", &s, e) != 0)
        return -1;
    reference_request req = {.quantity = QUANTITY_AO, .sampling = {.spp = rq->spp, .seed = rq->seed + view,
                             .threads = ctx->threads}, .normals = NORMAL_SHADING, .max_distance = INFINITY};
    render_stats stats;
    int rc = reference_render(&s, "builtin:sphere-on-plane", &cam, &req, &dv->img, &stats, e);
    scene_free(&s);
    return rc;
}

/* The floor pixels' samples (y == 0 and covered). */
static int gather_floor(decal_view *dv, gt_error *e)
{
    size_t n = image_pixel_count(&dv->img);
    const float *mask = image_channel_data(&dv->img, CH_MASK), *px = image_channel_data(&dv->img, CH_P_X);
    const float *py = image_channel_data(&dv->img, CH_P_Y), *pz = image_channel_data(&dv->img, CH_P_Z);
    const float *v = image_channel_data(&dv->img, CH_AO), *se = image_channel_data(&dv->img, CH_AO_STDERR);
    dv->p = malloc(n * sizeof(vec3)), dv->n = malloc(n * sizeof(vec3));
    dv->v = malloc(n * sizeof(float)), dv->stderr_ = malloc(n * sizeof(float)), dv->floor_mask = malloc(n * sizeof(float));
    if (!dv->p || !dv->n || !dv->v || !dv->stderr_ || !dv->floor_mask)
        return gt_error_set(e, "ao decals", "out of memory");
    dv->count = 0;
    for (size_t i = 0; i < n; ++i) {
        dv->floor_mask[i] = mask[i] != 0.0f && py[i] == 0.0f;
        if (dv->floor_mask[i] == 0.0f)
            continue;
        dv->p[dv->count] = v3(px[i], 0.0f, pz[i]), dv->n[dv->count] = v3(0, 1, 0);
        dv->v[dv->count] = v[i], dv->stderr_[dv->count++] = se[i];
    }
    dv->samples = (ao_decal_samples){dv->p, dv->n, dv->v, dv->count, v3(0, 1.5f, 0)};
    return dv->count > 0 ? 0 : gt_error_set(e, "ao decals", "no floor pixel in view");
}

static double variant_visibility(int variant, const decal_view *dv, size_t i, const ao_decals_result *r)
{
    vec3 c = dv->samples.centre, p = dv->p[i], n = dv->n[i];
    switch (variant) {
    case 0: return 1.0 - ao_sphere_exact(p, n, c, 1.0f);
    case 1: return 1.0 - ao_sphere_quilez(p, n, c, 1.0f);
    case 2: return 1.0 - ao_point_decal_published(v3_scale(v3_sub(p, c), 1.0f / DECAL_RADIUS), n);
    case 3: return 1.0 - ao_point_decal_published(v3_scale(v3_sub(c, p), 1.0f / DECAL_RADIUS), n);
    default: return ao_decal_fit_visibility(&dv->samples, i, r->fit.params);
    }
}

/* RMSE, worst, 4-sigma share, and DSSIM over the floor (other pixels hold the reference in both). */
static int score(int variant, int view, const decal_view *dv, ao_decals_result *r, gt_error *e)
{
    size_t n = image_pixel_count(&dv->img), k = 0, outliers = 0;
    const float *ref = image_channel_data(&dv->img, CH_AO);
    float *a = malloc(n * sizeof(float));
    double sum = 0.0, worst = 0.0;
    if (!a)
        return gt_error_set(e, "ao decals", "out of memory");
    for (size_t i = 0; i < n; ++i) {
        a[i] = ref[i];
        if (dv->floor_mask[i] == 0.0f)
            continue;
        double d = variant_visibility(variant, dv, k, r) - dv->v[k];
        a[i] = (float)(dv->v[k] + d);
        sum += d * d, worst = fmax(worst, fabs(d));
        /* a pixel whose samples all agree has a sample s.e. of 0 but no exact mean: the larger of the
         * sample s.e. and the binomial one under the decal's value (tests/raytracer/test_ao_closed_forms.c) */
        double m = dv->v[k] + d, binomial = sqrt(fmax(m * (1.0 - m), 0.0) / r->request.spp);
        outliers += fabs(d) > 4.0 * fmax(fmax(dv->stderr_[k], binomial), 1e-6);
        ++k;
    }
    ao_decal_row *row = &r->rows[variant];
    row->rmse[view] = sqrt(sum / (double)k), row->worst[view] = worst, row->outlier_share[view] = (double)outliers / k;
    ssim_result s;
    int rc = ssim_compute(a, ref, dv->floor_mask, dv->img.width, dv->img.height, "ao decals", NULL, &s, e);
    row->dssim[view] = rc == 0 ? s.dssim : 0.0;
    free(a);
    return rc;
}

static void free_view(decal_view *dv)
{
    image_free(&dv->img);
    free(dv->p), free(dv->n), free(dv->v), free(dv->stderr_), free(dv->floor_mask);
}

int ao_decals_study(const study_context *ctx, const ao_decals_request *rq, ao_decals_result *out, gt_error *e)
{
    decal_view views[AO_DECAL_VIEWS];
    memset(out, 0, sizeof *out);
    memset(views, 0, sizeof views);
    out->request = *rq;
    int rc = 0;
    for (int v = 0; v < AO_DECAL_VIEWS && rc == 0; ++v) {
        rc = render_view(ctx, rq, v, &views[v], e) || gather_floor(&views[v], e);
        out->floor_pixels[v] = views[v].count;
    }
    rc = rc == 0 ? ao_decal_fit(&views[0].samples, DECAL_RADIUS, &out->fit, e) : rc;
    for (int k = 0; k < AO_DECAL_VARIANTS && rc == 0; ++k) {
        out->rows[k].variant = variant_names[k];
        for (int v = 0; v < AO_DECAL_VIEWS && rc == 0; ++v)
            rc = score(k, v, &views[v], out, e);
    }
    for (int v = 0; v < AO_DECAL_VIEWS; ++v)
        free_view(&views[v]);
    rc = rc == 0 ? ao_decals_scenes_study(ctx, rq->scene_size ? rq->scene_size : rq->size, rq->spp, rq->seed, &out->scenes, e) : rc;
    ao_decals_scenes_free(&out->scenes);
    return rc ? -1 : 0;
}
