#include "realtime/screen_space.h"

#include <math.h>

#include "core/optics/heightfield_model.h"
#include "core/reference_schema.h"

int ss_gbuffer_from_image(const image *img, const char *what, ss_camera camera, ss_gbuffer *g, gt_error *e)
{
    static const char *const names[5] = {CH_DEPTH, CH_N_X, CH_N_Y, CH_N_Z, CH_MASK};
    const float *planes[5];
    for (int c = 0; c < 5; ++c)
        if (!(planes[c] = image_channel_data(img, names[c])))
            return gt_error_set(e, what, "missing channel %s (a G-buffer needs depth.Z, N.X, N.Y, N.Z and mask.A; "
                                         "'gtlab render gbuffer' writes them)", names[c]);
    g->width = img->width;
    g->height = img->height;
    g->depth = planes[0];
    for (int a = 0; a < 3; ++a)
        g->normal[a] = planes[1 + a];
    g->mask = planes[4];
    g->camera = camera;
    g->depth_lo = g->depth_hi = NULL;
    return 0;
}

vec3 ss_view_position(const ss_gbuffer *g, int x, int y)
{
    const ss_camera *c = &g->camera;
    float d = g->depth[(long)y * g->width + x];
    float sx = (2.0f * ((float)x + 0.5f) / (float)g->width - 1.0f) * c->tan_half_yfov * c->aspect;
    float sy = (1.0f - 2.0f * ((float)y + 0.5f) / (float)g->height) * c->tan_half_yfov;
    return v3(sx * d, sy * d, -d);
}

void ss_depth_bounds(const ss_gbuffer *g, int x, int y, float *lo, float *hi)
{
    const float centre = g->depth[(long)y * g->width + x];
    const float pz = -centre; /* as ss_view_position's z */
    float l = centre, h = centre;
    for (int k = 0; k < 9; ++k) {
        int ox = k % 3 - 1, oy = k / 3 - 1;
        float d;
        if (ss_covered(g, x + ox, y + oy))
            d = g->depth[(long)(y + oy) * g->width + x + ox];
        else if (ss_covered(g, x - ox, y - oy)) /* the missing side mirrored */
            d = -2.0f * pz - g->depth[(long)(y - oy) * g->width + x - ox];
        else
            continue;
        l = ss_minf(l, d);
        h = ss_maxf(h, d);
    }
    *lo = l;
    *hi = h;
}

void ss_depth_bounds_planes(const ss_gbuffer *g, float *lo, float *hi)
{
#pragma omp parallel for schedule(static)
    for (int y = 0; y < g->height; ++y)
        for (int x = 0; x < g->width; ++x) {
            long i = (long)y * g->width + x;
            ss_depth_bounds(g, x, y, &lo[i], &hi[i]);
        }
}

vec3 ss_sample_position(const ss_gbuffer *g, float fx, float fy)
{
    const ss_camera *c = &g->camera;
    int x = (int)floorf(fx), y = (int)floorf(fy);
    vec3 w = v3((2.0f * fx / (float)g->width - 1.0f) * c->tan_half_yfov * c->aspect,
                (1.0f - 2.0f * fy / (float)g->height) * c->tan_half_yfov, -1.0f);
    vec3 p = ss_view_position(g, x, y), n = ss_view_normal(g, x, y);
    float nw = v3_dot(n, w), depth = v3_dot(n, p) / nw;
    if (!(fabsf(nw) >= HEIGHTFIELD_MIN_FACING * v3_length(w) && depth > 0.0f))
        depth = -p.z;
    float lo, hi;
    if (g->depth_lo) {
        long i = (long)y * g->width + x;
        lo = g->depth_lo[i], hi = g->depth_hi[i];
    } else
        ss_depth_bounds(g, x, y, &lo, &hi);
    return v3_scale(w, ss_clampf(depth, lo, hi));
}

vec3 ss_view_normal(const ss_gbuffer *g, int x, int y)
{
    long i = (long)y * g->width + x;
    vec3 n = v3(g->normal[0][i], g->normal[1][i], g->normal[2][i]);
    const ss_camera *c = &g->camera;
    return v3(v3_dot(n, c->right), v3_dot(n, c->up), -v3_dot(n, c->forward));
}

vec3 ss_world_direction(const ss_gbuffer *g, vec3 v)
{
    const ss_camera *c = &g->camera;
    return v3_add(v3_add(v3_scale(c->right, v.x), v3_scale(c->up, v.y)), v3_scale(c->forward, -v.z));
}

float ss_pixels_per_unit(const ss_gbuffer *g, float depth)
{
    return 0.5f * (float)g->height / (g->camera.tan_half_yfov * depth);
}

float ss_radius_px(const ss_gbuffer *g, int x, int y, float radius, float max_px)
{
    return ss_minf(radius * ss_pixels_per_unit(g, g->depth[(long)y * g->width + x]), max_px);
}
