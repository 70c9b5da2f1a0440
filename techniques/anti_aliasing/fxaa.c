/* FXAA 3.11, quality preset 12 (fxaa.h). */
#include "anti_aliasing/fxaa.h"

#include <math.h>
#include <stdlib.h>

enum { SEARCH_STEPS = 5 };
static const double search_step[SEARCH_STEPS] = {1.0, 1.5, 2.0, 4.0, 12.0}; /* FXAA_QUALITY__P0..P4, preset 12 */

typedef struct {
    const float *rgb;
    const float *luma;
    int width, height;
} fxaa_image;

fxaa_settings fxaa_default_settings(void)
{
    fxaa_settings s = {0.75, 0.166, 0.0833};
    return s;
}

static double texel_luma(const fxaa_image *im, int i, int j)
{
    i = i < 0 ? 0 : (i >= im->width ? im->width - 1 : i);
    j = j < 0 ? 0 : (j >= im->height ? im->height - 1 : j);
    return im->luma[(size_t)j * im->width + i];
}

/* Bilinear luma at position (x, y) in pixels. */
static double luma_at(const fxaa_image *im, double x, double y)
{
    double fx = x - 0.5, fy = y - 0.5;
    int i = (int)floor(fx), j = (int)floor(fy);
    double a = fx - i, b = fy - j;
    return (1 - b) * ((1 - a) * texel_luma(im, i, j) + a * texel_luma(im, i + 1, j)) +
           b * ((1 - a) * texel_luma(im, i, j + 1) + a * texel_luma(im, i + 1, j + 1));
}

static void colour_at(const fxaa_image *im, double x, double y, float out[3])
{
    double fx = x - 0.5, fy = y - 0.5;
    int i = (int)floor(fx), j = (int)floor(fy);
    double a = fx - i, b = fy - j, w[4] = {(1 - a) * (1 - b), a * (1 - b), (1 - a) * b, a * b};
    int ci[4] = {i, i + 1, i, i + 1}, cj[4] = {j, j, j + 1, j + 1};
    for (int c = 0; c < 3; ++c) {
        double v = 0.0;
        for (int k = 0; k < 4; ++k) {
            int ii = ci[k] < 0 ? 0 : (ci[k] >= im->width ? im->width - 1 : ci[k]);
            int jj = cj[k] < 0 ? 0 : (cj[k] >= im->height ? im->height - 1 : cj[k]);
            v += w[k] * im->rgb[3 * ((size_t)jj * im->width + ii) + c];
        }
        out[c] = (float)v;
    }
}

/* The 3 x 3 neighbourhood's lumas, named as in Fxaa3_11.h (N = up). */
typedef struct {
    double m, n, s, e, w, nw, ne, sw, se;
} neighbourhood;

static neighbourhood gather(const fxaa_image *im, int i, int j)
{
    neighbourhood h = {texel_luma(im, i, j),         texel_luma(im, i, j - 1),     texel_luma(im, i, j + 1),
                       texel_luma(im, i + 1, j),     texel_luma(im, i - 1, j),     texel_luma(im, i - 1, j - 1),
                       texel_luma(im, i + 1, j - 1), texel_luma(im, i - 1, j + 1), texel_luma(im, i + 1, j + 1)};
    return h;
}

/* Whether the horizontal edge measure wins (edgeHorz >= edgeVert). */
static int horizontal_span(const neighbourhood *h)
{
    double horz = fabs(-2 * h->w + h->nw + h->sw) + 2 * fabs(-2 * h->m + h->n + h->s) + fabs(-2 * h->e + h->ne + h->se);
    double vert = fabs(-2 * h->s + h->sw + h->se) + 2 * fabs(-2 * h->m + h->w + h->e) + fabs(-2 * h->n + h->nw + h->ne);
    return horz >= vert;
}

/* The subpixel shift's least value: subpixH of Fxaa3_11.h. */
static double subpixel_shift(const neighbourhood *h, double range, double subpix)
{
    double a = 2 * (h->n + h->s + h->w + h->e) + h->nw + h->sw + h->ne + h->se;
    double c = fmin(1.0, fabs(a / 12.0 - h->m) / range);
    double f = (3.0 - 2.0 * c) * c * c;
    return f * f * subpix;
}

/* One end of the search: its position and luma relative to the edge's mean. */
typedef struct {
    double x, y, end;
    int done;
} search_end;

static void sample_end(const fxaa_image *im, search_end *p, double half_pair, double gradient_scaled)
{
    p->end = luma_at(im, p->x, p->y) - half_pair;
    p->done = fabs(p->end) >= gradient_scaled;
}

/* Walks both ends along the edge (ox, oy) with preset 12's steps: after each
 * check an end not yet done advances, and is sampled again, except after the
 * last step (Fxaa3_11.h's nested doneNP blocks). */
static void search_edge(const fxaa_image *im, search_end *n, search_end *p, double ox, double oy, double half_pair,
                        double gradient_scaled)
{
    sample_end(im, n, half_pair, gradient_scaled);
    sample_end(im, p, half_pair, gradient_scaled);
    for (int k = 1; k < SEARCH_STEPS; ++k) {
        if (!n->done)
            n->x -= ox * search_step[k], n->y -= oy * search_step[k];
        if (!p->done)
            p->x += ox * search_step[k], p->y += oy * search_step[k];
        if (k == SEARCH_STEPS - 1 || (n->done && p->done))
            break;
        if (!n->done)
            sample_end(im, n, half_pair, gradient_scaled);
        if (!p->done)
            sample_end(im, p, half_pair, gradient_scaled);
    }
}

static void fxaa_pixel(const fxaa_settings *s, const fxaa_image *im, int i, int j, float out[3])
{
    neighbourhood h = gather(im, i, j);
    double mx = fmax(fmax(h.n, h.w), fmax(h.e, fmax(h.s, h.m))), mn = fmin(fmin(h.n, h.w), fmin(h.e, fmin(h.s, h.m)));
    double range = mx - mn, x = i + 0.5, y = j + 0.5;
    if (range < fmax(s->edge_threshold_min, mx * s->edge_threshold)) {
        for (int c = 0; c < 3; ++c)
            out[c] = im->rgb[3 * ((size_t)j * im->width + i) + c];
        return;
    }
    int horz = horizontal_span(&h);
    double luma_n = horz ? h.n : h.w, luma_s = horz ? h.s : h.e;
    int pair_n = fabs(luma_n - h.m) >= fabs(luma_s - h.m);
    double gradient = fmax(fabs(luma_n - h.m), fabs(luma_s - h.m)), sign = pair_n ? -1.0 : 1.0;
    double half_pair = 0.5 * ((pair_n ? luma_n : luma_s) + h.m), ox = horz, oy = !horz;
    double bx = x + (horz ? 0.0 : 0.5 * sign), by = y + (horz ? 0.5 * sign : 0.0);
    search_end n = {bx - ox * search_step[0], by - oy * search_step[0], 0, 0};
    search_end p = {bx + ox * search_step[0], by + oy * search_step[0], 0, 0};
    search_edge(im, &n, &p, ox, oy, half_pair, gradient / 4.0);
    double dst_n = horz ? x - n.x : y - n.y, dst_p = horz ? p.x - x : p.y - y;
    int centre_below = h.m - half_pair < 0.0;
    int good = dst_n < dst_p ? (n.end < 0.0) != centre_below : (p.end < 0.0) != centre_below;
    double offset = good ? 0.5 - fmin(dst_n, dst_p) / (dst_n + dst_p) : 0.0;
    offset = fmax(offset, subpixel_shift(&h, range, s->subpix));
    colour_at(im, x + (horz ? 0.0 : offset * sign), y + (horz ? offset * sign : 0.0), out);
}

int fxaa_apply(const fxaa_settings *s, const float *rgb, int width, int height, int threads, float *out)
{
    float *luma = malloc(sizeof *luma * (size_t)width * (size_t)height);
    if (!luma)
        return -1;
    for (size_t k = 0; k < (size_t)width * height; ++k)
        luma[k] = 0.299f * rgb[3 * k] + 0.587f * rgb[3 * k + 1] + 0.114f * rgb[3 * k + 2];
    fxaa_image im = {rgb, luma, width, height};
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i)
            fxaa_pixel(s, &im, i, j, out + 3 * ((size_t)j * width + i));
    free(luma);
    return 0;
}
