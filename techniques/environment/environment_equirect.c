/* Equirectangular geometry: directions, texel solid angles and moments in
 * closed form, the bilinear lookup and the solid-angle-weighted pyramid. See
 * the header for the convention. */
#include "environment/environment_equirect.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/vec3.h" /* M_PI */

void equirect_direction(double u, double v, double w[3])
{
    double phi = 2.0 * M_PI * (u - 0.5), theta = M_PI * v, s = sin(theta);
    w[0] = s * cos(phi);
    w[1] = cos(theta);
    w[2] = s * sin(phi);
}

void equirect_coordinates(const double w[3], double *u, double *v)
{
    *u = 0.5 + atan2(w[2], w[0]) / (2.0 * M_PI);
    if (*u >= 1.0)
        *u = 0.0;
    *v = acos(fmax(-1.0, fmin(1.0, w[1]))) / M_PI;
}

void equirect_texel_direction(int width, int height, int i, int j, double w[3])
{
    equirect_direction((i + 0.5) / width, (j + 0.5) / height, w);
}

double equirect_texel_solid_angle(int width, int height, int j)
{
    double c0 = cos(M_PI * j / height), c1 = cos(M_PI * (j + 1) / height);
    return 2.0 * M_PI / width * (c0 - c1);
}

/* The theta factors: \int f(theta) sin theta dtheta over the row, for
 * f = 1, cos, cos^2, sin^2, sin, sin cos. */
typedef struct {
    double one, c, cc, ss, s, sc;
} theta_parts;

static theta_parts theta_integrals(double t0, double t1)
{
    double c0 = cos(t0), c1 = cos(t1), s0 = sin(t0), s1 = sin(t1);
    theta_parts t;
    t.one = c0 - c1;
    t.c = 0.5 * (c0 * c0 - c1 * c1);
    t.cc = (c0 * c0 * c0 - c1 * c1 * c1) / 3.0;
    t.ss = t.one - t.cc;
    t.s = 0.5 * (t1 - t0) - 0.25 * (sin(2.0 * t1) - sin(2.0 * t0));
    t.sc = (s1 * s1 * s1 - s0 * s0 * s0) / 3.0;
    return t;
}

/* The phi factors: \int g(phi) dphi over the column, g = 1, sin, cos,
 * sin cos, sin^2, cos^2. */
typedef struct {
    double one, s, c, sc, ss, cc;
} phi_parts;

static phi_parts phi_integrals(double p0, double p1)
{
    double half = 0.5 * (p1 - p0), d2 = 0.25 * (sin(2.0 * p1) - sin(2.0 * p0));
    phi_parts p;
    p.one = p1 - p0;
    p.s = cos(p0) - cos(p1);
    p.c = sin(p1) - sin(p0);
    p.sc = 0.5 * (sin(p1) * sin(p1) - sin(p0) * sin(p0));
    p.ss = half - d2;
    p.cc = half + d2;
    return p;
}

void equirect_texel_moments(int width, int height, int i, int j, double m[EQUIRECT_MONOMIALS])
{
    theta_parts t = theta_integrals(M_PI * j / height, M_PI * (j + 1) / height);
    phi_parts p = phi_integrals(2.0 * M_PI * ((double)i / width - 0.5), 2.0 * M_PI * ((double)(i + 1) / width - 0.5));
    m[MONO_1] = t.one * p.one;
    m[MONO_X] = t.s * p.c;
    m[MONO_Y] = t.c * p.one;
    m[MONO_Z] = t.s * p.s;
    m[MONO_XY] = t.sc * p.c;
    m[MONO_YZ] = t.sc * p.s;
    m[MONO_XZ] = t.ss * p.sc;
    m[MONO_XX] = t.ss * p.cc;
    m[MONO_YY] = t.cc * p.one;
    m[MONO_ZZ] = t.ss * p.ss;
}

void equirect_bilinear(const float *rgb, int width, int height, const double w[3], float out[3])
{
    double u, v;
    equirect_coordinates(w, &u, &v);
    double x = u * width - 0.5, y = v * height - 0.5;
    double fx = floor(x), fy = floor(y);
    float tx = (float)(x - fx), ty = (float)(y - fy);
    int i0 = ((int)fx % width + width) % width, i1 = (i0 + 1) % width;
    int j0 = (int)fy, j1 = j0 + 1;
    if (j0 < 0)
        j0 = 0, ty = 0.0f;
    if (j1 > height - 1)
        j1 = height - 1;
    const float *a = rgb + ((size_t)j0 * width + i0) * 3, *b = rgb + ((size_t)j0 * width + i1) * 3;
    const float *c = rgb + ((size_t)j1 * width + i0) * 3, *d = rgb + ((size_t)j1 * width + i1) * 3;
    for (int k = 0; k < 3; ++k) {
        float top = a[k] + (b[k] - a[k]) * tx, bottom = c[k] + (d[k] - c[k]) * tx;
        out[k] = top + (bottom - top) * ty;
    }
}

/* Level k + 1 from level k: each texel the solid-angle-weighted mean of its 2 x 2 children. */
static void pyramid_reduce(const float *src, int width, int height, float *dst)
{
    int w2 = width / 2, h2 = height / 2;
    for (int j = 0; j < h2; ++j) {
        double o0 = equirect_texel_solid_angle(width, height, 2 * j);
        double o1 = equirect_texel_solid_angle(width, height, 2 * j + 1);
        for (int i = 0; i < w2; ++i)
            for (int k = 0; k < 3; ++k) {
                const float *r0 = src + ((size_t)(2 * j) * width + 2 * i) * 3 + k, *r1 = r0 + (size_t)width * 3;
                double sum = o0 * ((double)r0[0] + r0[3]) + o1 * ((double)r1[0] + r1[3]);
                dst[((size_t)j * w2 + i) * 3 + k] = (float)(sum / (2.0 * (o0 + o1)));
            }
    }
}

int equirect_pyramid_build(equirect_pyramid *p, const environment_equirect *env)
{
    memset(p, 0, sizeof *p);
    if (env->width < 1 || env->height < 1 || !env->rgb)
        return -1;
    size_t n = (size_t)env->width * env->height * 3;
    p->rgb[0] = malloc(n * sizeof(float));
    if (!p->rgb[0])
        return -1;
    memcpy(p->rgb[0], env->rgb, n * sizeof(float));
    p->width[0] = env->width, p->height[0] = env->height, p->levels = 1;
    while (p->levels < EQUIRECT_PYRAMID_MAX_LEVELS) {
        int k = p->levels - 1, w = p->width[k], h = p->height[k];
        if (w % 2 || h % 2 || w / 2 < EQUIRECT_PYRAMID_MIN_WIDTH)
            break;
        p->rgb[k + 1] = malloc((size_t)(w / 2) * (h / 2) * 3 * sizeof(float));
        if (!p->rgb[k + 1]) {
            equirect_pyramid_free(p);
            return -1;
        }
        pyramid_reduce(p->rgb[k], w, h, p->rgb[k + 1]);
        p->width[k + 1] = w / 2, p->height[k + 1] = h / 2, p->levels++;
    }
    return 0;
}

void equirect_pyramid_free(equirect_pyramid *p)
{
    for (int k = 0; k < EQUIRECT_PYRAMID_MAX_LEVELS; ++k)
        free(p->rgb[k]);
    memset(p, 0, sizeof *p);
}

void equirect_pyramid_lookup(const equirect_pyramid *p, const double w[3], double level, float out[3])
{
    level = fmax(0.0, fmin(level, p->levels - 1.0));
    int k = (int)floor(level);
    float a[3], b[3], t = (float)(level - k);
    equirect_bilinear(p->rgb[k], p->width[k], p->height[k], w, a);
    if (k + 1 >= p->levels || t == 0.0f) {
        out[0] = a[0], out[1] = a[1], out[2] = a[2];
        return;
    }
    equirect_bilinear(p->rgb[k + 1], p->width[k + 1], p->height[k + 1], w, b);
    for (int c = 0; c < 3; ++c)
        out[c] = a[c] + (b[c] - a[c]) * t;
}
