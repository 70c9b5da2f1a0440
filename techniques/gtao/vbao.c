/* Visibility-bitmask AO (Therrien, Levesque, Gilet 2023); see vbao.h. */
#include "gtao/vbao.h"

#include <math.h>
#include <stdio.h>


#define VBAO_PI 3.14159265358979f

vbao_params vbao_preset(int preset, float thickness, vbao_choices choices)
{
    int paper = choices == VBAO_PAPER;
    vbao_params p = {.sectors = VBAO_MAX_SECTORS, .thickness = thickness,
                     .counting = paper ? VBAO_COUNT_EQUAL : VBAO_COUNT_COSINE,
                     .backface = paper ? VBAO_BACK_VIEW : VBAO_BACK_DEPTH,
                     .rounding = paper ? VBAO_ROUND_PAPER : VBAO_ROUND_CENTRE};
    gtao_preset(gtao_preset_names[preset], &p.gtao);
    return p;
}

void vbao_params_text(const vbao_params *p, char *text, size_t size)
{
    static const char *const counting[] = {"cosine", "uniform", "equal"};
    char gtao[512];
    gtao_params_text(&p->gtao, gtao, sizeof gtao);
    snprintf(text, size, "sectors=%d thickness=%.9g counting=%s back=%s rounding=%s %s", p->sectors, p->thickness,
             counting[p->counting], p->backface == VBAO_BACK_DEPTH ? "depth" : "view",
             p->rounding == VBAO_ROUND_CENTRE ? "centre" : "paper", gtao);
}

/* Sectors k0 .. k1 - 1 of N. */
static uint32_t sector_run(int k0, int k1, int sectors)
{
    k0 = k0 < 0 ? 0 : k0;
    k1 = k1 > sectors ? sectors : k1;
    if (k1 <= k0)
        return 0u;
    uint32_t width = (uint32_t)(k1 - k0);
    return (width >= 32u ? 0xFFFFFFFFu : (1u << width) - 1u) << k0;
}

uint32_t vbao_sector_bits(float lo, float hi, int sectors, vbao_rounding rounding)
{
    float n = (float)sectors;
    lo = ss_clampf(lo, 0.0f, 1.0f);
    hi = ss_clampf(hi, 0.0f, 1.0f);
    if (rounding == VBAO_ROUND_CENTRE)
        return sector_run((int)ceilf(lo * n - 0.5f), (int)floorf(hi * n - 0.5f) + 1, sectors);
    int start = (int)(lo * n);
    return sector_run(start, start + (int)ceilf((hi - lo) * n), sectors);
}

static float acos_clamped(float c, int fast)
{
    c = ss_clampf(c, -1.0f, 1.0f);
    return fast ? gtao_fast_acos(c) : acosf(c);
}

/* The fraction x in [0, 1] of the normal's half-circle at the direction d
 * (from the centre, in the slice) on side `sign` (+1: side 2). */
static float half_circle_fraction(vec3 d, const gtao_slice *s, float sign, int fast)
{
    float theta = sign * acos_clamped(v3_dot(d, s->v) / v3_length(d), fast);
    return (theta - s->n) / VBAO_PI + 0.5f;
}

/* The back face's offset from the sample q per unit of thickness. */
static vec3 back_direction(const vbao_params *p, const gtao_slice *s, vec3 q)
{
    return p->backface == VBAO_BACK_DEPTH ? v3_scale(q, -1.0f / q.z) : v3_neg(s->v);
}

/* The fractions of the half-circle at the front and back faces of sample
 * xy, widening [*lo, *hi]; 0 if the sample is beyond the radius. */
static int sample_interval(const ss_gbuffer *g, vec3 pc, const vbao_params *p, const gtao_slice *s, float sign,
                           const float *xy, float *lo, float *hi)
{
    vec3 q = ss_sample_position(g, xy[0], xy[1]), d = v3_sub(q, pc), u = back_direction(p, s, q);
    if (!(v3_length(d) <= p->gtao.radius))
        return 0;
    vec3 back = isinf(p->thickness) ? u : v3_add(d, v3_scale(u, p->thickness));
    float front_x = half_circle_fraction(d, s, sign, p->gtao.fast_math);
    float back_x = half_circle_fraction(back, s, sign, p->gtao.fast_math);
    *lo = ss_minf(*lo, ss_minf(front_x, back_x));
    *hi = ss_maxf(*hi, ss_maxf(front_x, back_x));
    return 1;
}

/* Each sample occupies its own interval; in the exact mode (steps 0) the
 * samples come in pairs, the two ends of one pixel cell, and the pair
 * occupies the hull of its two intervals: the whole slab of the cell's
 * planar piece, so nothing leaks between the ends. */
static uint32_t side_bits(const ss_gbuffer *g, vec3 pc, const vbao_params *p, const gtao_slice *s, float sign,
                          const float (*xy)[2], int count)
{
    uint32_t bits = 0u;
    int group = p->gtao.steps == 0 ? 2 : 1;
    for (int i = 0; i < count; i += group) {
        float lo = INFINITY, hi = -INFINITY;
        int kept = 0;
        for (int j = i; j < i + group && j < count; ++j)
            kept |= sample_interval(g, pc, p, s, sign, xy[j], &lo, &hi);
        if (kept)
            bits |= vbao_sector_bits(lo, hi, p->sectors, p->rounding);
    }
    return bits;
}

uint32_t vbao_slice_bits(const ss_gbuffer *g, int x, int y, const vbao_params *p, const gtao_slice *s, float phi,
                         float offset)
{
    vec3 pc = ss_view_position(g, x, y);
    float dx = cosf(phi), dy = sinf(phi), xy[GTAO_MAX_SAMPLES][2];
    float r = ss_radius_px(g, x, y, p->gtao.radius, p->gtao.max_radius_px);
    int c2 = ss_side_samples(g, x, y, dx, dy, r, p->gtao.steps, offset, xy);
    uint32_t bits = side_bits(g, pc, p, s, 1.0f, (const float(*)[2])xy, c2);
    int c1 = ss_side_samples(g, x, y, -dx, -dy, r, p->gtao.steps, offset, xy);
    return bits | side_bits(g, pc, p, s, -1.0f, (const float(*)[2])xy, c1);
}

/* GTAO's inner integrals from the view vector (angle 0) to theta, signed so
 * that the integral over [a, b] is F(b) - F(a) on either side of v. */
static float cumulative_visibility(float theta, const gtao_slice *s, vbao_counting counting)
{
    float side = theta >= 0.0f ? 1.0f : -1.0f;
    float h1 = ss_minf(theta, 0.0f), h2 = ss_maxf(theta, 0.0f);
    if (counting == VBAO_COUNT_UNIFORM)
        return side * 0.5f * gtao_integrate_arc_uniform(h1, h2);
    return side * s->n_len * gtao_integrate_arc_cosine(h1, h2, s->n);
}

static void cumulative_bent(float theta, const gtao_slice *s, float *bv, float *bs)
{
    float side = theta >= 0.0f ? 1.0f : -1.0f;
    gtao_integrate_arc_bent(ss_minf(theta, 0.0f), ss_maxf(theta, 0.0f), s->n, bv, bs);
    *bv *= side * s->n_len;
    *bs *= side * s->n_len;
}

/* The free run of sectors k0 .. k1 - 1: its visibility, and its bent direction added to *bent. */
static float free_run(int k0, int k1, const gtao_slice *s, const vbao_params *p, vec3 *bent)
{
    if (p->counting == VBAO_COUNT_EQUAL && !bent)
        return (float)(k1 - k0) / (float)p->sectors;
    float a = s->n + VBAO_PI * ((float)k0 / (float)p->sectors - 0.5f);
    float b = s->n + VBAO_PI * ((float)k1 / (float)p->sectors - 0.5f);
    if (bent) {
        float va, sa, vb, sb;
        cumulative_bent(a, s, &va, &sa);
        cumulative_bent(b, s, &vb, &sb);
        *bent = v3_add(*bent, v3_add(v3_scale(s->v, vb - va), v3_scale(s->side, sb - sa)));
    }
    if (p->counting == VBAO_COUNT_EQUAL)
        return (float)(k1 - k0) / (float)p->sectors;
    return cumulative_visibility(b, s, p->counting) - cumulative_visibility(a, s, p->counting);
}

float vbao_slice_visibility(uint32_t occupied, const gtao_slice *s, const vbao_params *p, vec3 *bent)
{
    float sum = 0.0f;
    for (int k = 0; k < p->sectors;) {
        if (occupied >> k & 1u) {
            ++k;
            continue;
        }
        int end = k;
        while (end < p->sectors && !(occupied >> end & 1u))
            ++end;
        sum += free_run(k, end, s, p, bent);
        k = end;
    }
    return sum;
}

static void pixel_vbao(const ss_gbuffer *g, const void *params, int frame, int x, int y, float *ao, vec3 *bent)
{
    const vbao_params *p = params;
    float sum = 0.0f, offset = gtao_step_offset(x, y, frame, p->gtao.pattern);
    vec3 b = v3(0.0f, 0.0f, 0.0f);
    for (int k = 0; k < p->gtao.slices; ++k) {
        gtao_slice s;
        float phi = gtao_slice_angle(x, y, frame, k, p->gtao.slices, p->gtao.pattern);
        gtao_slice_geometry(g, x, y, phi, p->gtao.fast_math, &s);
        vec3 sb = v3(0.0f, 0.0f, 0.0f);
        sum += s.weight * vbao_slice_visibility(vbao_slice_bits(g, x, y, p, &s, phi, offset), &s, p, bent ? &sb : NULL);
        b = v3_add(b, v3_scale(sb, s.weight));
    }
    *ao = sum / (float)p->gtao.slices;
    if (!bent)
        return;
    float len = v3_length(b);
    *bent = len > 0.0f ? ss_world_direction(g, v3_scale(b, 1.0f / len)) : ss_world_direction(g, ss_view_normal(g, x, y));
}

void vbao_frame(const ss_gbuffer *g, const vbao_params *p, int frame, float *ao, float *const *bent)
{
    ss_pixel_frame(g, pixel_vbao, p, frame, ao, bent);
}

int vbao_render(const ss_gbuffer *g, const vbao_params *p, float *ao, float *const *bent)
{
    return ss_pixel_render(g, pixel_vbao, p, p->gtao.frames, p->gtao.denoise, ao, bent);
}
