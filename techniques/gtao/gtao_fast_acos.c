/* The talk's fast arc cosine with free coefficients and GTAO's slice
 * visibility replayed from cached cosines; see gtao_fast_acos.h. */
#include "gtao/gtao_fast_acos.h"

#include <math.h>

#define REPLAY_PI 3.14159265358979f

gtao_acos_poly gtao_acos_poly_talk(void)
{
    return (gtao_acos_poly){-0.156583f, 0.5f * REPLAY_PI, GTAO_FAST_SQRT_MAGIC};
}

/* The same operations in the same order as gtao_fast_acos, so the talk's
 * coefficients give its values bit for bit. */
float gtao_fast_acos_poly(float x, const gtao_acos_poly *c)
{
    float a = fabsf(x);
    float r = (c->slope * a + c->constant) * gtao_fast_sqrt_magic(1.0f - a, c->magic);
    return x >= 0.0f ? r : REPLAY_PI - r;
}

/* The highest sample cosine from v along one side (-2 when there is none). */
static float side_max_cos(const ss_gbuffer *g, int x, int y, vec3 pc, vec3 v, float dx, float dy, float r_px,
                          const gtao_params *p, float offset)
{
    float xy[GTAO_MAX_SAMPLES][2], best = -2.0f;
    int count = ss_side_samples(g, x, y, dx, dy, r_px, p->steps, offset, xy);
    for (int i = 0; i < count; ++i) {
        vec3 d = v3_sub(ss_sample_position(g, xy[i][0], xy[i][1]), pc);
        float len = v3_length(d);
        if (len > p->radius) /* no attenuation: beyond the radius a sample has no effect */
            continue;
        float c = v3_dot(d, v) / len;
        best = c > best ? c : best;
    }
    return best;
}

void gtao_slice_cosines_at(const ss_gbuffer *g, int x, int y, const gtao_params *p, float phi, float offset,
                           gtao_slice_cosines *out)
{
    gtao_params exact = *p;
    exact.fast_math = 0;
    gtao_slice s;
    gtao_search_slice(g, x, y, &exact, phi, offset, &s);
    /* The projected normal as gtao_search_slice forms it. */
    vec3 pc = ss_view_position(g, x, y), n = ss_view_normal(g, x, y);
    vec3 axis = v3_cross(s.side, s.v);
    vec3 np = v3_sub(n, v3_scale(axis, v3_dot(n, axis)));
    out->weight = s.weight;
    out->n_len = s.n_len;
    out->cos_n = s.n_len > 0.0f ? v3_dot(np, s.v) / s.n_len : 1.0f;
    out->n_sign = v3_dot(np, s.side) < 0.0f ? -1.0f : 1.0f;
    float r = ss_radius_px(g, x, y, p->radius, p->max_radius_px), dx = cosf(phi), dy = sinf(phi);
    out->max_cos[1] = side_max_cos(g, x, y, pc, s.v, dx, dy, r, p, offset);
    out->max_cos[0] = side_max_cos(g, x, y, pc, s.v, -dx, -dy, r, p, offset);
}

static float arc_cosine(float c, const gtao_acos_poly *poly)
{
    c = ss_minf(ss_maxf(c, -1.0f), 1.0f);
    return poly ? gtao_fast_acos_poly(c, poly) : acosf(c);
}

float gtao_replay_slice(const gtao_slice_cosines *s, const gtao_acos_poly *c)
{
    float n_angle = arc_cosine(s->cos_n, c);
    float n = s->n_sign < 0.0f ? -n_angle : n_angle;
    float sin_n = sinf(n);
    /* Each side's horizon starts at its hemisphere limit (gtao.c, side_horizon_cos). */
    float c1 = ss_maxf(sin_n, s->max_cos[0]), c2 = ss_maxf(-sin_n, s->max_cos[1]);
    float h1 = -arc_cosine(c1, c), h2 = arc_cosine(c2, c);
    h1 = n + ss_maxf(h1 - n, -0.5f * REPLAY_PI);
    h2 = n + ss_minf(h2 - n, 0.5f * REPLAY_PI);
    return s->weight * (s->n_len * gtao_integrate_arc_cosine(h1, h2, n));
}
