/* CryENGINE 2's SSAO (Mittring 2007); see crytek_ssao.h. */
#include "gtao/crytek_ssao.h"

#include <math.h>
#include <stdio.h>

#include "gtao/gtao.h"
#include "gtao/gtao_denoiser.h"

#define CRYTEK_GOLDEN_ANGLE 2.39996323f

/* Pair k of `pairs`: a Fibonacci-sphere direction at the equal-volume radius. */
static vec3 pair_offset(int k, int pairs, float radius)
{
    float u = ((float)k + 0.5f) / (float)pairs;
    float z = 1.0f - 2.0f * u, ring = sqrtf(ss_maxf(0.0f, 1.0f - z * z)), a = CRYTEK_GOLDEN_ANGLE * (float)k;
    return v3_scale(v3(ring * cosf(a), ring * sinf(a), z), radius * cbrtf(u));
}

/* Screen point (pixels) of view-space point s: the inverse of
 * ss_view_position's mapping (realtime/screen_space.h). */
static void project(const ss_gbuffer *g, vec3 s, float *fx, float *fy)
{
    float d = -s.z, t = g->camera.tan_half_yfov;
    *fx = 0.5f * (s.x / (d * t * g->camera.aspect) + 1.0f) * (float)g->width;
    *fy = 0.5f * (1.0f - s.y / (d * t)) * (float)g->height;
}

/* 1 if the depth buffer occludes view-space point s within the range R. */
static int occluded(const ss_gbuffer *g, vec3 s, float range)
{
    float fx, fy;
    if (s.z >= 0.0f)
        return 0;
    project(g, s, &fx, &fy);
    if (!ss_covered(g, (int)floorf(fx), (int)floorf(fy)))
        return 0;
    float buffer = -ss_sample_position(g, fx, fy).z, depth = -s.z;
    return buffer < depth && buffer > depth - range;
}

static float pixel_crytek(const ss_gbuffer *g, const crytek_params *p, int frame, int x, int y)
{
    vec3 c = ss_view_position(g, x, y);
    float phi = 2.0f * gtao_slice_angle(x, y, frame, 0, 1, p->pattern), cp = cosf(phi), sp = sinf(phi);
    int pairs = p->samples / 2, hits = 0;
    for (int k = 0; k < pairs; ++k) {
        vec3 o = pair_offset(k, pairs, p->radius);
        o = v3(cp * o.x - sp * o.y, sp * o.x + cp * o.y, o.z);
        hits += occluded(g, v3_add(c, o), p->radius) + occluded(g, v3_sub(c, o), p->radius);
    }
    return ss_minf(1.0f, 2.0f * (1.0f - (float)hits / (float)(2 * pairs)));
}

void crytek_frame(const ss_gbuffer *g, const crytek_params *p, int frame, float *ao)
{
#pragma omp parallel for schedule(dynamic, 4)
    for (int y = 0; y < g->height; ++y)
        for (int x = 0; x < g->width; ++x) {
            long i = (long)y * g->width + x;
            ao[i] = g->mask[i] == 0.0f ? 0.0f : pixel_crytek(g, p, frame, x, y);
        }
}

static void frame_planes(const ss_gbuffer *g, const void *params, int frame, float *const *planes)
{
    crytek_frame(g, params, frame, planes[0]);
}

int crytek_render(const ss_gbuffer *g, const crytek_params *p, float *ao)
{
    return gtao_denoised_frames(g, frame_planes, p, p->frames, p->denoise, 1, &ao);
}

void crytek_params_text(const crytek_params *p, char *text, size_t size)
{
    snprintf(text, size, "samples=%d radius=%.9g pattern=%d denoise=%d frames=%d", p->samples, p->radius,
             p->pattern, p->denoise, p->frames);
}
