/* INSIDE's AO decals against the AO reference on the sphere over a plane: see ao_decals_study.h. */
#include "ao_decals/ao_decals_study.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ao/ao_quantity.h"
#include "ao_decals/ao_decals.h"
#include "ao_decals/ao_decals_quality.h"
#include "core/reference_schema.h"
#include "metrics/ssim.h"
#include "raytracer/reference_render.h"
#include "scene/scene_loaders.h"

#define DECAL_RADIUS 3.0f

static const char *const variant_names[AO_DECAL_VARIANTS] = {
    "exact sphere",          "Quilez sphere",          "point decal, published sign", "point decal, light's sign",
    "point decal, refit", "point decal, refit k = 2"};

/* builtin:sphere-on-plane's sphere as the decal's occluder. */
static const ao_decal_volume sphere_volume = {{0.0f, 1.5f, 0.0f}, {1.0f, 1.0f, 1.0f}};

ao_decals_request ao_decals_default_request(study_quality quality)
{
    const ao_decals_quality *q = ao_decals_quality_of(quality);
    ao_decals_request rq = {q->view_size, q->reference_spp, 3, q->scene_size, q->noise_budget};
    return rq;
}

typedef struct {
    image img;
    vec3 *p, *n;
    float *v, *stderr_, *sample_counts, *floor_mask; /* the reference's samples at each floor pixel */
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
                             .target_stderr = rq->noise_budget, .threads = ctx->threads}, .normals = NORMAL_SHADING};
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
    const float *count = image_channel_data(&dv->img, CH_SPP);
    dv->p = malloc(n * sizeof(vec3)), dv->n = malloc(n * sizeof(vec3));
    dv->v = malloc(n * sizeof(float)), dv->stderr_ = malloc(n * sizeof(float)), dv->floor_mask = malloc(n * sizeof(float));
    dv->sample_counts = malloc(n * sizeof(float));
    if (!dv->p || !dv->n || !dv->v || !dv->stderr_ || !dv->sample_counts || !dv->floor_mask)
        return gt_error_set(e, "ao decals", "out of memory");
    dv->count = 0;
    for (size_t i = 0; i < n; ++i) {
        dv->floor_mask[i] = mask[i] != 0.0f && py[i] == 0.0f;
        if (dv->floor_mask[i] == 0.0f)
            continue;
        dv->p[dv->count] = v3(px[i], 0.0f, pz[i]), dv->n[dv->count] = v3(0, 1, 0);
        dv->v[dv->count] = v[i], dv->sample_counts[dv->count] = count[i], dv->stderr_[dv->count++] = se[i];
    }
    dv->samples = (ao_decal_samples){dv->p, dv->n, dv->v, NULL, dv->count, &sphere_volume, 1};
    return dv->count > 0 ? 0 : gt_error_set(e, "ao decals", "no floor pixel in view");
}

static double variant_visibility(int variant, const decal_view *dv, size_t i, const ao_decals_result *r)
{
    vec3 c = sphere_volume.centre, p = dv->p[i], n = dv->n[i];
    switch (variant) {
    case 0: return 1.0 - ao_sphere_exact(p, n, c, 1.0f);
    case 1: return 1.0 - ao_sphere_quilez(p, n, c, 1.0f);
    case 2: return 1.0 - ao_point_decal_published(v3_scale(v3_sub(p, c), 1.0f / DECAL_RADIUS), n);
    case 3: return 1.0 - ao_point_decal_published(v3_scale(v3_sub(c, p), 1.0f / DECAL_RADIUS), n);
    case 4: return ao_decal_fit_visibility(&dv->samples, i, r->fit.params);
    default: return ao_decal_fit_visibility(&dv->samples, i, r->fit_k2.params);
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
        if (variant == 1)
            r->quilez_exact_worst[view] =
                fmax(r->quilez_exact_worst[view], fabs(variant_visibility(1, dv, k, r) - variant_visibility(0, dv, k, r)));
        /* a pixel whose samples all agree has a sample s.e. of 0 but no exact mean: the larger of the
         * sample s.e. and the binomial one under the decal's value (tests/raytracer/test_ao_closed_forms.c) */
        double m = dv->v[k] + d, binomial = sqrt(fmax(m * (1.0 - m), 0.0) / dv->sample_counts[k]);
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
    free(dv->p), free(dv->n), free(dv->v), free(dv->stderr_), free(dv->sample_counts), free(dv->floor_mask);
}

/* ---- The refit on sphere view A and the pill, held out on the other scenes ----------------------- */

static ao_decal_samples scene_samples(const ao_decal_scene_view *v)
{
    return (ao_decal_samples){v->p, v->n, v->v, v->walls, v->count, v->volumes, v->scene->occluder_count};
}

static int is_fitted_scene(const ao_decal_scene_view *v) { return strcmp(v->scene->name, "pill-on-plane") == 0; }

static double refit_visibility(const ao_decal_scene_view *view, size_t i, const void *user)
{
    ao_decal_samples s = scene_samples(view);
    return ao_decal_fit_visibility(&s, i, (const double *)user);
}

/* Sum of squared errors of params over a set. */
static double squared_error(const ao_decal_samples *s, const double *params)
{
    double sum = 0.0;
    for (size_t i = 0; i < s->count; ++i) {
        double d = ao_decal_fit_visibility(s, i, params) - s->visibility[i];
        sum += d * d;
    }
    return sum;
}

static void compare_fits(ao_decals_result *out, const decal_view *a)
{
    double params[AO_DECAL_COMPARED][AO_DECAL_PARAMS], fitted[AO_DECAL_COMPARED] = {0}, held[AO_DECAL_COMPARED] = {0};
    double noise = 0.0; /* the held-out references' squared standard errors */
    ao_decal_published_params(params[AO_DECAL_PUBLISHED]);
    memcpy(params[AO_DECAL_REFIT_K2], out->fit_k2.params, sizeof params[0]);
    memcpy(params[AO_DECAL_REFIT_FREE], out->fit.params, sizeof params[0]);
    out->fitted_count = a->samples.count, out->held_out_count = 0, out->held_out_scenes = 0;
    for (int m = 0; m < AO_DECAL_COMPARED; ++m)
        fitted[m] = squared_error(&a->samples, params[m]);
    for (int k = 0; k < out->scenes.view_count; ++k) {
        ao_decal_samples s = scene_samples(&out->scenes.views[k]);
        int fit_here = is_fitted_scene(&out->scenes.views[k]), j = out->held_out_scenes;
        *(fit_here ? &out->fitted_count : &out->held_out_count) += s.count;
        for (int m = 0; m < AO_DECAL_COMPARED; ++m) {
            double sq = squared_error(&s, params[m]);
            *(fit_here ? &fitted[m] : &held[m]) += sq;
            if (!fit_here)
                out->held_out_scene_rmse[m][j] = s.count ? sqrt(sq / (double)s.count) : NAN;
        }
        out->held_out_scenes += !fit_here;
        for (size_t i = 0; !fit_here && i < s.count; ++i)
            noise += (double)out->scenes.views[k].stderr_[i] * out->scenes.views[k].stderr_[i];
    }
    out->held_out_noise_rmse = out->held_out_count ? sqrt(noise / (double)out->held_out_count) : 0.0;
    for (int m = 0; m < AO_DECAL_COMPARED; ++m) {
        out->fitted_rmse[m] = sqrt(fitted[m] / (double)out->fitted_count);
        out->held_out_rmse[m] = sqrt(held[m] / (double)out->held_out_count);
    }
}

static int refit(const study_context *ctx, const decal_view *a, ao_decals_result *out, gt_error *e)
{
    ao_decal_samples sets[AO_DECAL_FIT_SETS_MAX];
    int count = 0, rc = 0;
    sets[count++] = a->samples;
    for (int k = 0; k < out->scenes.view_count; ++k)
        if (is_fitted_scene(&out->scenes.views[k]))
            sets[count++] = scene_samples(&out->scenes.views[k]);
    rc = ao_decal_fit(sets, count, 0.0, &out->fit, e) || ao_decal_fit(sets, count, 2.0, &out->fit_k2, e) ||
         ao_decal_fit(&sets[0], 1, 0.0, &out->fit_sphere, e) ||
         (count > 1 && ao_decal_fit(&sets[1], 1, 0.0, &out->fit_pill, e));
    char figures[4096];
    rc = rc == 0 ? study_make_dir(ctx, AO_DECALS_DIR, figures, sizeof figures, e) : rc;
    for (int k = 0; k < out->scenes.view_count && rc == 0; ++k) {
        const ao_decal_scene_view *v = &out->scenes.views[k];
        const char *name = is_fitted_scene(v) ? "point decal, refit (fitted here)" : "point decal, refit (held out)";
        rc = ao_decals_scenes_score(&out->scenes, v, name, "refit", refit_visibility, out->fit.params, figures,
                                    e) ||
             ao_decals_scenes_score(&out->scenes, v, "point decal, refit k = 2", "refit_k2", refit_visibility,
                                    out->fit_k2.params, figures, e);
    }
    if (rc == 0)
        compare_fits(out, a);
    return rc ? -1 : 0;
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
    rc = rc == 0 ? ao_decals_scenes_study(ctx, rq->scene_size ? rq->scene_size : rq->size, rq->spp,
                                          rq->noise_budget, rq->seed, &out->scenes, e)
                   : rc;
    rc = rc == 0 ? refit(ctx, &views[0], out, e) : rc;
    for (int k = 0; k < AO_DECAL_VARIANTS && rc == 0; ++k) {
        out->rows[k].variant = variant_names[k];
        for (int v = 0; v < AO_DECAL_VIEWS && rc == 0; ++v)
            rc = score(k, v, &views[v], out, e);
    }
    for (int v = 0; v < AO_DECAL_VIEWS; ++v)
        free_view(&views[v]);
    ao_decals_scenes_free(&out->scenes);
    return rc ? -1 : 0;
}
