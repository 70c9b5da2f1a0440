/* The exact irradiance map: blocks of texels reduced to their radiance-
 * weighted first moments, then E(n) = sum over blocks of max(0, n . LM) per
 * channel. See the header for why this is exact off the horizon. */
#include "environment/irradiance_map.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>

/* The blocks of an environment: lm[(b * 3 + c) * 3 + axis] = sum_t L_t,c M_t,axis. */
typedef struct {
    int count;
    double *lm;
} moment_blocks;

/* The largest reduction <= wanted that divides both sizes. */
static int usable_reduction(const environment_equirect *env, int wanted)
{
    int r = wanted < 0 ? 0 : wanted;
    while (r > 0 && ((env->width % (1 << r)) || (env->height % (1 << r))))
        --r;
    return r;
}

static void add_texel(const environment_equirect *env, int i, int j, double *lm)
{
    double m[EQUIRECT_MONOMIALS];
    equirect_texel_moments(env->width, env->height, i, j, m);
    const float *L = env->rgb + ((size_t)j * env->width + i) * 3;
    for (int c = 0; c < 3; ++c) {
        lm[c * 3 + 0] += L[c] * m[MONO_X];
        lm[c * 3 + 1] += L[c] * m[MONO_Y];
        lm[c * 3 + 2] += L[c] * m[MONO_Z];
    }
}

static int blocks_build(const environment_equirect *env, int reduction, moment_blocks *b)
{
    int f = 1 << reduction, bw = env->width / f, bh = env->height / f;
    b->count = bw * bh;
    b->lm = calloc((size_t)b->count * 9, sizeof(double));
    if (!b->lm)
        return -1;
    for (int j = 0; j < env->height; ++j)
        for (int i = 0; i < env->width; ++i)
            add_texel(env, i, j, b->lm + (size_t)((j / f) * bw + i / f) * 9);
    return 0;
}

static void blocks_irradiance(const moment_blocks *b, const double n[3], double e[3])
{
    e[0] = e[1] = e[2] = 0.0;
    for (int k = 0; k < b->count; ++k) {
        const double *lm = b->lm + (size_t)k * 9;
        for (int c = 0; c < 3; ++c)
            e[c] += fmax(0.0, n[0] * lm[c * 3] + n[1] * lm[c * 3 + 1] + n[2] * lm[c * 3 + 2]);
    }
}

void irradiance_map_quadrature(const environment_equirect *env, int reduction, const double n[3], double e[3])
{
    moment_blocks b;
    e[0] = e[1] = e[2] = 0.0;
    if (blocks_build(env, usable_reduction(env, reduction), &b) != 0)
        return;
    blocks_irradiance(&b, n, e);
    free(b.lm);
}

int irradiance_map_build(irradiance_map *m, const environment_equirect *env, int width, int reduction, int threads)
{
    m->rgb = NULL;
    if (width < 2 || width % 2 || env->width < 1 || env->height < 1)
        return -1;
    m->width = width, m->height = width / 2, m->reduction = usable_reduction(env, reduction);
    moment_blocks b;
    if (blocks_build(env, m->reduction, &b) != 0)
        return -1;
    m->rgb = malloc((size_t)m->width * m->height * 3 * sizeof(float));
    if (!m->rgb) {
        free(b.lm);
        return -1;
    }
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads > 0 ? threads : 1)
    for (int j = 0; j < m->height; ++j)
        for (int i = 0; i < m->width; ++i) {
            double n[3], e[3];
            equirect_texel_direction(m->width, m->height, i, j, n);
            blocks_irradiance(&b, n, e);
            for (int c = 0; c < 3; ++c)
                m->rgb[((size_t)j * m->width + i) * 3 + c] = (float)e[c];
        }
    free(b.lm);
    return 0;
}

void irradiance_map_free(irradiance_map *m)
{
    free(m->rgb);
    m->rgb = NULL;
}

void irradiance_map_lookup(const irradiance_map *m, const double n[3], float e[3])
{
    equirect_bilinear(m->rgb, m->width, m->height, n, e);
}
