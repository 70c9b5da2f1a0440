/* HBAO after Bavoil, Sainz and Dimitrov 2008, as summarised by the GTAO talk
 * (seeds/001, "Method": "HBAO is mathematically equivalent to our method
 * (with uniform weighting) if no obscurance is used"); see hbao.h. The
 * elevations are measured from the plane perpendicular to the view vector,
 * so sin(elevation) is the cosine GTAO measures from the view vector: the
 * two methods share the samples but not the integration. As in GTAO each
 * direction is weighted by its rotation about the view vector per screen
 * angle (gtao_slice_weight). */
#include "gtao/hbao.h"

#include <math.h>
#include <stdio.h>

#include "gtao/gtao.h"
#include "gtao/gtao_denoiser.h"

/* Occlusion of one direction: from the tangent elevation up to the horizon. */
static float direction_occlusion(const ss_gbuffer *g, const hbao_params *p, int x, int y, float psi, float offset)
{
    vec3 pc = ss_view_position(g, x, y), n = ss_view_normal(g, x, y);
    vec3 v = v3_normalize(v3_neg(pc));
    float dx = cosf(psi), dy = sinf(psi);
    vec3 d3 = v3(dx, -dy, 0.0f);
    vec3 u = v3_normalize(v3_sub(d3, v3_scale(v, v3_dot(d3, v)))); /* horizontal unit of this direction */
    /* The tangent of the surface in the direction's vertical plane is n
     * rotated by 90 degrees in that plane: sin t = -(n.u) / |n in the plane|. */
    float nu = v3_dot(n, u), nv = v3_dot(n, v);
    float sin_t = -nu / sqrtf(nu * nu + nv * nv);
    float xy[GTAO_MAX_SAMPLES][2];
    float r_px = ss_radius_px(g, x, y, p->radius, p->max_radius_px);
    int count = ss_side_samples(g, x, y, dx, dy, r_px, p->steps, offset, xy);
    float sin_h = sin_t, occlusion = 0.0f;
    for (int i = 0; i < count; ++i) {
        vec3 d = v3_sub(ss_sample_position(g, xy[i][0], xy[i][1]), pc);
        float len = v3_length(d);
        if (len > p->radius)
            continue;
        float s = v3_dot(d, v) / len;
        if (s <= sin_h)
            continue;
        float w = p->attenuation ? 1.0f - (len * len) / (p->radius * p->radius) : 1.0f;
        occlusion += w * (s - sin_h);
        sin_h = s;
    }
    return gtao_slice_weight(v, psi) * occlusion;
}

void hbao_frame(const ss_gbuffer *g, const hbao_params *p, int frame, float *ao)
{
#pragma omp parallel for schedule(dynamic, 4)
    for (int y = 0; y < g->height; ++y)
        for (int x = 0; x < g->width; ++x) {
            long i = (long)y * g->width + x;
            if (g->mask[i] == 0.0f) {
                ao[i] = 0.0f;
                continue;
            }
            float offset = gtao_step_offset(x, y, frame, p->pattern), sum = 0.0f;
            for (int k = 0; k < p->directions; ++k)
                sum += direction_occlusion(g, p, x, y, 2.0f * gtao_slice_angle(x, y, frame, k, p->directions, p->pattern),
                                           offset);
            ao[i] = 1.0f - sum / (float)p->directions;
        }
}

static void frame_planes(const ss_gbuffer *g, const void *params, int frame, float *const *planes)
{
    hbao_frame(g, params, frame, planes[0]);
}

int hbao_render(const ss_gbuffer *g, const hbao_params *p, float *ao)
{
    return gtao_denoised_frames(g, frame_planes, p, p->frames, p->denoise, 1, &ao);
}

void hbao_params_text(const hbao_params *p, char *text, size_t size)
{
    snprintf(text, size, "directions=%d steps=%d radius=%.9g max_radius_px=%.9g attenuation=%d pattern=%d denoise=%d frames=%d",
             p->directions, p->steps, p->radius, p->max_radius_px, p->attenuation, p->pattern, p->denoise, p->frames);
}
