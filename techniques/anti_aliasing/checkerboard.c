/* The talk's checkerboard rendering (checkerboard.h). */
#include "anti_aliasing/checkerboard.h"

#include <stdlib.h>
#include <string.h>

#include "anti_aliasing/taa_sampling.h"

checkerboard_settings checkerboard_default_settings(void)
{
    checkerboard_settings s = {1, 1, fxaa_default_settings()};
    return s;
}

int checkerboard_renders(int frame, int i, int j) { return (i + j + frame % 2) % 2 == 0; }

static int clamp_index(int i, int n) { return i < 0 ? 0 : (i >= n ? n - 1 : i); }

/* The rendered corner nearest to the grid cell (a, b): its own corner when
 * inside the image, else the clamped one moved by one column if needed. */
static const float *cell_corner(const checkerboard_grid *g, const float *corners, int a, int b)
{
    int i = clamp_index(a + (b - g->k) + g->parity, g->width), j = clamp_index(a - (b - g->k), g->height);
    if ((i + j + g->parity) % 2 != 0)
        i += i > 0 ? -1 : 1;
    return corners + 3 * ((size_t)j * g->width + i);
}

int checkerboard_grid_build(const checkerboard_settings *s, const float *corners, int width, int height, int frame,
                            int threads, checkerboard_grid *g)
{
    memset(g, 0, sizeof *g);
    g->width = width, g->height = height, g->parity = frame % 2, g->k = height / 2 + 1;
    g->a_count = (width + height) / 2 + 1, g->b_count = (width + 1) / 2 + g->k + 1;
    size_t cells = (size_t)g->a_count * g->b_count;
    float *raw = malloc(3 * cells * sizeof(float));
    if (!raw)
        return -1;
    for (int b = 0; b < g->b_count; ++b)
        for (int a = 0; a < g->a_count; ++a)
            memcpy(raw + 3 * ((size_t)b * g->a_count + a), cell_corner(g, corners, a, b), 3 * sizeof(float));
    if (!s->fxaa) {
        g->rgb = raw;
        return 0;
    }
    g->rgb = malloc(3 * cells * sizeof(float));
    int rc = g->rgb ? fxaa_apply(&s->fx, raw, g->a_count, g->b_count, threads, g->rgb) : -1;
    free(raw);
    if (rc != 0)
        checkerboard_grid_free(g);
    return rc;
}

void checkerboard_grid_free(checkerboard_grid *g)
{
    free(g->rgb);
    g->rgb = NULL;
}

/* The grid's bilinear value at native image position (x, y). */
static void grid_fetch(const checkerboard_grid *g, double x, double y, float out[3])
{
    double a = 0.5 * (x + y - g->parity), b = 0.5 * (x - y - g->parity) + g->k;
    taa_bilinear(g->rgb, g->a_count, g->b_count, a + 0.5, b + 0.5, out); /* cell (a, b)'s sample is at (a, b) */
}

static int inside_box(const float *v, const float lo[3], const float hi[3])
{
    return v[0] >= lo[0] && v[0] <= hi[0] && v[1] >= lo[1] && v[1] <= hi[1] && v[2] >= lo[2] && v[2] <= hi[2];
}

static void resolve_pixel(const checkerboard_settings *s, const checkerboard_grid *prev, const float *current,
                          const float *motion, int i, int j, float *out)
{
    int w = prev ? prev->width : 0, h = prev ? prev->height : 0;
    size_t k = (size_t)j * w + i;
    double x = i + 0.5 + motion[2 * k], y = j + 0.5 + motion[2 * k + 1];
    float hist[3], lo[3], hi[3];
    int accept = taa_inside(w, h, x, y);
    if (accept) {
        grid_fetch(prev, x, y, hist);
        taa_neighbourhood_box(current, w, h, i, j, lo, hi);
        accept = !s->reject || inside_box(hist, lo, hi);
    }
    for (int c = 0; c < 3; ++c)
        out[3 * k + c] = accept ? 0.5f * current[3 * k + c] + 0.5f * hist[c] : current[3 * k + c];
}

int checkerboard_resolve(const checkerboard_settings *s, const checkerboard_grid *cur, const checkerboard_grid *prev,
                         const float *motion, int threads, float *out)
{
    int w = cur->width, h = cur->height;
    float *now = malloc(3 * sizeof(float) * (size_t)w * h);
    if (!now)
        return -1;
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            grid_fetch(cur, i + 0.5, j + 0.5, now + 3 * ((size_t)j * w + i));
    if (!prev)
        memcpy(out, now, 3 * sizeof(float) * (size_t)w * h);
    else {
#pragma omp parallel for schedule(static) num_threads(threads)
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i)
                resolve_pixel(s, prev, now, motion, i, j, out);
    }
    free(now);
    return 0;
}
