#include "environment/environment_diffuse_integrator.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/sampling/hemisphere_sampling.h"
#include "core/reference_schema.h"
#include "raytracer/diffuse_path_wavefront.h"

/* The first quantity of each RGB triple. */
enum { TOTAL = 0, DIRECT = 3, UNOCCLUDED = 6 };

/* ---- The plan -------------------------------------------------------------- */

static int validate(const multibounce_settings *s, gt_error *e)
{
    if (s->bounces != MULTIBOUNCE_UNLIMITED && (s->bounces < 0 || s->bounces > MULTIBOUNCE_PATH_LIMIT))
        return gt_error_set(e, "env-diffuse", "bounces %d outside [0, %d]", s->bounces, MULTIBOUNCE_PATH_LIMIT);
    if (s->scene_albedo)
        return s->albedo_count == 0 ? 0 : gt_error_set(e, "env-diffuse", "grey albedos given with the scene's");
    if (s->albedo_count != 1)
        return gt_error_set(e, "env-diffuse", "takes one grey albedo or 'scene', not %d albedos", s->albedo_count);
    if (!(s->albedos[0] >= 0.0f && s->albedos[0] <= 1.0f))
        return gt_error_set(e, "env-diffuse", "albedo %g outside [0, 1]", (double)s->albedos[0]);
    return 0;
}

int environment_diffuse_plan_init(environment_diffuse_plan *plan, const environment_light *light,
                                  const multibounce_settings *albedo, normal_mode normals, gt_error *e)
{
    memset(plan, 0, sizeof *plan);
    if (validate(albedo, e) != 0)
        return -1;
    plan->light = light;
    plan->albedo = *albedo;
    plan->normals = normals;
    static const char *const names[3][3] = {CH_ENV_DIFFUSE_RGB, CH_ENV_DIFFUSE_DIRECT_RGB,
                                            CH_ENV_DIFFUSE_UNOCCLUDED_RGB};
    for (int q = 0; q < ENVIRONMENT_DIFFUSE_QUANTITIES; ++q) {
        snprintf(plan->quantities[q].name, IMAGE_NAME_MAX, "%s", names[q / 3][q % 3]);
        plan->quantities[q].scale_exponent = light->scale_exponent;
    }
    return 0;
}

/* ---- Paths (raytracer/diffuse_path_wavefront.h) ----------------------------- */

/* One batch's paths and where they score: values[q * SAMPLE_BATCH + k]. */
typedef struct {
    path_wavefront p;
    const environment_light *light;
    int mixed; /* directions from a mixture of cosine and environment sampling */
    float *values;
} environment_wavefront;

static void wavefront_start(environment_wavefront *wf, const integrator *self, const pixel_context *px,
                            uint32_t first_index, int count, float *values)
{
    const environment_diffuse_plan *plan = self->settings;
    path_wavefront_start(&wf->p, self->scene, px, first_index, count, &plan->albedo, plan->normals);
    wf->light = plan->light;
    wf->mixed = plan->light->brdf_fraction < 1.0f;
    wf->values = values;
    memset(values, 0, sizeof(float) * ENVIRONMENT_DIFFUSE_QUANTITIES * SAMPLE_BATCH);
}

/* Sample k's weight times L into the three channels starting at `first`. */
static void add_light(environment_wavefront *wf, int first, int k, const float light[3])
{
    for (int c = 0; c < 3; ++c)
        wf->values[(first + c) * SAMPLE_BATCH + k] = wf->p.throughput[wf->p.weights == 3 ? c : 0][k] * light[c];
}

/* Sample k's path escapes from vertex `depth`, bringing radiance `light`. */
static void path_escapes(environment_wavefront *wf, int k, int depth, const float light[3])
{
    add_light(wf, TOTAL, k, light);
    if (depth == 0)
        add_light(wf, DIRECT, k, light);
}

/* Which sampler each live path's direction comes from (1: the
 * environment's), u0 rescaled to [0, 1) for it. */
static void choose_strategies(const environment_wavefront *wf, float *u0, unsigned char *from_env)
{
    const float c = wf->light->brdf_fraction;
    for (int i = 0; i < wf->p.live; ++i) {
        from_env[i] = !(u0[i] < c);
        u0[i] = from_env[i] ? (u0[i] - c) / (1.0f - c) : u0[i] / c;
        u0[i] = fminf(u0[i], 0x1.fffffep-1f);
    }
}

/* (max(0, n.w) / pi) / p_mix: the mixture weight of direction w at p,
 * the environment's density there being pdf_env. */
static float lambert_weight(const environment_wavefront *wf, const path_vertex *p, vec3 w, float pdf_env)
{
    double cos_n = v3_dot(w, p->shading.n);
    if (!(cos_n > 0.0))
        return 0.0f;
    double p_brdf = cos_n / M_PI, c = wf->light->brdf_fraction;
    return (float)(p_brdf / (c * p_brdf + (1.0 - c) * pdf_env));
}

/* The directions leaving the live paths: cosine-sampled in each path's
 * shading frame, or drawn from the environment (from_env), all of the
 * latter in one call so that their table lookups overlap. */
static void directions(const environment_wavefront *wf, const vec3 *local, const unsigned char *from_env, const float *u0,
                       const float *u1, vec3 *dir)
{
    float u[SAMPLE_BATCH][2];
    int which[SAMPLE_BATCH], m = 0;
    vec3 drawn[SAMPLE_BATCH];
    for (int i = 0; i < wf->p.live; ++i)
        if (from_env[i])
            u[m][0] = u0[i], u[m][1] = u1[i], which[m++] = i;
        else
            dir[i] = frame_to_world(&wf->p.paths[i].shading, local[i]);
    environment_sampler_sample_many(&wf->light->sampler, m, (const float(*)[2])u, drawn);
    for (int k = 0; k < m; ++k)
        dir[which[k]] = drawn[k];
}

/* The radiance arriving along each direction and the environment's density
 * there, from one texel lookup each (all at once), for the directions that
 * can carry light: under the mixture, those above the shading horizon
 * (lambert_weight is 0 below it and reads neither). The others get 0. */
static void arriving_light(const environment_wavefront *wf, const vec3 *dir, float (*light)[3], float *pdf_env)
{
    vec3 w[SAMPLE_BATCH];
    int which[SAMPLE_BATCH], m = 0;
    float rgb[SAMPLE_BATCH][3], pdf[SAMPLE_BATCH];
    for (int i = 0; i < wf->p.live; ++i) {
        light[i][0] = light[i][1] = light[i][2] = pdf_env[i] = 0.0f;
        if (!wf->mixed || v3_dot(dir[i], wf->p.paths[i].shading.n) > 0.0f)
            w[m] = dir[i], which[m++] = i;
    }
    environment_sampler_lookup_many(&wf->light->sampler, m, w, rgb, pdf);
    for (int k = 0; k < m; ++k) {
        memcpy(light[which[k]], rgb[k], sizeof rgb[k]);
        pdf_env[which[k]] = pdf[k];
    }
}

/* Live path i's mixture weight for direction w, folded into its throughput
 * (mixture sampling only). Returns 0 if the direction carries nothing. */
static int weigh(environment_wavefront *wf, int i, vec3 w, float pdf_env)
{
    if (!wf->mixed)
        return 1;
    const path_vertex *p = &wf->p.paths[i];
    float weight = lambert_weight(wf, p, w, pdf_env);
    for (int k = 0; k < wf->p.weights; ++k)
        wf->p.throughput[k][p->sample] *= weight;
    return weight > 0.0f;
}

/* The rays leaving the live paths' vertices at `depth` (dimension pair
 * depth), owner[r] the path of ray r and light[r] the radiance arriving
 * along it should it escape. At depth 0 every direction adds to the
 * unoccluded channels. A direction below the surface it leaves is blocked
 * and gets no ray. Returns the number of rays. */
static int leaving_rays(environment_wavefront *wf, int depth, struct RTCRayHit *rays, int *owner, float (*light)[3])
{
    float u0[SAMPLE_BATCH], u1[SAMPLE_BATCH], arriving[SAMPLE_BATCH][3], pdf_env[SAMPLE_BATCH];
    unsigned char from_env[SAMPLE_BATCH] = {0};
    vec3 local[SAMPLE_BATCH], dir[SAMPLE_BATCH];
    path_wavefront_live_points(&wf->p, (uint32_t)depth, u0, u1);
    if (wf->mixed)
        choose_strategies(wf, u0, from_env);
    sample_cosine_hemisphere_batch(u0, u1, wf->p.live, local);
    directions(wf, local, from_env, u0, u1, dir);
    arriving_light(wf, dir, arriving, pdf_env);
    int n = 0;
    for (int i = 0; i < wf->p.live; ++i) {
        const path_vertex *p = &wf->p.paths[i];
        if (!weigh(wf, i, dir[i], pdf_env[i]))
            continue;
        if (depth == 0)
            add_light(wf, UNOCCLUDED, p->sample, arriving[i]);
        if (v3_dot(dir[i], p->ng) <= 0.0f)
            continue;
        memcpy(light[n], arriving[i], sizeof arriving[i]);
        embree_ray_init(&rays[n].ray, p->origin, dir[i], INFINITY);
        owner[n++] = i;
    }
    return n;
}

/* The last vertex: only whether each ray escapes matters. */
static void trace_last(environment_wavefront *wf, int depth, const struct RTCRayHit *rays, const int *owner,
                       const float (*light)[3], int n)
{
    _Alignas(16) struct RTCRay shadow[SAMPLE_BATCH];
    for (int r = 0; r < n; ++r)
        shadow[r] = rays[r].ray;
    embree_unoccluded_stream(wf->p.scene, shadow, (unsigned)n);
    for (int r = 0; r < n; ++r)
        if (shadow[r].tfar >= 0.0f)
            path_escapes(wf, wf->p.paths[owner[r]].sample, depth, light[r]);
    wf->p.live = 0;
}

/* Closest hits: escapes add light, hits become the next vertices of the
 * paths that survive them (compacted in place, in order). */
static void trace_next(environment_wavefront *wf, int depth, struct RTCRayHit *rays, const int *owner,
                       const float (*light)[3], int n)
{
    float roulette[SAMPLE_BATCH];
    if (wf->p.unlimited)
        path_wavefront_roulette(&wf->p, depth, roulette);
    embree_closest_hit_stream(wf->p.scene, rays, (unsigned)n);
    int kept = 0;
    for (int r = 0; r < n; ++r) {
        path_vertex *p = &wf->p.paths[owner[r]];
        if (rays[r].hit.geomID == RTC_INVALID_GEOMETRY_ID)
            path_escapes(wf, p->sample, depth, light[r]);
        else {
            surface_hit hit;
            embree_surface_at(wf->p.scene, &rays[r], wf->p.surface_parts, &hit);
            if (path_wavefront_continue(&wf->p, &hit, wf->p.unlimited ? roulette[owner[r]] : 0.0f, p))
                wf->p.paths[kept++] = *p;
        }
    }
    wf->p.live = kept;
}

static int environment_diffuse_sample_batch(const integrator *self, const pixel_context *px, uint32_t first_index,
                                            int count, float *values)
{
    environment_wavefront wf;
    wavefront_start(&wf, self, px, first_index, count, values);
    int rays = 0;
    for (int depth = 0; wf.p.live > 0; ++depth) {
        _Alignas(16) struct RTCRayHit stream[SAMPLE_BATCH];
        int owner[SAMPLE_BATCH];
        float light[SAMPLE_BATCH][3];
        int n = leaving_rays(&wf, depth, stream, owner, light);
        rays += n;
        if (depth == wf.p.max_bounces)
            trace_last(&wf, depth, stream, owner, (const float(*)[3])light, n);
        else
            trace_next(&wf, depth, stream, owner, (const float(*)[3])light, n);
    }
    return rays;
}

integrator environment_diffuse_integrator(const embree_scene *es, const environment_diffuse_plan *plan)
{
    integrator it = {"env-diffuse", ENVIRONMENT_DIFFUSE_QUANTITIES, plan->quantities, NULL, environment_diffuse_sample_batch,
                     es, plan, 0};
    return it;
}
