/* Height-field AO reference after the GTAO talk's screen-space ray marcher
 * (seeds/001, "Methodology"); see heightfield_ao_integrator.h. */
#include "ao/heightfield_ao_integrator.h"

#include <math.h>
#include <stdlib.h>

#include "core/optics/heightfield_model.h"
#include "core/sampling/hemisphere_sampling.h"
#include "core/reference_schema.h"

enum { HF_V, HF_VUNIFORM, HF_QUANTITY_COUNT };
static const mc_quantity hf_quantities[HF_QUANTITY_COUNT] = {{CH_AO, 0}, {CH_AO_UNIFORM, 0}};


/* Camera-relative coordinates: (a, b, z) with z the depth along the axis and
 * the screen position x = (a / z / (tan aspect) + 1) W / 2, y = (1 - b / z / tan) H / 2. */
static vec3 to_camera(const camera_view *v, vec3 p)
{
    vec3 r = v3_sub(p, v->origin);
    return v3(v3_dot(r, v->right), v3_dot(r, v->up), v3_dot(r, v->forward));
}

static void to_screen(const camera_view *v, vec3 c, float *x, float *y)
{
    *x = (c.x / (c.z * v->tan_half_yfov * v->aspect) + 1.0f) * 0.5f * (float)v->width;
    *y = (1.0f - c.y / (c.z * v->tan_half_yfov)) * 0.5f * (float)v->height;
}

/* The unnormalised direction of the eye ray through screen point (x, y):
 * its component along the camera axis is 1. */
static vec3 eye_direction(const camera_view *v, float x, float y)
{
    float sx = (2.0f * x / (float)v->width - 1.0f) * v->tan_half_yfov * v->aspect;
    float sy = (1.0f - 2.0f * y / (float)v->height) * v->tan_half_yfov;
    return v3_add(v->forward, v3_add(v3_scale(v->right, sx), v3_scale(v->up, sy)));
}

/* Depth of pixel j's surface (its tangent plane) along the eye ray through
 * screen point (x, y), clamped to its neighbourhood's depths
 * (core/optics/heightfield_model.h). */
static float surface_depth(const heightfield_settings *hs, long j, float x, float y)
{
    const camera_view *v = &hs->gb->view;
    const surface_hit *h = &hs->gb->hits[j];
    vec3 w = eye_direction(v, x, y);
    float nw = v3_dot(h->ng, w);
    float depth = v3_dot(h->ng, v3_sub(h->p, v->origin)) / nw;
    if (!(fabsf(nw) >= HEIGHTFIELD_MIN_FACING * v3_length(w) && depth > 0.0f))
        depth = hs->depth[j];
    return fminf(fmaxf(depth, hs->depth_lo[j]), hs->depth_hi[j]);
}

/* The ray's end: where it reaches max_distance, or just short of the camera
 * plane, or far enough to leave any image (100 times the start's depth
 * beyond which the projection hardly moves: the march stops at the border). */
static float ray_end(const heightfield_settings *hs, vec3 c0, vec3 dc)
{
    float t = isfinite(hs->max_distance) ? hs->max_distance : 1e3f * fmaxf(c0.z, 1e-3f);
    float near = 1e-3f * c0.z;
    if (dc.z < 0.0f)
        t = fminf(t, (near - c0.z) / dc.z);
    return t;
}

/* Clips the screen segment s0 + u (s1 - s0), u in [0, 1], to the image. */
static float clip_to_image(float x0, float y0, float x1, float y1, float w, float h)
{
    float u = 1.0f;
    if (x1 < 0.0f) u = fminf(u, x0 / (x0 - x1));
    if (x1 > w) u = fminf(u, (w - x0) / (x1 - x0));
    if (y1 < 0.0f) u = fminf(u, y0 / (y0 - y1));
    if (y1 > h) u = fminf(u, (h - y0) / (y1 - y0));
    return fmaxf(u, 0.0f);
}

/* Whether the ray's point at screen parameter u (segment s0 -> s1, depths
 * z0 -> z1) lies behind the height field. */
typedef struct {
    float x0, y0, x1, y1, z0, z1;
    int x_start, y_start;
} screen_segment;

static int behind_at(const heightfield_settings *hs, const screen_segment *sg, float u)
{
    const camera_view *v = &hs->gb->view;
    float x = sg->x0 + u * (sg->x1 - sg->x0), y = sg->y0 + u * (sg->y1 - sg->y0);
    int px = (int)floorf(x), py = (int)floorf(y);
    if (px < 0 || py < 0 || px >= v->width || py >= v->height || (px == sg->x_start && py == sg->y_start))
        return 0; /* nothing known off the image; the start's own plane cannot occlude an outgoing ray */
    long j = (long)py * v->width + px;
    /* Perspective-correct depth: 1/z is linear in screen space. */
    float a = u * sg->z0 / ((1.0f - u) * sg->z1 + u * sg->z0);
    float z = sg->z0 + a * (sg->z1 - sg->z0);
    return hs->gb->mask[j] && z > surface_depth(hs, j, x, y) * (1.0f + 1e-5f);
}

static float ray_depth(const screen_segment *sg, float u)
{
    float a = u * sg->z0 / ((1.0f - u) * sg->z1 + u * sg->z0);
    return sg->z0 + a * (sg->z1 - sg->z0);
}

/* How far the ray's point at screen parameter u lies behind the surface of
 * the pixel under it, in depth (> 0: behind); 0 when no surface counts there
 * (off the image, background, the start's own pixel). */
static int depth_behind(const heightfield_settings *hs, const screen_segment *sg, float u, float *h)
{
    const camera_view *v = &hs->gb->view;
    float x = sg->x0 + u * (sg->x1 - sg->x0), y = sg->y0 + u * (sg->y1 - sg->y0);
    int px = (int)floorf(x), py = (int)floorf(y);
    if (px < 0 || py < 0 || px >= v->width || py >= v->height || (px == sg->x_start && py == sg->y_start))
        return 0;
    long j = (long)py * v->width + px;
    if (!hs->gb->mask[j])
        return 0;
    *h = ray_depth(sg, u) - surface_depth(hs, j, x, y) * (1.0f + 1e-5f);
    return 1;
}

/* Whether the ray enters the slab of the cell it crosses between screen
 * parameters ua < ub (one pixel): some u with 0 < h(u) < T, h the depth
 * behind the surface. 1/depth is linear in u for the ray, and for the
 * surface where it is the pixel's unclamped tangent plane, so h = 1/a - 1/b
 * (a, b linear) has at most one extremum, where b/a = sqrt(b'/a'); the range
 * of h over the cell is spanned by the ends and that point, and it meets
 * (0, T) iff its maximum is > 0 and its minimum < T. (Where the depth is
 * clamped, the extremum is located from the end values.) */
static int in_slab(const heightfield_settings *hs, const screen_segment *sg, float ua, float ub)
{
    float ha, hb;
    if (!depth_behind(hs, sg, ua, &ha) || !depth_behind(hs, sg, ub, &hb))
        return 0; /* both ends lie in one covered pixel, or the cell does not count */
    float lo = fminf(ha, hb), hi = fmaxf(ha, hb);
    float za = ray_depth(sg, ua), zb = ray_depth(sg, ub);
    float a0 = 1.0f / za, a1 = (1.0f / zb - a0) / (ub - ua);
    float b0 = 1.0f / (za - ha), b1 = (1.0f / (zb - hb) - b0) / (ub - ua);
    if (a1 * b1 > 0.0f) {
        float k = sqrtf(b1 / a1), s = (k * a0 - b0) / (b1 - k * a1), hc;
        if (s > 0.0f && s < ub - ua && depth_behind(hs, sg, ua + s, &hc)) {
            lo = fminf(lo, hc);
            hi = fmaxf(hi, hc);
        }
    }
    return hi > 0.0f && lo < hs->thickness;
}

/* Distance along the screen path (origin o, unit direction d) to the next
 * multiple of `size` beyond cell c on one axis. */
static float boundary(float o, float d, int c, int size)
{
    if (d > 0.0f)
        return ((float)((c / size + 1) * size) - o) / d;
    if (d < 0.0f)
        return ((float)(c / size * size) - o) / d;
    return INFINITY;
}

/* The screen path of the ray crosses pixel cells; in each, the ray is behind
 * the cell's plane on at most one side of a single point (the ray and the
 * plane are both straight), so testing the ray just inside both ends of every
 * cell it crosses decides exactly whether it passes behind the height field.
 * Tiles (32x32, then 8x8) whose nearest surface is farther than the ray's
 * depth through them (the ray's depth is monotonic) are crossed in one step. */
/* The nearest the surface of pixel j comes to the camera: its plane's depth
 * is extreme at the cell's corners (1/depth is linear across it). */
const int heightfield_tile_sizes[HEIGHTFIELD_LEVELS] = {32, 8};

static float cell_min_depth(const heightfield_settings *hs, int x, int y)
{
    long j = (long)y * hs->gb->width + x;
    float m = hs->depth[j];
    for (int k = 0; k < 4; ++k)
        m = fminf(m, surface_depth(hs, j, (float)(x + (k & 1)), (float)(y + (k >> 1))));
    return m;
}

static int covered(const gbuffer *gb, int x, int y)
{
    return x >= 0 && y >= 0 && x < gb->width && y < gb->height && gb->mask[(size_t)y * gb->width + x];
}

int heightfield_settings_init(heightfield_settings *hs, const gbuffer *gb, float max_distance)
{
    size_t n = (size_t)gb->width * (size_t)gb->height;
    hs->gb = gb;
    hs->max_distance = max_distance;
    hs->thickness = INFINITY;
    int tiles_y[HEIGHTFIELD_LEVELS], ok = 1;
    hs->depth = malloc(sizeof *hs->depth * n);
    hs->depth_lo = malloc(sizeof *hs->depth_lo * n);
    hs->depth_hi = malloc(sizeof *hs->depth_hi * n);
    ok &= hs->depth_lo && hs->depth_hi;
    for (int level = 0; level < HEIGHTFIELD_LEVELS; ++level) {
        int size = heightfield_tile_sizes[level];
        hs->tiles_x[level] = (gb->width + size - 1) / size;
        tiles_y[level] = (gb->height + size - 1) / size;
        hs->tile_min[level] = malloc(sizeof(float) * (size_t)hs->tiles_x[level] * (size_t)tiles_y[level]);
        ok &= hs->tile_min[level] != NULL;
    }
    if (!hs->depth || !ok) {
        heightfield_settings_free(hs);
        return -1;
    }
    for (size_t i = 0; i < n; ++i)
        hs->depth[i] = gb->mask[i] ? camera_depth(&gb->view, gb->hits[i].p) : INFINITY;
    for (int y = 0; y < gb->height; ++y)
        for (int x = 0; x < gb->width; ++x) {
            size_t i = (size_t)y * gb->width + x;
            hs->depth_lo[i] = hs->depth_hi[i] = hs->depth[i];
            if (!gb->mask[i])
                continue;
            for (int k = 0; k < 9; ++k) {
                int ox = k % 3 - 1, oy = k / 3 - 1;
                float d;
                if (covered(gb, x + ox, y + oy))
                    d = hs->depth[(size_t)(y + oy) * gb->width + x + ox];
                else if (covered(gb, x - ox, y - oy)) /* the missing side mirrored */
                    d = 2.0f * hs->depth[i] - hs->depth[(size_t)(y - oy) * gb->width + x - ox];
                else
                    continue;
                hs->depth_lo[i] = fminf(hs->depth_lo[i], d);
                hs->depth_hi[i] = fmaxf(hs->depth_hi[i], d);
            }
        }
    for (int level = 0; level < HEIGHTFIELD_LEVELS; ++level)
        for (int t = 0; t < hs->tiles_x[level] * tiles_y[level]; ++t)
            hs->tile_min[level][t] = INFINITY;
    for (int y = 0; y < gb->height; ++y)
        for (int x = 0; x < gb->width; ++x) {
            if (!gb->mask[(size_t)y * gb->width + x])
                continue;
            float m = cell_min_depth(hs, x, y);
            for (int level = 0; level < HEIGHTFIELD_LEVELS; ++level) {
                int size = heightfield_tile_sizes[level];
                float *t = &hs->tile_min[level][(y / size) * hs->tiles_x[level] + x / size];
                *t = fminf(*t, m);
            }
        }
    return 0;
}

void heightfield_settings_free(heightfield_settings *hs)
{
    free(hs->depth);
    free(hs->depth_lo);
    free(hs->depth_hi);
    hs->depth = hs->depth_lo = hs->depth_hi = NULL;
    for (int level = 0; level < HEIGHTFIELD_LEVELS; ++level) {
        free(hs->tile_min[level]);
        hs->tile_min[level] = NULL;
    }
}

/* Whether the segment's start lies on the surface of the pixel it projects
 * to (to a ten-thousandth of its depth): a point of the G-buffer or a ray's
 * hit on a pixel's surface, whose own plane cannot occlude a ray leaving it
 * (the march skips that cell), not a point in front of it on the side wall
 * of a neighbour's column (heightfield_first_hit). */
static int on_own_surface(const heightfield_settings *hs, const screen_segment *sg)
{
    const camera_view *v = &hs->gb->view;
    if (sg->x_start < 0 || sg->y_start < 0 || sg->x_start >= v->width || sg->y_start >= v->height)
        return 1;
    long j = (long)sg->y_start * v->width + sg->x_start;
    return !hs->gb->mask[j] || sg->z0 >= surface_depth(hs, j, sg->x0, sg->y0) * (1.0f - 1e-4f);
}

/* The screen segment of the ray p + t d up to its end (ray_end). */
static screen_segment ray_segment(const heightfield_settings *hs, vec3 p, vec3 d)
{
    const camera_view *v = &hs->gb->view;
    vec3 c0 = to_camera(v, p), dc = v3(v3_dot(d, v->right), v3_dot(d, v->up), v3_dot(d, v->forward));
    vec3 c1 = v3_add(c0, v3_scale(dc, ray_end(hs, c0, dc)));
    screen_segment sg = {0, 0, 0, 0, c0.z, c1.z, 0, 0};
    to_screen(v, c0, &sg.x0, &sg.y0);
    to_screen(v, c1, &sg.x1, &sg.y1);
    sg.x_start = (int)floorf(sg.x0);
    sg.y_start = (int)floorf(sg.y0);
    if (!on_own_surface(hs, &sg))
        sg.x_start = sg.y_start = -1;
    return sg;
}

/* Where, between screen parameters ua (in front) and ub (behind), the ray
 * passes behind the height field of the cell it crosses there: bisection
 * to a thousandth of the interval (the hit's place on the pixel's surface;
 * visibility itself is decided by the ends). */
static float crossing(const heightfield_settings *hs, const screen_segment *sg, float ua, float ub)
{
    for (int k = 0; k < 10; ++k) {
        float um = 0.5f * (ua + ub);
        if (behind_at(hs, sg, um))
            ub = um;
        else
            ua = um;
    }
    return ub;
}

/* Marches the ray's screen segment (below); returns 1 when it passes behind
 * the height field (or enters a slab), with *u_hit the screen parameter of
 * a point of the cell where it does: the crossing (infinite thickness), or
 * the cell's entry (finite); *wall = 1 when the ray enters the cell already
 * behind its surface (it meets the side of that pixel's column), with
 * *u_before a point of the cell it comes from. */
static int march(const heightfield_settings *hs, const screen_segment *sg, float *u_hit, int *wall, float *u_before)
{
    const camera_view *v = &hs->gb->view;
    float length = hypotf(sg->x1 - sg->x0, sg->y1 - sg->y0);
    if (!(length > 0.0f))
        return 0;
    float u_end = clip_to_image(sg->x0, sg->y0, sg->x1, sg->y1, (float)v->width, (float)v->height);
    float dx = (sg->x1 - sg->x0) / length, dy = (sg->y1 - sg->y0) / length, tau_end = u_end * length;
    const float eps = 1e-3f;
    for (float tau = 0.0f; tau < tau_end;) {
        int cx = (int)floorf(sg->x0 + (tau + eps) * dx), cy = (int)floorf(sg->y0 + (tau + eps) * dy);
        if (cx < 0 || cy < 0 || cx >= v->width || cy >= v->height)
            break;
        int skipped = 0;
        for (int level = 0; level < HEIGHTFIELD_LEVELS && !skipped; ++level) {
            int size = heightfield_tile_sizes[level];
            float tile_exit = fminf(fminf(boundary(sg->x0, dx, cx, size), boundary(sg->y0, dy, cy, size)), tau_end);
            /* Nudged positions can round back onto the boundary just crossed
             * when the path is nearly parallel to it: always move on. */
            tile_exit = fmaxf(tile_exit, tau + eps);
            float tile_min = hs->tile_min[level][(cy / size) * hs->tiles_x[level] + cx / size];
            if (fmaxf(ray_depth(sg, tau / length), ray_depth(sg, tile_exit / length)) <= tile_min) {
                tau = tile_exit;
                skipped = 1;
            }
        }
        if (skipped)
            continue;
        float cell_exit = fmaxf(fminf(fminf(boundary(sg->x0, dx, cx, 1), boundary(sg->y0, dy, cy, 1)), tau_end), tau + eps);
        float ua = (tau + eps) / length, ub = (cell_exit - eps) / length;
        if (!isinf(hs->thickness)) {
            if (in_slab(hs, sg, ua, ub)) {
                *u_hit = ua;
                return 1;
            }
        } else if (tau > 0.0f && behind_at(hs, sg, ua)) {
            *u_hit = ua;
            *u_before = (tau - eps) / length;
            *wall = 1;
            return 1;
        } else if (behind_at(hs, sg, ub)) {
            *u_hit = crossing(hs, sg, ua, ub);
            *wall = 0;
            return 1;
        }
        tau = cell_exit;
    }
    return 0;
}

int heightfield_unoccluded(const heightfield_settings *hs, vec3 p, vec3 d)
{
    screen_segment sg = ray_segment(hs, p, d);
    float u, before;
    int wall;
    return !march(hs, &sg, &u, &wall, &before);
}

/* The side of a pixel's column the ray enters at screen parameter u from
 * the neighbouring cell at `before`: the plane through the eye and the
 * pixel edge crossed (x = X or y = Y on the screen), facing the ray. Moves
 * hit->p to the ray's point on it, nudged a thousandth of a pixel back
 * towards the ray, and sets both normals. */
static void column_side(const heightfield_settings *hs, const screen_segment *sg, float u, float before, vec3 p,
                        vec3 d, surface_hit *hit)
{
    const camera_view *v = &hs->gb->view;
    float x = sg->x0 + u * (sg->x1 - sg->x0), y = sg->y0 + u * (sg->y1 - sg->y0);
    float xb = sg->x0 + before * (sg->x1 - sg->x0), yb = sg->y0 + before * (sg->y1 - sg->y0);
    vec3 n;
    if (floorf(xb) != floorf(x)) {
        float edge = xb < x ? floorf(x) : floorf(x) + 1.0f;
        float slope = (2.0f * edge / (float)v->width - 1.0f) * v->tan_half_yfov * v->aspect;
        n = v3_sub(v->right, v3_scale(v->forward, slope));
    } else {
        float edge = yb < y ? floorf(y) : floorf(y) + 1.0f;
        n = v3_sub(v->up, v3_scale(v->forward, (1.0f - 2.0f * edge / (float)v->height) * v->tan_half_yfov));
    }
    n = v3_normalize(n);
    if (v3_dot(n, d) > 0.0f)
        n = v3_scale(n, -1.0f);
    float t = -v3_dot(n, v3_sub(p, v->origin)) / v3_dot(n, d);
    vec3 q = v3_add(p, v3_scale(d, fmaxf(t, 0.0f)));
    float pixel = 2.0f * v->tan_half_yfov * camera_depth(v, q) / (float)v->height;
    hit->p = v3_add(q, v3_scale(n, 1e-3f * pixel));
    hit->ng = hit->ns = n;
}

int heightfield_first_hit(const heightfield_settings *hs, vec3 p, vec3 d, surface_hit *hit)
{
    screen_segment sg = ray_segment(hs, p, d);
    float u, before;
    int wall;
    if (!march(hs, &sg, &u, &wall, &before))
        return 0;
    if (!hit)
        return 1;
    const camera_view *v = &hs->gb->view;
    float x = sg.x0 + u * (sg.x1 - sg.x0), y = sg.y0 + u * (sg.y1 - sg.y0);
    int px = (int)floorf(x), py = (int)floorf(y);
    px = px < 0 ? 0 : px >= v->width ? v->width - 1 : px;
    py = py < 0 ? 0 : py >= v->height ? v->height - 1 : py;
    long j = (long)py * v->width + px;
    *hit = hs->gb->hits[j];
    if (wall && isinf(hs->thickness))
        column_side(hs, &sg, u, before, p, d, hit);
    else
        hit->p = v3_add(v->origin, v3_scale(eye_direction(v, x, y), surface_depth(hs, j, x, y)));
    hit->t = v3_length(v3_sub(hit->p, p));
    return 1;
}

/* cos of the in-slice angle from v of the surface seen at pixel (x, y)'s
 * centre, seen from p: its offset d projected on the slice's plane (v, s).
 * -2 where nothing counts: off the image, background, beyond max_distance,
 * and on or below p's tangent plane (n . d <= 0), where the solid behind a
 * point (away from the eye, so down) cannot reach the hemisphere. */
static float centre_cos_angle(const heightfield_settings *hs, vec3 p, vec3 n, vec3 v, vec3 s, int x, int y)
{
    const camera_view *view = &hs->gb->view;
    if (x < 0 || y < 0 || x >= view->width || y >= view->height)
        return -2.0f;
    long j = (long)y * view->width + x;
    if (!hs->gb->mask[j])
        return -2.0f;
    vec3 d = v3_sub(hs->gb->hits[j].p, p);
    float length = v3_length(d), dv = v3_dot(d, v), ds = v3_dot(d, s);
    if (!(v3_dot(n, d) > 1e-4f * length) || !(ds > 0.0f) || !(length <= hs->max_distance))
        return -2.0f;
    return dv / sqrtf(dv * dv + ds * ds);
}

float heightfield_horizon(const heightfield_settings *hs, vec3 p, vec3 n, vec3 v, vec3 s)
{
    const camera_view *view = &hs->gb->view;
    vec3 c0 = to_camera(view, p), c1 = to_camera(view, v3_add(p, v3_scale(s, 1e-3f * c0.z)));
    float x0, y0, x1, y1;
    to_screen(view, c0, &x0, &y0);
    to_screen(view, c1, &x1, &y1);
    float length = hypotf(x1 - x0, y1 - y0), best = -1.0f;
    if (!(length > 0.0f) || !(c0.z > 0.0f))
        return (float)M_PI;
    float dx = (x1 - x0) / length, dy = (y1 - y0) / length;
    int steps = (int)(hypotf((float)view->width, (float)view->height) + 1.0f);
    for (int k = 1; k <= steps; ++k) {
        int x = (int)floorf(x0 + (float)k * dx), y = (int)floorf(y0 + (float)k * dy);
        if (x < 0 || y < 0 || x >= view->width || y >= view->height)
            break;
        float c = centre_cos_angle(hs, p, n, v, s, x, y);
        best = c > best ? c : best;
    }
    return best > -1.0f ? acosf(best < 1.0f ? best : 1.0f) : (float)M_PI;
}

/* Per sample one cosine- and one uniform-distributed direction from the same
 * 2-D point (as ao_integrator.c); a direction below the geometric surface is
 * blocked by the surface itself. */
static int hf_sample_batch(const integrator *self, const pixel_context *px, uint32_t first_index, int count,
                           float *values)
{
    const heightfield_settings *hs = self->settings;
    const sample_pair_seeds pair = sample_pair_seeds_for(px, 0);
    float u0[SAMPLE_BATCH], u1[SAMPLE_BATCH];
    vec3 local[2][SAMPLE_BATCH];
    sample_pair_points(&pair, first_index, count, u0, u1);
    sample_hemisphere_batch(u0, u1, count, local[0], local[1]);
    int marched = 0;
    for (int k = 0; k < count; ++k)
        for (int q = 0; q < 2; ++q) {
            vec3 d = frame_to_world(&px->shading, local[q][k]);
            int above = v3_dot(d, px->surface->ng) > 0.0f;
            values[(q == 0 ? HF_V : HF_VUNIFORM) * SAMPLE_BATCH + k] =
                above && heightfield_unoccluded(hs, px->surface->p, d) ? 1.0f : 0.0f;
            marched += above;
        }
    return marched;
}

integrator heightfield_ao_integrator(const heightfield_settings *settings)
{
    integrator it = {"heightfield-ao", HF_QUANTITY_COUNT, hf_quantities, NULL, hf_sample_batch, NULL, settings, 0};
    return it;
}
