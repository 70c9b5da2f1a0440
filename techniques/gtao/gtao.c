/* GTAO after Jimenez et al., SIGGRAPH 2016 (seeds/001), slides "Method",
 * "Integration Domain", "Cosine Weighting", "Cosine Weighting Normal
 * Projection", "Bent Normal", "Achieving the Performance Target", "Noise
 * Distribution", "Minimizing Artifacts". Corrections to the transcription
 * (each proved in tests/):
 *  - "Method": h = -+cos(max ...) must be -+acos(max ...): the max is a cosine.
 *  - GTAOFastCos is an arc cosine (Eberly's acos), not a cosine.
 *  - GTAOFastSqrt's constant 0x1FB01DF5 is Drobot's 0x1FBD1DF5 with a digit
 *    lost: the transcribed one is 10.5% low at worst, Drobot's 4.5%.
 *  - The 4x4 direction noise lacks a pair of brackets: as transcribed the
 *    (x & 3) term is not scaled by 1/16, adds whole turns, and the tile holds
 *    4 distinct directions instead of 16.
 *  - "offsets[frameCount / 6] % 4]" is offsets[(frameCount / 6) % 4].
 *  - Temporal rotations and offsets added at full weight repeat the spatial
 *    values (48 distinct slices, 4 distinct offsets, not 96 and 16); they are
 *    applied as sub-steps of the spatial pattern (rotation / 16, offset / 4).
 *  - "Possible Pitfall": the integrand is cos(theta - n) |sin theta|.
 *  - "Bent Normal": the halfway direction between the horizons is 16 degrees
 *    off on an open plane seen at 45 degrees; the arc's cosine-weighted mean
 *    direction is integrated in closed form instead (gtao_integrate_arc_bent).
 * Addition: slices are weighted by d psi / d phi (gtao_slice_weight), the
 * rotation about the view vector per screen angle, without which a tilted
 * plane off the image centre came out 2% dark with 32 regular slices. */
#include "gtao/gtao.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gtao/gtao_denoiser.h"
#include "gtao/gtao_pattern.h"

#define GTAO_PI 3.14159265358979f

float gtao_integrate_arc_cosine(float h1, float h2, float n)
{
    float cos_n = cosf(n), sin_n = sinf(n);
    return 0.25f * (-cosf(2.0f * h1 - n) + cos_n + 2.0f * h1 * sin_n) +
           0.25f * (-cosf(2.0f * h2 - n) + cos_n + 2.0f * h2 * sin_n);
}

float gtao_integrate_arc_uniform(float h1, float h2) { return (1.0f - cosf(h1)) + (1.0f - cosf(h2)); }

/* Antiderivatives of cos t cos(t - n) sin t and sin t cos(t - n) sin t,
 * with cos(t - n) = cos t cos n + sin t sin n. */
static void bent_antiderivatives(float t, float cos_n, float sin_n, float *fv, float *fs)
{
    float c = cosf(t), s = sinf(t), c3 = c * c * c, s3 = s * s * s;
    *fv = (-cos_n * c3 + sin_n * s3) / 3.0f;
    *fs = cos_n * s3 / 3.0f + sin_n * (c3 / 3.0f - c);
}

void gtao_integrate_arc_bent(float h1, float h2, float n, float *bv, float *bs)
{
    float cos_n = cosf(n), sin_n = sinf(n), v1, s1, v2, s2, v0, s0;
    bent_antiderivatives(h1, cos_n, sin_n, &v1, &s1);
    bent_antiderivatives(h2, cos_n, sin_n, &v2, &s2);
    bent_antiderivatives(0.0f, cos_n, sin_n, &v0, &s0);
    /* Side 2 runs 0 -> h2 with |sin| = sin; side 1 runs h1 -> 0 with
     * |sin| = -sin, which is F(h1) - F(0) as well. */
    *bv = (v2 - v0) + (v1 - v0);
    *bs = (s2 - s0) + (s1 - s0);
}

float gtao_fast_sqrt_magic(float x, uint32_t magic)
{
    uint32_t bits;
    memcpy(&bits, &x, sizeof bits);
    bits = magic + (bits >> 1);
    float r;
    memcpy(&r, &bits, sizeof r);
    return r;
}

float gtao_fast_sqrt(float x) { return gtao_fast_sqrt_magic(x, GTAO_FAST_SQRT_MAGIC); }

float gtao_fast_acos(float x)
{
    float a = fabsf(x);
    float r = (-0.156583f * a + 0.5f * GTAO_PI) * gtao_fast_sqrt(1.0f - a);
    return x >= 0.0f ? r : GTAO_PI - r;
}

static float fraction(float t) { return t - floorf(t); }

float gtao_slice_angle(int x, int y, int frame, int k, int slices, int pattern)
{
    float u = pattern ? fraction(gtao_pattern_direction(x, y, pattern) + gtao_temporal_rotation(frame) / 16.0f) : 0.5f;
    return GTAO_PI * ((float)k + u) / (float)slices;
}

float gtao_step_offset(int x, int y, int frame, int pattern)
{
    return pattern ? fraction(gtao_spatial_offset(x, y) + 0.25f * gtao_temporal_offset(frame)) : 0.5f;
}

static const gtao_params presets[] = {
    /* weighting, slices, steps, radius, falloff, max px, thickness, pattern, fast, denoise, frames, bent halfway */
    {GTAO_COSINE, 1, 2, 1.0f, 0.25f, 256.0f, 0.0f, 1, 1, 1, 1, 0},   /* low */
    {GTAO_COSINE, 1, 4, 1.0f, 0.25f, 256.0f, 0.0f, 1, 1, 1, 1, 0},   /* medium: the talk's */
    {GTAO_COSINE, 2, 6, 1.0f, 0.25f, 256.0f, 0.0f, 1, 0, 1, 1, 0},   /* high */
    {GTAO_COSINE, 4, 8, 1.0f, 0.25f, 256.0f, 0.0f, 1, 0, 1, 1, 0},   /* ultra */
    {GTAO_COSINE, 64, 0, 1.0f, 0.25f, 256.0f, 0.0f, 0, 0, 0, 1, 0},  /* reference: every cell */
};
const char *const gtao_preset_names[] = {"low", "medium", "high", "ultra", "reference", NULL};
_Static_assert(sizeof gtao_preset_names / sizeof gtao_preset_names[0] == GTAO_PRESET_COUNT + 1,
               "gtao_preset_id follows gtao_preset_names");
_Static_assert(sizeof presets / sizeof presets[0] == GTAO_PRESET_COUNT, "one preset per gtao_preset_id");

gtao_params gtao_params_shader_port(void)
{
    return (gtao_params){.weighting = GTAO_COSINE, .slices = 4, .steps = 8, .radius = 1.0f, .falloff = 0.25f,
                         .max_radius_px = 256.0f, .frames = 1};
}

int gtao_preset(const char *name, gtao_params *p)
{
    for (int i = 0; gtao_preset_names[i]; ++i)
        if (strcmp(name, gtao_preset_names[i]) == 0) {
            *p = presets[i];
            return 0;
        }
    return -1;
}

void gtao_params_text(const gtao_params *p, char *text, size_t size)
{
    snprintf(text, size,
             "weighting=%s slices=%d steps=%d radius=%.9g falloff=%.9g max_radius_px=%.9g thickness=%.9g pattern=%d "
             "fast_math=%d denoise=%d frames=%d bent=%s",
             p->weighting == GTAO_UNIFORM ? "uniform" : "cosine", p->slices, p->steps, p->radius, p->falloff,
             p->max_radius_px, p->thickness, p->pattern, p->fast_math, p->denoise, p->frames,
             p->bent_halfway ? "halfway" : "exact");
}

static int keep_sample(const ss_gbuffer *g, int x, int y, float fx, float fy, float (*xy)[2], int count)
{
    int sx = (int)floorf(fx), sy = (int)floorf(fy);
    if ((sx == x && sy == y) || !ss_covered(g, sx, sy))
        return count;
    xy[count][0] = fx;
    xy[count][1] = fy;
    return count + 1;
}

/* Exact mode: both ends of every pixel cell the line crosses. Each cell is a
 * plane piece, and along a line on a plane the angle seen from the centre
 * is monotonic, so a cell's highest point is one of its ends. */
static int cell_samples(const ss_gbuffer *g, int x, int y, float dx, float dy, float radius_px, float (*xy)[2])
{
    const float eps = 1e-3f;
    float ox = (float)x + 0.5f, oy = (float)y + 0.5f;
    float step_x = dx > 0 ? 1.0f / dx : dx < 0 ? -1.0f / dx : INFINITY;
    float step_y = dy > 0 ? 1.0f / dy : dy < 0 ? -1.0f / dy : INFINITY;
    float next_x = step_x * 0.5f, next_y = step_y * 0.5f; /* the centre is mid-cell */
    int count = 0;
    float t = 0.0f;
    while (t < radius_px && count + 2 <= GTAO_MAX_SAMPLES) {
        float t_next = ss_minf(ss_minf(next_x, next_y), radius_px);
        if (t > 0.0f)
            count = keep_sample(g, x, y, ox + (t + eps) * dx, oy + (t + eps) * dy, xy, count);
        count = keep_sample(g, x, y, ox + (t_next - eps) * dx, oy + (t_next - eps) * dy, xy, count);
        if (next_x <= next_y)
            next_x += step_x;
        else
            next_y += step_y;
        t = t_next;
        float fx = ox + t * dx, fy = oy + t * dy;
        if (fx < 0.0f || fy < 0.0f || fx > (float)g->width || fy > (float)g->height)
            break;
    }
    return count;
}

int ss_side_samples(const ss_gbuffer *g, int x, int y, float dx, float dy, float radius_px, int steps, float offset,
                    float (*xy)[2])
{
    if (steps == 0)
        return cell_samples(g, x, y, dx, dy, radius_px, xy);
    int count = 0;
    for (int j = 0; j < steps; ++j) {
        float t = radius_px * ((float)j + offset) / (float)steps;
        count = keep_sample(g, x, y, (float)x + 0.5f + t * dx, (float)y + 0.5f + t * dy, xy, count);
    }
    return count;
}

/* Conservative attenuation: full effect up to (1 - falloff) radius, then a
 * linear fade to none at the radius. */
static float attenuation(float distance, const gtao_params *p)
{
    float fade = p->falloff * p->radius;
    if (fade <= 0.0f)
        return distance <= p->radius ? 1.0f : 0.0f;
    return ss_minf(ss_maxf((p->radius - distance) / fade, 0.0f), 1.0f);
}

/* Cosines computed from rounded positions may leave [-1, 1] by an ulp; the
 * fast acos would then take the fast sqrt of a negative number. */
static float acos_of(float c, int fast)
{
    c = ss_minf(ss_maxf(c, -1.0f), 1.0f);
    return fast ? gtao_fast_acos(c) : acosf(c);
}

/* Cosine of the horizon on one side, from near to far: a sample raises the
 * horizon to its own cosine (faded towards `low`, the side's hemisphere
 * limit, by its attenuation); with the thickness heuristic a lower sample
 * behind the current horizon pulls it back down a little, since an occluder
 * seen only by its front face is assumed about as thick as it is wide. */
static float side_horizon_cos(const ss_gbuffer *g, vec3 pc, vec3 v, const float (*xy)[2], int count, float low,
                              const gtao_params *p)
{
    float horizon = low;
    for (int i = 0; i < count; ++i) {
        vec3 d = v3_sub(ss_sample_position(g, xy[i][0], xy[i][1]), pc);
        float len = v3_length(d);
        float c = low + attenuation(len, p) * (v3_dot(d, v) / len - low);
        if (c > horizon)
            horizon = c;
        else
            horizon += p->thickness * (ss_maxf(c, low) - horizon);
    }
    return horizon;
}

float gtao_slice_weight(vec3 v, float phi)
{
    float dv = cosf(phi) * v.x - sinf(phi) * v.y;
    return v.z / (1.0f - dv * dv);
}

void gtao_slice_geometry(const ss_gbuffer *g, int x, int y, float phi, int fast_math, gtao_slice *s)
{
    vec3 pc = ss_view_position(g, x, y), n = ss_view_normal(g, x, y);
    float dx = cosf(phi), dy = sinf(phi);
    /* Screen direction (dx, dy) (y down) is the view-space direction (dx, -dy, 0)
     * on the image plane; the slice plane holds it and the eye ray. */
    vec3 d3 = v3(dx, -dy, 0.0f);
    s->v = v3_normalize(v3_neg(pc));
    s->side = v3_normalize(v3_sub(d3, v3_scale(s->v, v3_dot(d3, s->v))));
    s->weight = gtao_slice_weight(s->v, phi);
    vec3 axis = v3_cross(s->side, s->v);
    vec3 np = v3_sub(n, v3_scale(axis, v3_dot(n, axis)));
    s->n_len = v3_length(np);
    float cos_n = s->n_len > 0.0f ? v3_dot(np, s->v) / s->n_len : 1.0f;
    float n_angle = acos_of(cos_n, fast_math);
    s->n = v3_dot(np, s->side) < 0.0f ? -n_angle : n_angle;
}

void gtao_search_slice(const ss_gbuffer *g, int x, int y, const gtao_params *p, float phi, float offset,
                       gtao_slice *s)
{
    gtao_slice_geometry(g, x, y, phi, p->fast_math, s);
    vec3 pc = ss_view_position(g, x, y);
    float dx = cosf(phi), dy = sinf(phi);
    /* The hemisphere limits n -+ pi/2 as cosines from v: cos(n - pi/2) = sin n,
     * cos(n + pi/2) = -sin n. */
    float sin_n = sinf(s->n);
    float xy[GTAO_MAX_SAMPLES][2];
    float r = ss_radius_px(g, x, y, p->radius, p->max_radius_px);
    int c2n = ss_side_samples(g, x, y, dx, dy, r, p->steps, offset, xy);
    float c2 = side_horizon_cos(g, pc, s->v, (const float(*)[2])xy, c2n, -sin_n, p);
    int c1n = ss_side_samples(g, x, y, -dx, -dy, r, p->steps, offset, xy);
    float c1 = side_horizon_cos(g, pc, s->v, (const float(*)[2])xy, c1n, sin_n, p);
    float h1 = -acos_of(c1, p->fast_math), h2 = acos_of(c2, p->fast_math);
    s->h1 = s->n + ss_maxf(h1 - s->n, -0.5f * GTAO_PI);
    s->h2 = s->n + ss_minf(h2 - s->n, 0.5f * GTAO_PI);
}

/* The slice's visibility contribution: cosine-weighted arcs are weighted by
 * the projected normal's length (Timonen 2013); uniform arcs are halved so
 * an open slice counts 1 in both. */
static float slice_visibility(const gtao_slice *s, gtao_weighting w)
{
    if (w == GTAO_UNIFORM)
        return 0.5f * gtao_integrate_arc_uniform(s->h1, s->h2);
    return s->n_len * gtao_integrate_arc_cosine(s->h1, s->h2, s->n);
}

/* The slice's share of the bent normal (view space): the exact
 * cosine-weighted mean direction of the visible arc, weighted like the
 * visibility, or the talk's halfway direction weighted by the visibility. */
static vec3 slice_bent(const gtao_slice *s, float visibility, int halfway)
{
    float bv, bs;
    if (halfway) {
        float h = gtao_bent_halfway_angle(s->h1, s->h2);
        bv = visibility * cosf(h);
        bs = visibility * sinf(h);
    } else {
        gtao_integrate_arc_bent(s->h1, s->h2, s->n, &bv, &bs);
        bv *= s->weight * s->n_len;
        bs *= s->weight * s->n_len;
    }
    return v3_add(v3_scale(s->v, bv), v3_scale(s->side, bs));
}

static void pixel_gtao(const ss_gbuffer *g, const void *params, int frame, int x, int y, float *ao, vec3 *bent)
{
    const gtao_params *p = params;
    float sum = 0.0f;
    vec3 b = v3(0.0f, 0.0f, 0.0f);
    float offset = gtao_step_offset(x, y, frame, p->pattern);
    for (int k = 0; k < p->slices; ++k) {
        gtao_slice s;
        gtao_search_slice(g, x, y, p, gtao_slice_angle(x, y, frame, k, p->slices, p->pattern), offset, &s);
        float vis = s.weight * slice_visibility(&s, p->weighting);
        sum += vis;
        b = v3_add(b, slice_bent(&s, vis, p->bent_halfway));
    }
    *ao = sum / (float)p->slices;
    float len = v3_length(b);
    if (bent)
        *bent = len > 0.0f ? ss_world_direction(g, v3_scale(b, 1.0f / len))
                           : ss_world_direction(g, ss_view_normal(g, x, y));
}

static void pixel_frame(const ss_gbuffer *g, ss_pixel_fn fn, const void *params, int frame, float *ao,
                        float *const *bent)
{
#pragma omp parallel for schedule(dynamic, 4)
    for (int y = 0; y < g->height; ++y)
        for (int x = 0; x < g->width; ++x) {
            long i = (long)y * g->width + x;
            float a = 0.0f;
            vec3 b = v3(0.0f, 0.0f, 0.0f);
            if (g->mask[i] != 0.0f)
                fn(g, params, frame, x, y, &a, bent ? &b : NULL);
            ao[i] = a;
            if (bent) {
                bent[0][i] = b.x;
                bent[1][i] = b.y;
                bent[2][i] = b.z;
            }
        }
}

/* The depth bounds of every pixel are worked out once per frame, not per
 * sample (ss_depth_bounds_planes; the same bits either way); without memory
 * for them, per sample. */
void ss_pixel_frame(const ss_gbuffer *g, ss_pixel_fn fn, const void *params, int frame, float *ao, float *const *bent)
{
    size_t n = (size_t)g->width * g->height;
    float *bounds = g->depth_lo ? NULL : malloc(2 * n * sizeof *bounds);
    ss_gbuffer with_bounds = *g;
    if (bounds) {
        ss_depth_bounds_planes(g, bounds, bounds + n);
        with_bounds.depth_lo = bounds, with_bounds.depth_hi = bounds + n;
    }
    pixel_frame(&with_bounds, fn, params, frame, ao, bent);
    free(bounds);
}

typedef struct {
    ss_pixel_fn fn;
    const void *params;
    int bent;
} frame_job;

/* Adapts ss_pixel_frame to the shared frame loop: plane 0 AO, planes 1-3 the bent normal. */
static void frame_planes(const ss_gbuffer *g, const void *params, int frame, float *const *planes)
{
    const frame_job *job = params;
    ss_pixel_frame(g, job->fn, job->params, frame, planes[0], job->bent ? planes + 1 : NULL);
}

int ss_pixel_render(const ss_gbuffer *g, ss_pixel_fn fn, const void *params, int frames, int denoise, float *ao,
                    float *const *bent)
{
    frame_job job = {fn, params, bent != NULL};
    float *out[4] = {ao, job.bent ? bent[0] : NULL, job.bent ? bent[1] : NULL, job.bent ? bent[2] : NULL};
    if (gtao_denoised_frames(g, frame_planes, &job, frames, denoise, job.bent ? 4 : 1, out) != 0)
        return -1;
    if (job.bent)
        gtao_normalize_directions(g, bent);
    return 0;
}

void gtao_frame(const ss_gbuffer *g, const gtao_params *p, int frame, float *ao, float *const *bent)
{
    ss_pixel_frame(g, pixel_gtao, p, frame, ao, bent);
}

int gtao_render(const ss_gbuffer *g, const gtao_params *p, float *ao, float *const *bent)
{
    return ss_pixel_render(g, pixel_gtao, p, p->frames, p->denoise, ao, bent);
}
