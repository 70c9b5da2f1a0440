/* GTAO with the "Possible Pitfall" integrand; see gtao_sin_n_pitfall.h. */
#include "gtao/gtao_sin_n_pitfall.h"

#include <math.h>

#include "gtao/gtao_denoiser.h"

float gtao_integrate_arc_pitfall(float h1, float h2, float n)
{
    return fabsf(sinf(n)) * (sinf(h2 - n) - sinf(h1 - n));
}

static float pixel_pitfall(const ss_gbuffer *g, const gtao_params *p, int frame, int x, int y)
{
    float sum = 0.0f, offset = gtao_step_offset(x, y, frame, p->pattern);
    for (int k = 0; k < p->slices; ++k) {
        gtao_slice s;
        gtao_search_slice(g, x, y, p, gtao_slice_angle(x, y, frame, k, p->slices, p->pattern), offset, &s);
        sum += s.weight * (s.n_len * gtao_integrate_arc_pitfall(s.h1, s.h2, s.n));
    }
    return sum / (float)p->slices;
}

void gtao_pitfall_frame(const ss_gbuffer *g, const gtao_params *p, int frame, float *ao)
{
#pragma omp parallel for schedule(dynamic, 4)
    for (int y = 0; y < g->height; ++y)
        for (int x = 0; x < g->width; ++x) {
            long i = (long)y * g->width + x;
            ao[i] = g->mask[i] == 0.0f ? 0.0f : pixel_pitfall(g, p, frame, x, y);
        }
}

static void frame_planes(const ss_gbuffer *g, const void *params, int frame, float *const *planes)
{
    gtao_pitfall_frame(g, params, frame, planes[0]);
}

int gtao_pitfall_render(const ss_gbuffer *g, const gtao_params *p, float *ao)
{
    return gtao_denoised_frames(g, frame_planes, p, p->frames, p->denoise, 1, &ao);
}
