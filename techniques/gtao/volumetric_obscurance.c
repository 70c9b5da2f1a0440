/* Volumetric obscurance (Loos and Sloan 2010) with CryENGINE 3's 4 samples
 * (seeds/004, "SSAO improvements"); see volumetric_obscurance.h. */
#include "gtao/volumetric_obscurance.h"

#include <math.h>
#include <stdio.h>

#include "gtao/gtao.h"
#include "gtao/gtao_denoiser.h"

/* Line sample at disc point (ox, oy) (units of the sphere radius): the
 * length of the sphere's chord along the view axis that lies behind the
 * surface seen at that pixel, and the chord's full length. */
static void line_sample(const ss_gbuffer *g, int x, int y, float r_px, float radius, float ox, float oy, float *full,
                        float *occupied)
{
    float half = radius * sqrtf(ss_maxf(1.0f - ox * ox - oy * oy, 0.0f));
    int sx = (int)floorf((float)x + 0.5f + ox * r_px), sy = (int)floorf((float)y + 0.5f + oy * r_px);
    *full = 2.0f * half;
    if (!ss_covered(g, sx, sy)) {
        *occupied = 0.0f; /* nothing known there: empty */
        return;
    }
    float zc = g->depth[(long)y * g->width + x], zs = g->depth[(long)sy * g->width + sx];
    *occupied = ss_minf(ss_maxf(zc + half - ss_maxf(zs, zc - half), 0.0f), 2.0f * half);
}

void vo_frame(const ss_gbuffer *g, const vo_params *p, int frame, float *ao)
{
    /* Two opposite pairs, equal-area radii sqrt((k + 0.5) / 2), at right angles. */
    static const float radii[2] = {0.5f, 0.8660254f};
#pragma omp parallel for schedule(dynamic, 4)
    for (int y = 0; y < g->height; ++y)
        for (int x = 0; x < g->width; ++x) {
            long i = (long)y * g->width + x;
            if (g->mask[i] == 0.0f) {
                ao[i] = 0.0f;
                continue;
            }
            float r_px = ss_radius_px(g, x, y, p->radius, p->max_radius_px);
            float base = gtao_slice_angle(x, y, frame, 0, 1, p->pattern);
            float full = 0.0f, occupied = 0.0f;
            for (int k = 0; k < 4; ++k) {
                float a = base + 1.5707963f * (float)(k >> 1) + 3.1415927f * (float)(k & 1);
                float f, o;
                line_sample(g, x, y, r_px, p->radius, radii[k >> 1] * cosf(a), radii[k >> 1] * sinf(a), &f, &o);
                full += f;
                occupied += o;
            }
            ao[i] = ss_minf(1.0f, 2.0f * (1.0f - occupied / full));
        }
}

static void frame_planes(const ss_gbuffer *g, const void *params, int frame, float *const *planes)
{
    vo_frame(g, params, frame, planes[0]);
}

int vo_render(const ss_gbuffer *g, const vo_params *p, float *ao)
{
    return gtao_denoised_frames(g, frame_planes, p, p->frames, p->denoise, 1, &ao);
}

void vo_params_text(const vo_params *p, char *text, size_t size)
{
    snprintf(text, size, "samples=4 radius=%.9g max_radius_px=%.9g pattern=%d denoise=%d frames=%d", p->radius,
             p->max_radius_px, p->pattern, p->denoise, p->frames);
}
