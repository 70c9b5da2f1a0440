#include "raytracer/multibounce_integrator.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/hemisphere_sampling.h"
#include "scene/material_lookup.h"
#include "core/reference_schema.h"

/* ---- Settings ---------------------------------------------------------------------- */

/* The shortest %g text that reads back as the same float, so a channel name
 * says "0.3" rather than "0.300000012" and distinct albedos get distinct names. */
static void format_albedo(float albedo, char *text, size_t size)
{
    for (int digits = 1; digits <= 9; ++digits) {
        snprintf(text, size, "%.*g", digits, (double)albedo);
        if (strtof(text, NULL) == albedo)
            return;
    }
}

static int parse_albedo(const char *token, float *albedo, gt_error *e)
{
    char *end;
    errno = 0;
    double value = strtod(token, &end);
    if (end == token || *end != '\0' || errno != 0 || !(value >= 0.0 && value <= 1.0))
        return gt_error_set(e, "--albedo", "'%s' is not an albedo in [0, 1]", token);
    *albedo = (float)value;
    return 0;
}

/* Whether albedo i repeats an earlier one (it would name the same channel). */
static int repeats_earlier(const multibounce_settings *s, int i)
{
    for (int j = 0; j < i; ++j)
        if (s->albedos[j] == s->albedos[i])
            return 1;
    return 0;
}

int multibounce_parse_albedos(const char *text, multibounce_settings *s, gt_error *e)
{
    if (strcmp(text, "scene") == 0) {
        s->scene_albedo = 1;
        s->albedo_count = 0;
        return 0;
    }
    s->scene_albedo = 0;
    s->albedo_count = 0;
    for (const char *start = text;; ++start) {
        const char *comma = strchr(start, ',');
        size_t length = comma ? (size_t)(comma - start) : strlen(start);
        char token[64];
        if (length == 0 || length >= sizeof token)
            return gt_error_set(e, "--albedo", "'%s' is not a comma-separated list of albedos or 'scene'", text);
        if (s->albedo_count == MULTIBOUNCE_MAX_ALBEDOS)
            return gt_error_set(e, "--albedo", "more than %d albedos", MULTIBOUNCE_MAX_ALBEDOS);
        memcpy(token, start, length);
        token[length] = '\0';
        if (parse_albedo(token, &s->albedos[s->albedo_count], e) != 0)
            return -1;
        if (repeats_earlier(s, s->albedo_count++))
            return gt_error_set(e, "--albedo", "'%s' is given twice", token);
        if (!comma)
            return 0;
        start = comma;
    }
}

int multibounce_parse_bounces(const char *text, multibounce_settings *s, gt_error *e)
{
    if (strcmp(text, "inf") == 0) {
        s->bounces = MULTIBOUNCE_UNLIMITED;
        return 0;
    }
    char *end;
    errno = 0;
    long value = strtol(text, &end, 10);
    if (end == text || *end != '\0' || errno != 0 || value < 0 || value > MULTIBOUNCE_PATH_LIMIT)
        return gt_error_set(e, "--bounces", "'%s' is neither a count in [0, %d] nor 'inf'", text,
                            MULTIBOUNCE_PATH_LIMIT);
    s->bounces = (int)value;
    return 0;
}

void multibounce_albedos_text(const multibounce_settings *s, char *text, size_t size)
{
    if (s->scene_albedo) {
        snprintf(text, size, "scene");
        return;
    }
    size_t used = 0;
    text[0] = '\0';
    for (int i = 0; i < s->albedo_count && used + 1 < size; ++i) {
        char one[32];
        format_albedo(s->albedos[i], one, sizeof one);
        used += (size_t)snprintf(text + used, size - used, "%s%s", i ? " " : "", one);
    }
}

void multibounce_bounces_text(const multibounce_settings *s, char *text, size_t size)
{
    if (s->bounces == MULTIBOUNCE_UNLIMITED)
        snprintf(text, size, "inf");
    else
        snprintf(text, size, "%d", s->bounces);
}

static int validate(const multibounce_settings *s, gt_error *e)
{
    if (s->bounces != MULTIBOUNCE_UNLIMITED && (s->bounces < 0 || s->bounces > MULTIBOUNCE_PATH_LIMIT))
        return gt_error_set(e, "multibounce", "bounces %d outside [0, %d]", s->bounces, MULTIBOUNCE_PATH_LIMIT);
    if (s->scene_albedo)
        return s->albedo_count == 0 ? 0 : gt_error_set(e, "multibounce", "grey albedos given with the scene's");
    if (s->albedo_count < 1 || s->albedo_count > MULTIBOUNCE_MAX_ALBEDOS)
        return gt_error_set(e, "multibounce", "needs 1 to %d albedos (or the scene's)", MULTIBOUNCE_MAX_ALBEDOS);
    for (int i = 0; i < s->albedo_count; ++i) {
        if (!(s->albedos[i] >= 0.0f && s->albedos[i] <= 1.0f))
            return gt_error_set(e, "multibounce", "albedo %g outside [0, 1]", (double)s->albedos[i]);
        if (repeats_earlier(s, i))
            return gt_error_set(e, "multibounce", "albedo %g given twice", (double)s->albedos[i]);
    }
    return 0;
}

/* Channel names: see the header. Every sample lies in [0, 1]: scale exponent 0. */
static void name_quantities(multibounce_plan *plan)
{
    const multibounce_settings *s = &plan->settings;
    int n = 0;
    if (s->scene_albedo) {
        static const char *const colours[3] = {CH_MULTIBOUNCE_R, CH_MULTIBOUNCE_G, CH_MULTIBOUNCE_B};
        for (int c = 0; c < 3; ++c)
            snprintf(plan->quantities[n++].name, IMAGE_NAME_MAX, "%s", colours[c]);
    } else if (s->albedo_count == 1) {
        snprintf(plan->quantities[n++].name, IMAGE_NAME_MAX, CH_MULTIBOUNCE);
    } else {
        for (int i = 0; i < s->albedo_count; ++i) {
            char albedo[32];
            format_albedo(s->albedos[i], albedo, sizeof albedo);
            snprintf(plan->quantities[n++].name, IMAGE_NAME_MAX, CH_MULTIBOUNCE_ALBEDO_FMT, albedo);
        }
    }
    snprintf(plan->quantities[n++].name, IMAGE_NAME_MAX, CH_AO);
    for (int q = 0; q < n; ++q)
        plan->quantities[q].scale_exponent = 0;
    plan->quantity_count = n;
}

int multibounce_plan_init(multibounce_plan *plan, const multibounce_settings *s, normal_mode normals, gt_error *e)
{
    memset(plan, 0, sizeof *plan);
    if (validate(s, e) != 0)
        return -1;
    plan->settings = *s;
    plan->normals = normals;
    name_quantities(plan);
    return 0;
}

void multibounce_warn_albedo_range(const scene *s)
{
    for (int m = 0; m < s->material_count; ++m)
        for (int c = 0; c < 3; ++c)
            if (!(s->materials[m].base_color[c] >= 0.0f && s->materials[m].base_color[c] <= 1.0f)) {
                gt_warn(s->name, "material %d has base colour %g outside [0, 1]; clamped for multibounce", m,
                        (double)s->materials[m].base_color[c]);
                return;
            }
}

/* ---- Paths ------------------------------------------------------------------------- */

/* A path at its current vertex. throughput[w] is the product of rho / q
 * (or rho at fixed depth) over the vertices after the first, per albedo
 * or colour channel w. */
typedef struct {
    vec3 origin, ng;
    frame shading;
    float throughput[MULTIBOUNCE_MAX_ALBEDOS];
    int sample; /* index within the batch */
} path_vertex;

static int weight_count(const multibounce_plan *plan)
{
    return plan->settings.scene_albedo ? 3 : plan->settings.albedo_count;
}

static path_vertex path_start(const pixel_context *px, int sample, int weights)
{
    path_vertex p;
    p.origin = px->ray_origin;
    p.ng = px->surface->ng;
    p.shading = px->shading; /* already on the geometric normal under NORMAL_GEOMETRIC (gbuffer.h) */
    for (int w = 0; w < weights; ++w)
        p.throughput[w] = 1.0f;
    p.sample = sample;
    return p;
}

static void path_move_to(path_vertex *p, const surface_hit *hit, normal_mode normals)
{
    p->origin = offset_ray_origin(hit->p, hit->ng);
    p->ng = hit->ng;
    p->shading = frame_from_normal(normals == NORMAL_GEOMETRIC ? hit->ng : hit->ns);
}

/* The albedos of a surface point, per weight. */
static void vertex_albedos(const multibounce_plan *plan, const scene *s, const surface_hit *hit, float *rho)
{
    if (!plan->settings.scene_albedo) {
        memcpy(rho, plan->settings.albedos, sizeof(float) * (size_t)plan->settings.albedo_count);
        return;
    }
    material_sample m = material_lookup(s, hit->mesh, hit->uv);
    for (int c = 0; c < 3; ++c)
        rho[c] = fminf(fmaxf(m.base_color[c], 0.0f), 1.0f);
}

/* Takes the path through a new vertex of albedos rho: at fixed depth the
 * throughput is multiplied by rho; unlimited, the path survives Russian
 * roulette with probability q = max rho (u uniform in [0, 1)) and is
 * multiplied by rho / q. Returns 0 if the path ends here. */
static int path_survives(const multibounce_plan *plan, const float *rho, float u, path_vertex *p)
{
    int weights = weight_count(plan);
    if (plan->settings.bounces != MULTIBOUNCE_UNLIMITED) {
        for (int w = 0; w < weights; ++w)
            p->throughput[w] *= rho[w];
        return 1;
    }
    float q = 0.0f;
    for (int w = 0; w < weights; ++w)
        q = fmaxf(q, rho[w]);
    if (!(u < q))
        return 0;
    for (int w = 0; w < weights; ++w)
        p->throughput[w] *= rho[w] / q;
    return 1;
}

/* Samples as a wavefront: every live path of the batch takes one bounce
 * before any takes the next, so each dimension pair's scramble seeds are
 * derived once per batch. A path escaping from vertex k adds its
 * throughput (prod rho over k inter-reflections) to each multibounce
 * channel, and 1 to ao.V if k = 0. */
static int multibounce_sample_batch(const integrator *self, const pixel_context *px, uint32_t first_index,
                                    int count, float *values)
{
    const multibounce_plan *plan = self->settings;
    const int weights = weight_count(plan), ao = weights;
    const int unlimited = plan->settings.bounces == MULTIBOUNCE_UNLIMITED;
    const int max_bounces = unlimited ? MULTIBOUNCE_PATH_LIMIT : plan->settings.bounces;
    path_vertex paths[SAMPLE_BATCH];
    memset(values, 0, sizeof(float) * (size_t)plan->quantity_count * SAMPLE_BATCH);
    for (int k = 0; k < count; ++k)
        paths[k] = path_start(px, k, weights);
    int live = count, rays = 0;
    for (int depth = 0; live > 0; ++depth) {
        const sample_pair_seeds directions = sample_pair_seeds_for(px, (uint32_t)depth);
        const sample_pair_seeds roulette = sample_pair_seeds_for(px, MULTIBOUNCE_ROULETTE_PAIRS + (uint32_t)depth + 1);
        int kept = 0;
        for (int i = 0; i < live; ++i) {
            path_vertex *p = &paths[i];
            uint32_t index = first_index + (uint32_t)p->sample;
            float u[2];
            sample_pair_point(&directions, index, u);
            vec3 d = frame_to_world(&p->shading, sample_cosine_hemisphere(u));
            if (v3_dot(d, p->ng) <= 0.0f)
                continue; /* below the surface it leaves: blocked */
            surface_hit hit;
            ++rays;
            if (!embree_closest_hit(self->scene, p->origin, d, INFINITY, &hit)) {
                for (int w = 0; w < weights; ++w)
                    values[w * SAMPLE_BATCH + p->sample] = p->throughput[w];
                values[ao * SAMPLE_BATCH + p->sample] = depth == 0 ? 1.0f : 0.0f;
                continue;
            }
            if (depth == max_bounces)
                continue;
            float rho[MULTIBOUNCE_MAX_ALBEDOS], r[2] = {0.0f, 0.0f};
            vertex_albedos(plan, self->scene->source, &hit, rho);
            if (unlimited)
                sample_pair_point(&roulette, index, r);
            if (!path_survives(plan, rho, r[0], p))
                continue;
            path_move_to(p, &hit, plan->normals);
            paths[kept++] = *p;
        }
        live = kept;
    }
    return rays;
}

integrator multibounce_integrator(const embree_scene *es, const multibounce_plan *plan)
{
    integrator it = {"multibounce", plan->quantity_count, plan->quantities, NULL, multibounce_sample_batch, es, plan};
    return it;
}
