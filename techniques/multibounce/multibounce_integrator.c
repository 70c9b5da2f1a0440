#include "multibounce/multibounce_integrator.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/sampling/hemisphere_sampling.h"
#include "core/reference_schema.h"
#include "raytracer/diffuse_path_wavefront.h"

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

/* One batch's paths (raytracer/diffuse_path_wavefront.h) and where they
 * score: values[q * SAMPLE_BATCH + k]. */
typedef struct {
    path_wavefront p;
    float *values;
} wavefront;

static void wavefront_start(wavefront *wf, const integrator *self, const pixel_context *px, uint32_t first_index,
                            int count, float *values)
{
    const multibounce_plan *plan = self->settings;
    path_wavefront_start(&wf->p, self->scene, px, first_index, count, &plan->settings, plan->normals);
    wf->values = values;
    memset(values, 0, sizeof(float) * (size_t)plan->quantity_count * SAMPLE_BATCH);
}

/* Sample k's path escapes from vertex `depth`: it adds its throughput (prod
 * rho over depth inter-reflections) to each multibounce channel, and 1 to
 * ao.V if depth = 0. */
static void path_escapes(wavefront *wf, int k, int depth)
{
    for (int w = 0; w < wf->p.weights; ++w)
        wf->values[w * SAMPLE_BATCH + k] = wf->p.throughput[w][k];
    wf->values[wf->p.weights * SAMPLE_BATCH + k] = depth == 0 ? 1.0f : 0.0f;
}

/* The rays leaving the live paths' vertices at `depth` (dimension pair
 * depth), owner[r] the path of ray r; a direction below the surface it
 * leaves is blocked and gets no ray. Returns the number of rays. */
static int leaving_rays(const path_wavefront *wf, int depth, struct RTCRayHit *rays, int *owner)
{
    float u0[SAMPLE_BATCH], u1[SAMPLE_BATCH];
    vec3 local[SAMPLE_BATCH];
    path_wavefront_live_points(wf, (uint32_t)depth, u0, u1);
    sample_cosine_hemisphere_batch(u0, u1, wf->live, local);
    int n = 0;
    for (int i = 0; i < wf->live; ++i) {
        const path_vertex *p = &wf->paths[i];
        vec3 d = frame_to_world(&p->shading, local[i]);
        if (v3_dot(d, p->ng) <= 0.0f)
            continue;
        embree_ray_init(&rays[n].ray, p->origin, d, INFINITY);
        owner[n++] = i;
    }
    return n;
}

/* The 3-D scene's world (multibounce_world): an occlusion stream for the
 * last rays, else a closest-hit stream and the surfaces hit. */
static void embree_trace(const void *data, struct RTCRayHit *rays, int n, int last, unsigned parts,
                         unsigned char *escaped, surface_hit *hits)
{
    const embree_scene *es = data;
    if (last) {
        _Alignas(16) struct RTCRay shadow[SAMPLE_BATCH];
        for (int r = 0; r < n; ++r)
            shadow[r] = rays[r].ray;
        embree_unoccluded_stream(es, shadow, (unsigned)n);
        for (int r = 0; r < n; ++r)
            escaped[r] = shadow[r].tfar >= 0.0f;
        return;
    }
    embree_closest_hit_stream(es, rays, (unsigned)n);
    for (int r = 0; r < n; ++r) {
        escaped[r] = rays[r].hit.geomID == RTC_INVALID_GEOMETRY_ID;
        if (!escaped[r])
            embree_surface_at(es, &rays[r], parts, &hits[r]);
    }
}

/* The rays leaving `depth` traced in the world: escapes are scored, and
 * (before the last vertex, depth = max_bounces) hits become the next
 * vertices of the paths that survive them (compacted in place, in order). */
static void trace_depth(wavefront *wf, const multibounce_world *world, int depth, struct RTCRayHit *rays,
                        const int *owner, int n)
{
    const int last = depth == wf->p.max_bounces;
    float roulette[SAMPLE_BATCH];
    unsigned char escaped[SAMPLE_BATCH];
    surface_hit hits[SAMPLE_BATCH];
    if (!last && wf->p.unlimited)
        path_wavefront_roulette(&wf->p, depth, roulette);
    world->trace(world->data, rays, n, last, wf->p.surface_parts, escaped, hits);
    int kept = 0;
    for (int r = 0; r < n; ++r) {
        path_vertex *p = &wf->p.paths[owner[r]];
        if (escaped[r])
            path_escapes(wf, p->sample, depth);
        else if (!last && path_wavefront_continue(&wf->p, &hits[r], wf->p.unlimited ? roulette[owner[r]] : 0.0f, p))
            wf->p.paths[kept++] = *p;
    }
    wf->p.live = kept;
}

/* Samples as a wavefront (above): each depth's rays go to the world as one
 * stream, and each dimension pair's scramble seeds are derived once per
 * batch. Returns the rays traced. */
static int multibounce_sample_batch(const integrator *self, const pixel_context *px, uint32_t first_index,
                                    int count, float *values)
{
    const multibounce_plan *plan = self->settings;
    const multibounce_world world = plan->world.trace ? plan->world : (multibounce_world){embree_trace, self->scene};
    wavefront wf;
    wavefront_start(&wf, self, px, first_index, count, values);
    int rays = 0;
    for (int depth = 0; wf.p.live > 0; ++depth) {
        _Alignas(16) struct RTCRayHit stream[SAMPLE_BATCH];
        int owner[SAMPLE_BATCH];
        int n = leaving_rays(&wf.p, depth, stream, owner);
        rays += n;
        trace_depth(&wf, &world, depth, stream, owner, n);
    }
    return rays;
}

integrator multibounce_integrator(const embree_scene *es, const multibounce_plan *plan)
{
    integrator it = {"multibounce", plan->quantity_count, plan->quantities, NULL, multibounce_sample_batch, es, plan, 0};
    return it;
}
