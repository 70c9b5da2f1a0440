/* Half resolution and the MIN depth chain of the GTAO talk; see
 * gtao_depth_mip.h. */
#include "gtao/gtao_depth_mip.h"

#include <math.h>
#include <stdlib.h>

#define GTAO_PI 3.14159265358979f

static float texel(const ss_depth_mip *m, int level, int x, int y)
{
    if (x < 0 || y < 0 || x >= m->width[level] || y >= m->height[level])
        return INFINITY;
    return m->depth[level][(long)y * m->width[level] + x];
}

static void downsample(ss_depth_mip *m, int level)
{
    for (int y = 0; y < m->height[level]; ++y)
        for (int x = 0; x < m->width[level]; ++x) {
            float a = ss_minf(texel(m, level - 1, 2 * x, 2 * y), texel(m, level - 1, 2 * x + 1, 2 * y));
            float b = ss_minf(texel(m, level - 1, 2 * x, 2 * y + 1), texel(m, level - 1, 2 * x + 1, 2 * y + 1));
            m->depth[level][(long)y * m->width[level] + x] = ss_minf(a, b);
        }
}

int ss_depth_mip_build(const ss_gbuffer *g, int levels, ss_depth_mip *m)
{
    *m = (ss_depth_mip){.levels = levels};
    for (int l = 0; l < levels; ++l) {
        m->width[l] = l == 0 ? g->width : (m->width[l - 1] + 1) / 2;
        m->height[l] = l == 0 ? g->height : (m->height[l - 1] + 1) / 2;
        if (!(m->depth[l] = malloc(sizeof(float) * (size_t)m->width[l] * m->height[l]))) {
            ss_depth_mip_free(m);
            return -1;
        }
    }
    for (long i = 0; i < (long)g->width * g->height; ++i)
        m->depth[0][i] = g->mask[i] != 0.0f ? g->depth[i] : INFINITY;
    for (int l = 1; l < levels; ++l)
        downsample(m, l);
    return 0;
}

void ss_depth_mip_free(ss_depth_mip *m)
{
    for (int l = 0; l < SS_DEPTH_MIP_MAX_LEVELS; ++l) {
        free(m->depth[l]);
        m->depth[l] = NULL;
    }
}

int gtao_mip_level(float distance_px, int levels)
{
    float l = floorf(log2f(ss_maxf(distance_px, 1.0f)) - GTAO_MIP_SAMPLING_OFFSET);
    return (int)ss_clampf(l, 0.0f, (float)(levels - 1));
}

float gtao_fetch_depth(const ss_depth_mip *m, gtao_depth_fetch fetch, float fx, float fy, float distance_px)
{
    int level = fetch == GTAO_FETCH_POINT ? 0 : gtao_mip_level(distance_px, m->levels);
    float scale = 1.0f / (float)(1 << level), u = fx * scale, v = fy * scale;
    if (fetch != GTAO_FETCH_MIP_MIN)
        return texel(m, level, (int)floorf(u), (int)floorf(v));
    int x0 = (int)floorf(u - 0.5f), y0 = (int)floorf(v - 0.5f);
    return ss_minf(ss_minf(texel(m, level, x0, y0), texel(m, level, x0 + 1, y0)),
                   ss_minf(texel(m, level, x0, y0 + 1), texel(m, level, x0 + 1, y0 + 1)));
}

/* The view-space point on the eye ray through screen point (fx, fy) at depth d. */
static vec3 ray_point(const ss_gbuffer *g, float fx, float fy, float d)
{
    const ss_camera *c = &g->camera;
    return v3((2.0f * fx / (float)g->width - 1.0f) * c->tan_half_yfov * c->aspect * d,
              (1.0f - 2.0f * fy / (float)g->height) * c->tan_half_yfov * d, -d);
}

static float attenuation(float distance, const gtao_params *p)
{
    float fade = p->falloff * p->radius;
    if (fade <= 0.0f)
        return distance <= p->radius ? 1.0f : 0.0f;
    return ss_clampf((p->radius - distance) / fade, 0.0f, 1.0f);
}

/* The cosine of one side's horizon, samples at t = r (j + offset) / steps
 * along (dx, dy); `low` is the side's hemisphere limit. */
static float side_horizon_cos(const ss_gbuffer *g, const ss_depth_mip *m, gtao_depth_fetch fetch, int x, int y,
                              float dx, float dy, float r, float offset, float low, const gtao_params *p)
{
    vec3 pc = ss_view_position(g, x, y), v = v3_normalize(v3_neg(pc));
    float horizon = low;
    for (int j = 0; j < p->steps; ++j) {
        float t = r * ((float)j + offset) / (float)p->steps;
        float fx = (float)x + 0.5f + t * dx, fy = (float)y + 0.5f + t * dy;
        if (fx < 0.0f || fy < 0.0f || ((int)floorf(fx) == x && (int)floorf(fy) == y))
            continue;
        float depth = gtao_fetch_depth(m, fetch, fx, fy, t);
        if (!isfinite(depth))
            continue;
        vec3 d = v3_sub(ray_point(g, fx, fy, depth), pc);
        float len = v3_length(d);
        horizon = ss_maxf(horizon, low + attenuation(len, p) * (v3_dot(d, v) / len - low));
    }
    return horizon;
}

static float acos_of(float c, int fast)
{
    c = ss_clampf(c, -1.0f, 1.0f);
    return fast ? gtao_fast_acos(c) : acosf(c);
}

void gtao_mip_search_slice(const ss_gbuffer *g, const ss_depth_mip *m, gtao_depth_fetch fetch, int x, int y,
                           const gtao_params *p, float phi, float offset, gtao_slice *s)
{
    gtao_params geometry = *p;
    geometry.steps = 1; /* gtao_search_slice for the slice's frame and normal only */
    gtao_search_slice(g, x, y, &geometry, phi, offset, s);
    float dx = cosf(phi), dy = sinf(phi), sin_n = sinf(s->n);
    float r = ss_radius_px(g, x, y, p->radius, p->max_radius_px);
    float c2 = side_horizon_cos(g, m, fetch, x, y, dx, dy, r, offset, -sin_n, p);
    float c1 = side_horizon_cos(g, m, fetch, x, y, -dx, -dy, r, offset, sin_n, p);
    float h1 = -acos_of(c1, p->fast_math), h2 = acos_of(c2, p->fast_math);
    s->h1 = s->n + ss_maxf(h1 - s->n, -0.5f * GTAO_PI);
    s->h2 = s->n + ss_minf(h2 - s->n, 0.5f * GTAO_PI);
}

static float pixel_ao(const ss_gbuffer *g, const ss_depth_mip *m, gtao_depth_fetch fetch, const gtao_params *p,
                      int x, int y)
{
    float sum = 0.0f;
    for (int k = 0; k < p->slices; ++k) {
        gtao_slice s;
        gtao_mip_search_slice(g, m, fetch, x, y, p, gtao_slice_angle(x, y, 0, k, p->slices, 0), 0.5f, &s);
        sum += s.weight * s.n_len * gtao_integrate_arc_cosine(s.h1, s.h2, s.n);
    }
    return sum / (float)p->slices;
}

void gtao_mip_frame(const ss_gbuffer *g, const ss_depth_mip *m, gtao_depth_fetch fetch, const gtao_params *p,
                    float *ao)
{
#pragma omp parallel for schedule(dynamic, 4)
    for (int y = 0; y < g->height; ++y)
        for (int x = 0; x < g->width; ++x) {
            long i = (long)y * g->width + x;
            ao[i] = g->mask[i] != 0.0f ? pixel_ao(g, m, fetch, p, x, y) : 0.0f;
        }
}

/* The covered pixel of the 2x2 block at (2 hx, 2 hy) closest to the camera; -1 if none. */
static long closest_in_block(const ss_gbuffer *full, int hx, int hy)
{
    long best = -1;
    for (int k = 0; k < 4; ++k) {
        int x = 2 * hx + (k & 1), y = 2 * hy + (k >> 1);
        long i = (long)y * full->width + x;
        if (ss_covered(full, x, y) && (best < 0 || full->depth[i] < full->depth[best]))
            best = i;
    }
    return best;
}

int ss_half_resolution(const ss_gbuffer *full, ss_half_gbuffer *half)
{
    int w = (full->width + 1) / 2, h = (full->height + 1) / 2;
    size_t n = (size_t)w * h;
    if (!(half->storage = calloc(5 * n, sizeof(float))))
        return -1;
    float *depth = half->storage, *normal = depth + n, *mask = depth + 4 * n;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            long i = (long)y * w + x, j = closest_in_block(full, x, y);
            if (j < 0)
                continue;
            depth[i] = full->depth[j];
            for (int a = 0; a < 3; ++a)
                normal[(size_t)a * n + i] = full->normal[a][j];
            mask[i] = 1.0f;
        }
    half->g = (ss_gbuffer){w, h, depth, {normal, normal + n, normal + 2 * n}, mask, full->camera, NULL, NULL};
    return 0;
}

void ss_half_free(ss_half_gbuffer *half)
{
    free(half->storage);
    half->storage = NULL;
}

void ss_upsample_nearest(const ss_gbuffer *full, const ss_gbuffer *half, const float *half_values, float *out)
{
    for (int y = 0; y < full->height; ++y)
        for (int x = 0; x < full->width; ++x)
            out[(long)y * full->width + x] = half_values[(long)(y / 2) * half->width + x / 2];
}
