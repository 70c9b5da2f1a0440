/* Alchemy ambient obscurance (McGuire et al. 2011); see alchemy_ao.h. */
#include "gtao/alchemy_ao.h"

#include <math.h>
#include <stdio.h>

#include "gtao/gtao.h"
#include "gtao/gtao_denoiser.h"

#define ALCHEMY_TURNS 7.0f
#define ALCHEMY_TWO_PI 6.28318531f

alchemy_params alchemy_default_params(float radius)
{
    return (alchemy_params){12, radius, 256.0f, 1.0f, 1.0f, 1e-4f, 1e-4f, 1, 0, 1};
}

/* max(0, v . n + z_C beta) / (v . v + epsilon) of one spiral sample. */
static float sample_term(const ss_gbuffer *g, const alchemy_params *p, vec3 c, vec3 n, float fx, float fy)
{
    if (!ss_covered(g, (int)floorf(fx), (int)floorf(fy)))
        return 0.0f;
    vec3 v = v3_sub(ss_sample_position(g, fx, fy), c);
    return ss_maxf(0.0f, v3_dot(v, n) + c.z * p->beta) / (v3_dot(v, v) + p->epsilon);
}

static float pixel_alchemy(const ss_gbuffer *g, const alchemy_params *p, int frame, int x, int y)
{
    vec3 c = ss_view_position(g, x, y), n = ss_view_normal(g, x, y);
    float r_px = ss_radius_px(g, x, y, p->radius, p->max_radius_px);
    float phi = 2.0f * gtao_slice_angle(x, y, frame, 0, 1, p->pattern), sum = 0.0f;
    for (int i = 0; i < p->samples; ++i) {
        float alpha = ((float)i + 0.5f) / (float)p->samples, theta = ALCHEMY_TWO_PI * ALCHEMY_TURNS * alpha + phi;
        sum += sample_term(g, p, c, n, (float)x + 0.5f + alpha * r_px * cosf(theta),
                           (float)y + 0.5f + alpha * r_px * sinf(theta));
    }
    float a = ss_maxf(0.0f, 1.0f - 2.0f * p->sigma / (float)p->samples * sum);
    return p->contrast == 1.0f ? a : powf(a, p->contrast);
}

void alchemy_frame(const ss_gbuffer *g, const alchemy_params *p, int frame, float *ao)
{
#pragma omp parallel for schedule(dynamic, 4)
    for (int y = 0; y < g->height; ++y)
        for (int x = 0; x < g->width; ++x) {
            long i = (long)y * g->width + x;
            ao[i] = g->mask[i] == 0.0f ? 0.0f : pixel_alchemy(g, p, frame, x, y);
        }
}

static void frame_planes(const ss_gbuffer *g, const void *params, int frame, float *const *planes)
{
    alchemy_frame(g, params, frame, planes[0]);
}

int alchemy_render(const ss_gbuffer *g, const alchemy_params *p, float *ao)
{
    return gtao_denoised_frames(g, frame_planes, p, p->frames, p->denoise, 1, &ao);
}

void alchemy_params_text(const alchemy_params *p, char *text, size_t size)
{
    snprintf(text, size,
             "samples=%d radius=%.9g max_radius_px=%.9g sigma=%.9g contrast=%.9g beta=%.9g epsilon=%.9g pattern=%d "
             "denoise=%d frames=%d",
             p->samples, p->radius, p->max_radius_px, p->sigma, p->contrast, p->beta, p->epsilon, p->pattern,
             p->denoise, p->frames);
}
