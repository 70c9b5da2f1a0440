#include "core/optics/environment_sampler.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The texel weights Y Omega_r, and I, their sum. */
static double *texel_weights(const environment_map *env, double *integral)
{
    size_t n = (size_t)env->width * (size_t)env->height;
    double *w = malloc(sizeof(double) * (n ? n : 1));
    if (!w)
        return NULL;
    *integral = 0.0;
    for (int r = 0; r < env->height; ++r)
        for (int c = 0; c < env->width; ++c) {
            size_t i = (size_t)r * env->width + c;
            w[i] = environment_luminance(env->rgb + 3 * i) * env->row_solid_angle[r];
            *integral += w[i];
        }
    return w;
}

int environment_sampler_init(environment_sampler *s, const environment_map *env, gt_error *e)
{
    memset(s, 0, sizeof *s);
    s->env = env;
    if (environment_map_is_constant(env)) {
        s->usable = environment_luminance(env->constant) > 0.0f;
        s->integral = 4.0 * M_PI * environment_luminance(env->constant);
        return 0;
    }
    double *w = texel_weights(env, &s->integral);
    size_t n = (size_t)env->width * (size_t)env->height;
    s->texel = malloc(sizeof *s->texel * n);
    s->row_cos = malloc(sizeof(double) * (size_t)(env->height + 1));
    if (!w || !s->texel || !s->row_cos || distribution_2d_init(&s->texels, w, env->height, env->width, e) != 0) {
        free(w);
        free(s->texel);
        free(s->row_cos);
        s->texel = NULL, s->row_cos = NULL;
        return gt_error_set(e, env->name, "out of memory for the environment sampler");
    }
    for (int r = 0; r <= env->height; ++r)
        s->row_cos[r] = cos(M_PI * r / env->height);
    s->usable = s->integral > 0.0;
    for (size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c)
            s->texel[i][c] = env->rgb[3 * i + (size_t)c] * env->intensity;
        s->texel[i][3] = s->usable ? (float)(environment_luminance(env->rgb + 3 * i) / s->integral) : 0.0f;
    }
    free(w);
    return 0;
}

void environment_sampler_free(environment_sampler *s)
{
    free(s->texel);
    free(s->row_cos);
    distribution_2d_free(&s->texels);
    memset(s, 0, sizeof *s);
}

/* phi and cos theta uniform over texel (row, column) at offsets t. */
static vec3 texel_direction(const environment_sampler *s, int row, int column, const double t[2])
{
    double cos_top = s->row_cos[row], cos_bottom = s->row_cos[row + 1];
    double cos_theta = cos_top + (cos_bottom - cos_top) * t[0];
    float sin_theta = (float)sqrt(fmax(0.0, 1.0 - cos_theta * cos_theta));
    float phi = (float)(2.0 * M_PI * ((column + t[1]) / s->env->width - 0.5));
    return v3(sin_theta * cosf(phi), (float)cos_theta, sin_theta * sinf(phi));
}

/* Uniform on the sphere: z = 1 - 2 u0, phi = 2 pi u1. */
static vec3 uniform_sphere(const float u[2])
{
    float z = 1.0f - 2.0f * u[0], r = sqrtf(fmaxf(0.0f, 1.0f - z * z)), phi = (float)(2.0 * M_PI) * u[1];
    return v3(r * cosf(phi), z, r * sinf(phi));
}

vec3 environment_sampler_sample(const environment_sampler *s, const float u[2], float *pdf)
{
    if (environment_map_is_constant(s->env)) {
        *pdf = (float)(0.25 / M_PI);
        return uniform_sphere(u);
    }
    int row, column;
    double t[2];
    const double uu[2] = {u[0], u[1]};
    distribution_2d_sample(&s->texels, uu, &row, &column, t);
    vec3 m = texel_direction(s, row, column, t);
    *pdf = s->texel[(size_t)row * s->env->width + column][3];
    return environment_map_to_world(s->env, m);
}

float environment_sampler_pdf(const environment_sampler *s, vec3 w)
{
    if (environment_map_is_constant(s->env))
        return s->usable ? (float)(0.25 / M_PI) : 0.0f;
    return s->texel[environment_texel_of(s->env, environment_world_to_map(s->env, w))][3];
}

void environment_sampler_lookup(const environment_sampler *s, vec3 w, float rgb[3], float *pdf)
{
    const environment_map *env = s->env;
    if (environment_map_is_constant(env)) {
        environment_map_radiance(env, w, rgb);
        *pdf = s->usable ? (float)(0.25 / M_PI) : 0.0f;
        return;
    }
    size_t t = (size_t)environment_texel_of(env, environment_world_to_map(env, w));
    for (int c = 0; c < 3; ++c)
        rgb[c] = s->texel[t][c];
    *pdf = s->texel[t][3];
}

/* ---- Many at once (see the header) ------------------------------------------ */

enum { CHUNK = 64 }; /* directions per pass: the prefetches in flight */

/* Pass 1 of n <= CHUNK draws: each row (offset t0, from the marginal,
 * small enough to stay cached) and its conditional's guide entry for u[1],
 * prefetched. */
static void draw_rows(const environment_sampler *s, int n, const float (*u)[2], int *row, double *t0,
                      const int **guide)
{
    const distribution_2d *d = &s->texels;
    for (int i = 0; i < n; ++i) {
        row[i] = distribution_1d_sample(&d->marginal, u[i][0], &t0[i]);
        guide[i] = distribution_1d_guide_of(&d->conditional[row[i]], u[i][1]);
        __builtin_prefetch(guide[i]);
    }
}

/* Draws ahead of the one being finished: their guide entries are read and
 * the CDF lines where their searches start prefetched this many draws
 * (a few hundred nanoseconds of arithmetic) before the search. */
enum { SEARCH_AHEAD = 6 };

/* n <= CHUNK draws of a sampled (non-constant) environment: the rows
 * (pass 1), then one loop that starts draw i + SEARCH_AHEAD's search (its
 * guide entry, its CDF line prefetched) while finishing draw i (the
 * search, the direction, its texel prefetched for the lookup). */
static void sample_chunk(const environment_sampler *s, int n, const float (*u)[2], vec3 *w)
{
    const distribution_1d *conditional = s->texels.conditional;
    int row[CHUNK], lo[CHUNK];
    double t0[CHUNK];
    const int *guide[CHUNK];
    draw_rows(s, n, u, row, t0, guide);
    for (int i = -SEARCH_AHEAD; i < n; ++i) {
        int j = i + SEARCH_AHEAD;
        if (j < n) {
            lo[j] = *guide[j];
            __builtin_prefetch(&conditional[row[j]].cdf[lo[j]]);
            __builtin_prefetch(&conditional[row[j]].cdf[lo[j] + 1]);
        }
        if (i < 0)
            continue;
        double t[2] = {t0[i], 0.0};
        int column = distribution_1d_sample_from(&conditional[row[i]], u[i][1], lo[i], &t[1]);
        __builtin_prefetch(s->texel[(size_t)row[i] * s->env->width + column]);
        w[i] = environment_map_to_world(s->env, texel_direction(s, row[i], column, t));
    }
}

void environment_sampler_sample_many(const environment_sampler *s, int n, const float (*u)[2], vec3 *w)
{
    float pdf;
    for (int first = 0; first < n; first += CHUNK) {
        int m = n - first < CHUNK ? n - first : CHUNK;
        if (environment_map_is_constant(s->env))
            for (int i = first; i < first + m; ++i)
                w[i] = environment_sampler_sample(s, u[i], &pdf);
        else
            sample_chunk(s, m, u + first, w + first);
    }
}

/* n <= CHUNK lookups in a map with texels: the indices (prefetched), then the loads. */
static void lookup_chunk(const environment_sampler *s, int n, const vec3 *w, float (*rgb)[3], float *pdf)
{
    size_t t[CHUNK];
    for (int i = 0; i < n; ++i) {
        t[i] = (size_t)environment_texel_of(s->env, environment_world_to_map(s->env, w[i]));
        __builtin_prefetch(s->texel[t[i]]);
    }
    for (int i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c)
            rgb[i][c] = s->texel[t[i]][c];
        pdf[i] = s->texel[t[i]][3];
    }
}

void environment_sampler_lookup_many(const environment_sampler *s, int n, const vec3 *w, float (*rgb)[3], float *pdf)
{
    for (int first = 0; first < n; first += CHUNK) {
        int m = n - first < CHUNK ? n - first : CHUNK;
        if (environment_map_is_constant(s->env))
            for (int i = first; i < first + m; ++i)
                environment_sampler_lookup(s, w[i], rgb[i], &pdf[i]);
        else
            lookup_chunk(s, m, w + first, rgb + first, pdf + first);
    }
}
