/* INSIDE's AO decals on the decal scenes: see ao_decals_scenes.h. */
#include "ao_decals/ao_decals_scenes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ao/ao_quantity.h"
#include "ao_decals/ao_decals_study.h"
#include "core/files/image_io.h"
#include "core/reference_schema.h"
#include "metrics/ssim.h"
#include "raytracer/reference_render.h"

/* ---- Exact forms per occluder ----------------------------------------------------------------- */

static int is_sphere(const ao_occluder *o) { return o->kind == AO_OCCLUDER_ELLIPSOID && o->half.x == o->half.y && o->half.y == o->half.z; }

/* The exact occlusion of occluder o (sphere or box; -1 for an ellipsoid, which has none). */
static double exact_occlusion(const ao_occluder *o, vec3 p, vec3 n)
{
    if (o->kind == AO_OCCLUDER_BOX)
        return ao_box_exact(p, n, v3_sub(o->centre, o->half), v3_add(o->centre, o->half));
    return is_sphere(o) ? ao_sphere_exact(p, n, o->centre, o->half.x) : -1.0;
}

/* The form factor of builtin:corner's three 10 x 10 walls: every ray from inside the open cube leaves
 * it through one face, so their sum is their union (tests/test_ao_decals_scenes.c). */
static double corner_walls(vec3 p, vec3 n)
{
    const vec3 walls[3][4] = {{v3(0, 0, 0), v3(10, 0, 0), v3(10, 0, 10), v3(0, 0, 10)},
                              {v3(0, 0, 0), v3(0, 10, 0), v3(0, 10, 10), v3(0, 0, 10)},
                              {v3(0, 0, 0), v3(10, 0, 0), v3(10, 10, 0), v3(0, 10, 0)}};
    double a = 0.0;
    for (int w = 0; w < 3; ++w)
        a += ao_polygon_form_factor(p, n, walls[w], 4);
    return a;
}

/* The published point decal of o at AO_DECAL_POINT_RADIUS, with the talk's sign or a light's. */
static double point_decal(const ao_occluder *o, vec3 p, vec3 n, int light_sign)
{
    ao_decal_volume vol = {o->centre, v3_scale(o->half, AO_DECAL_POINT_RADIUS)};
    vec3 pos, norm;
    ao_decal_unit_space(p, n, &vol, &pos, &norm);
    return ao_point_decal_published(light_sign ? v3_neg(pos) : pos, norm);
}

/* ---- Regions ---------------------------------------------------------------------------------- */

static ao_decal_region region_of(const ao_decal_scene_view *view, size_t i)
{
    const ao_decal_scene *d = view->scene;
    vec3 p = view->p[i], n = view->n[i];
    int significant = 1 - view->walls[i] > AO_DECAL_SIGNIFICANT, clipped = 0;
    for (int k = 0; k < d->occluder_count; ++k) {
        const ao_occluder *o = &d->occluders[k];
        double a = exact_occlusion(o, p, n);
        a = a < 0.0 ? point_decal(o, p, n, 1) : a;
        significant += a > AO_DECAL_SIGNIFICANT;
        clipped += a > AO_DECAL_SIGNIFICANT && is_sphere(o) && v3_dot(n, v3_sub(o->centre, p)) < o->half.x;
    }
    return significant >= 2 ? AO_REGION_OVERLAP : clipped ? AO_REGION_CLIPPED : AO_REGION_SINGLE;
}

/* ---- Views ------------------------------------------------------------------------------------ */

static int render(const ao_decal_scene *d, int size, const sampling_settings *sampling, image *img, gt_error *e)
{
    char spec[96];
    snprintf(spec, sizeof spec, "builtin:%s", d->name);
    scene s;
    camera cam;
    if (study_load_view(spec, size, size, &s, &cam, e) != 0)
        return -1;
    reference_request req = {.quantity = QUANTITY_AO, .sampling = *sampling, .normals = NORMAL_SHADING};
    render_stats stats;
    int rc = reference_render(&s, spec, &cam, &req, img, &stats, e);
    scene_free(&s);
    return rc;
}

/* A receiver: on the floor, or (corner) on any of the three walls. */
static int is_receiver(const ao_decal_scene *d, vec3 p)
{
    return p.y == 0.0f || (d->corner && (p.x == 0.0f || p.z == 0.0f));
}

static int alloc_view(ao_decal_scene_view *v, size_t n)
{
    v->pixel = malloc(n * sizeof *v->pixel), v->p = malloc(n * sizeof *v->p), v->n = malloc(n * sizeof *v->n);
    v->v = malloc(n * sizeof *v->v), v->stderr_ = malloc(n * sizeof *v->stderr_), v->walls = malloc(n * sizeof *v->walls);
    v->sample_counts = malloc(n * sizeof *v->sample_counts);
    v->region = malloc(n), v->receiver_mask = calloc(n, sizeof *v->receiver_mask);
    return v->pixel && v->p && v->n && v->v && v->stderr_ && v->walls && v->sample_counts && v->region && v->receiver_mask
               ? 0
               : -1;
}

static int gather(ao_decal_scene_view *v, gt_error *e)
{
    const image *img = &v->img;
    size_t n = image_pixel_count(img);
    const float *mask = image_channel_data(img, CH_MASK), *ao = image_channel_data(img, CH_AO);
    const float *se = image_channel_data(img, CH_AO_STDERR), *count = image_channel_data(img, CH_SPP);
    const float *p[3] = {image_channel_data(img, CH_P_X), image_channel_data(img, CH_P_Y), image_channel_data(img, CH_P_Z)};
    const float *nn[3] = {image_channel_data(img, CH_N_X), image_channel_data(img, CH_N_Y), image_channel_data(img, CH_N_Z)};
    if (alloc_view(v, n) != 0)
        return gt_error_set(e, v->scene->name, "out of memory");
    v->count = 0;
    for (size_t i = 0; i < n; ++i) {
        vec3 pi = v3(p[0][i], p[1][i], p[2][i]), ni = v3(nn[0][i], nn[1][i], nn[2][i]);
        if (mask[i] == 0.0f || !is_receiver(v->scene, pi))
            continue;
        size_t k = v->count++;
        v->receiver_mask[i] = 1.0f, v->pixel[k] = i, v->p[k] = pi, v->n[k] = ni, v->v[k] = ao[i], v->stderr_[k] = se[i];
        v->sample_counts[k] = count[i];
        v->walls[k] = v->scene->corner ? (float)(1.0 - corner_walls(pi, ni)) : 1.0f;
        v->region[k] = (unsigned char)region_of(v, k);
    }
    for (int k = 0; k < v->scene->occluder_count; ++k)
        v->volumes[k] = (ao_decal_volume){v->scene->occluders[k].centre, v->scene->occluders[k].half};
    return v->count > 0 ? 0 : gt_error_set(e, v->scene->name, "no receiver pixel in view");
}

static void free_view(ao_decal_scene_view *v)
{
    image_free(&v->img);
    free(v->pixel), free(v->p), free(v->n), free(v->v), free(v->stderr_), free(v->walls), free(v->sample_counts), free(v->region);
    free(v->receiver_mask);
    memset(v, 0, sizeof *v);
}

void ao_decals_scenes_free(ao_decals_scenes_result *r)
{
    for (int k = 0; k < r->view_count; ++k)
        free_view(&r->views[k]);
    r->view_count = 0;
}

/* ---- Scoring ---------------------------------------------------------------------------------- */

/* The DSSIM map (1 - SSIM) / 2 over the receivers' valid centres. */
static int write_dssim_map(const char *figures, const ao_decal_scene_view *view, const char *key, const float *map,
                           gt_error *e)
{
    int w = view->img.width, h = view->img.height;
    size_t n = (size_t)w * h;
    float *d = malloc(n * sizeof *d), *m = malloc(n * sizeof *m);
    int rc = d && m ? 0 : gt_error_set(e, view->scene->name, "out of memory");
    for (size_t i = 0; rc == 0 && i < n; ++i) {
        m[i] = isnan(map[i]) ? 0.0f : view->receiver_mask[i];
        d[i] = isnan(map[i]) ? 0.0f : 0.5f * (1.0f - map[i]);
    }
    char path[4096];
    snprintf(path, sizeof path, "%s/dssim_%s_%s.png", figures, view->scene->name, key);
    rc = rc == 0 ? image_write_heatmap(path, d, m, w, h, AO_DECAL_DSSIM_MAP_MAX, "inferno", e) : rc;
    free(d), free(m);
    return rc;
}

/* Accumulates the errors of the decal's image a (reference elsewhere) into row. */
static void accumulate(ao_decal_scene_row *row, const ao_decal_scene_view *view, const double *d)
{
    double sum = 0.0, bias = 0.0, region_sum[AO_DECAL_REGIONS] = {0};
    size_t outliers = 0;
    for (size_t k = 0; k < view->count; ++k) {
        sum += d[k] * d[k], bias += d[k], region_sum[view->region[k]] += d[k] * d[k];
        ++row->region_pixels[view->region[k]];
        row->worst = fmax(row->worst, fabs(d[k]));
        /* the larger of the sample s.e. and the binomial one under the decal's value (ao_decals_study.c) */
        double m = view->v[k] + d[k], binomial = sqrt(fmax(m * (1.0 - m), 0.0) / view->sample_counts[k]);
        outliers += fabs(d[k]) > 4.0 * fmax(fmax(view->stderr_[k], binomial), 1e-6);
    }
    row->pixels = view->count;
    row->rmse = sqrt(sum / (double)view->count), row->bias = bias / (double)view->count;
    row->outlier_share = (double)outliers / (double)view->count;
    for (int g = 0; g < AO_DECAL_REGIONS; ++g)
        row->region_rmse[g] = row->region_pixels[g] ? sqrt(region_sum[g] / (double)row->region_pixels[g]) : NAN;
}

int ao_decals_scenes_score(ao_decals_scenes_result *r, const ao_decal_scene_view *view, const char *decal,
                           const char *key, ao_decal_visibility_fn visibility, const void *user,
                           const char *figures, gt_error *e)
{
    if (r->row_count == AO_DECAL_SCENE_ROWS_MAX)
        return gt_error_set(e, "ao decals", "more than %d rows", AO_DECAL_SCENE_ROWS_MAX);
    size_t n = image_pixel_count(&view->img);
    const float *ref = image_channel_data(&view->img, CH_AO);
    float *a = malloc(n * sizeof *a), *map = malloc(n * sizeof *map);
    double *d = malloc(view->count * sizeof *d);
    if (!a || !map || !d) {
        free(a), free(map), free(d);
        return gt_error_set(e, "ao decals", "out of memory");
    }
    memcpy(a, ref, n * sizeof *a);
    for (size_t k = 0; k < view->count; ++k) {
        d[k] = visibility(view, k, user) - view->v[k];
        a[view->pixel[k]] = (float)(view->v[k] + d[k]);
    }
    ao_decal_scene_row *row = &r->rows[r->row_count++];
    memset(row, 0, sizeof *row);
    row->scene = view->scene->name, row->decal = decal;
    accumulate(row, view, d);
    ssim_result s;
    int rc = ssim_compute(a, ref, view->receiver_mask, view->img.width, view->img.height, "ao decals", map, &s, e);
    row->dssim = rc == 0 ? s.dssim : 0.0;
    rc = rc == 0 && figures ? write_dssim_map(figures, view, key, map, e) : rc;
    free(a), free(map), free(d);
    return rc;
}

/* ---- The decals ------------------------------------------------------------------------------- */

typedef enum { DECAL_EXACT, DECAL_ENGINE, DECAL_POINT_TALK, DECAL_POINT_LIGHT, DECAL_WALLS_ONLY } decal_kind;

static double occlusion(decal_kind kind, const ao_occluder *o, vec3 p, vec3 n)
{
    switch (kind) {
    case DECAL_EXACT: return exact_occlusion(o, p, n);
    case DECAL_ENGINE: return is_sphere(o) ? ao_sphere_quilez(p, n, o->centre, o->half.x) : exact_occlusion(o, p, n);
    case DECAL_POINT_TALK: return point_decal(o, p, n, 0);
    case DECAL_POINT_LIGHT: return point_decal(o, p, n, 1);
    default: return 0.0;
    }
}

static double decal_visibility(const ao_decal_scene_view *view, size_t i, const void *user)
{
    decal_kind kind = *(const decal_kind *)user;
    double v = view->walls[i];
    for (int k = 0; k < view->scene->occluder_count; ++k)
        v *= 1.0 - occlusion(kind, &view->scene->occluders[k], view->p[i], view->n[i]);
    return v;
}

/* The decals that apply to the scene: exact forms only where every occluder has one; the engine's
 * only where it differs (a sphere); the baseline only in the corner. */
static int score_scene(ao_decals_scenes_result *r, const ao_decal_scene_view *view, const char *figures, gt_error *e)
{
    static const decal_kind kinds[] = {DECAL_EXACT, DECAL_ENGINE, DECAL_POINT_TALK, DECAL_POINT_LIGHT, DECAL_WALLS_ONLY};
    static const char *const names[] = {"exact forms", "engine forms (Quilez sphere, exact box)",
                                        "point decal, talk's sign", "point decal, light's sign", "walls only, no decal"};
    static const char *const keys[] = {"exact", "engine", "point_talk", "point_light", "walls_only"};
    const ao_decal_scene *d = view->scene;
    int exact = 1, spheres = 0, rc = 0;
    for (int k = 0; k < d->occluder_count; ++k)
        exact &= exact_occlusion(&d->occluders[k], v3(0, 100, 0), v3(0, 1, 0)) >= 0.0, spheres += is_sphere(&d->occluders[k]);
    for (int k = 0; k < 5 && rc == 0; ++k) {
        if ((kinds[k] == DECAL_EXACT && !exact) || (kinds[k] == DECAL_ENGINE && !spheres) ||
            (kinds[k] == DECAL_WALLS_ONLY && !d->corner))
            continue;
        rc = ao_decals_scenes_score(r, view, names[k], keys[k], decal_visibility, &kinds[k], figures, e);
    }
    return rc;
}

int ao_decals_scenes_study(const study_context *ctx, int size, int spp, double noise_budget, unsigned seed,
                           ao_decals_scenes_result *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    char figures[4096];
    if (study_make_dir(ctx, AO_DECALS_DIR, figures, sizeof figures, e) != 0)
        return -1;
    int rc = 0;
    for (int s = 0; s < ao_decal_scene_count() && rc == 0; ++s) {
        ao_decal_scene_view *v = &out->views[out->view_count++];
        v->scene = ao_decal_scene_at(s);
        sampling_settings sampling = {.spp = spp, .seed = seed + 10u + (unsigned)s, .target_stderr = noise_budget,
                                      .threads = ctx->threads};
        rc = render(v->scene, size, &sampling, &v->img, e);
        rc = rc == 0 ? gather(v, e) : rc;
        rc = rc == 0 ? score_scene(out, v, figures, e) : rc;
    }
    if (rc != 0)
        ao_decals_scenes_free(out);
    return rc ? -1 : 0;
}
