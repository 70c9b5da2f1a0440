/* The average of the two horizon vectors as the bent normal; see
 * gtao_bent_horizons.h. */
#include "gtao/gtao_bent_horizons.h"

#include <math.h>

void gtao_bent_horizon_average(float h1, float h2, float *bv, float *bs)
{
    *bv = 0.5f * (cosf(h1) + cosf(h2));
    *bs = 0.5f * (sinf(h1) + sinf(h2));
}

static vec3 pixel_bent(const ss_gbuffer *g, const gtao_params *p, int frame, int x, int y)
{
    vec3 b = v3(0.0f, 0.0f, 0.0f);
    float offset = gtao_step_offset(x, y, frame, p->pattern);
    for (int k = 0; k < p->slices; ++k) {
        gtao_slice s;
        float bv, bs;
        gtao_search_slice(g, x, y, p, gtao_slice_angle(x, y, frame, k, p->slices, p->pattern), offset, &s);
        gtao_bent_horizon_average(s.h1, s.h2, &bv, &bs);
        b = v3_add(b, v3_add(v3_scale(s.v, s.weight * bv), v3_scale(s.side, s.weight * bs)));
    }
    float len = v3_length(b);
    /* every slice open: the sum is rounding noise */
    return len > 1e-4f * (float)p->slices ? ss_world_direction(g, v3_scale(b, 1.0f / len))
                                          : ss_world_direction(g, ss_view_normal(g, x, y));
}

void gtao_bent_horizons_frame(const ss_gbuffer *g, const gtao_params *p, int frame, float *const *bent)
{
#pragma omp parallel for schedule(dynamic, 4)
    for (int y = 0; y < g->height; ++y)
        for (int x = 0; x < g->width; ++x) {
            long i = (long)y * g->width + x;
            vec3 b = g->mask[i] != 0.0f ? pixel_bent(g, p, frame, x, y) : v3(0.0f, 0.0f, 0.0f);
            bent[0][i] = b.x;
            bent[1][i] = b.y;
            bent[2][i] = b.z;
        }
}
