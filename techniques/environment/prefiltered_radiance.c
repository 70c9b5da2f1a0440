/* GGX pre-filtered radiance by Karis's deterministic Hammersley filter
 * with filtered-importance-sampling lookups, its mip chain and the split
 * sum. See the header for the equations and the roughness mapping. */
#include "environment/prefiltered_radiance.h"

#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/frame.h"
#include "core/optics/ggx.h"

double prefiltered_level_roughness(int k, int levels) { return levels > 1 ? (double)k / (levels - 1) : 0.0; }

/* The radical inverse of i in base 2 (Hammersley's second coordinate). */
static double radical_inverse(uint32_t i)
{
    i = (i << 16) | (i >> 16);
    i = ((i & 0x55555555u) << 1) | ((i & 0xAAAAAAAAu) >> 1);
    i = ((i & 0x33333333u) << 2) | ((i & 0xCCCCCCCCu) >> 2);
    i = ((i & 0x0F0F0F0Fu) << 4) | ((i & 0xF0F0F0F0u) >> 4);
    i = ((i & 0x00FF00FFu) << 8) | ((i & 0xFF00FF00u) >> 8);
    return i * (1.0 / 4294967296.0);
}

static double mean_texel_solid_angle(int width, int height) { return 4.0 * M_PI / ((double)width * height); }

/* The pyramid level whose texels have the solid angle `omega`. */
static double level_of_solid_angle(const equirect_pyramid *s, double omega)
{
    return 0.5 * log2(omega / mean_texel_solid_angle(s->width[0], s->height[0]));
}

/* Sample i of n: the light direction l (local frame, R = +z), its n.l (<= 0: none) and D(h). */
static double sample_direction(int i, int n, double alpha, double l[3], double *d)
{
    double u1 = (i + 0.5) / n, phi = 2.0 * M_PI * radical_inverse((uint32_t)i);
    double cos2 = (1.0 - u1) / (1.0 + (alpha * alpha - 1.0) * u1), ch = sqrt(cos2), sh = sqrt(fmax(0.0, 1.0 - cos2));
    double h[3] = {sh * cos(phi), sh * sin(phi), ch};
    l[0] = 2.0 * ch * h[0], l[1] = 2.0 * ch * h[1], l[2] = 2.0 * ch * h[2] - 1.0;
    *d = ggx_ndf(ch, alpha);
    return l[2];
}

void prefiltered_radiance_filter(const equirect_pyramid *source, const double R[3], double roughness, int samples,
                                 double out_solid_angle, float out[3])
{
    if (roughness <= 0.0) {
        equirect_pyramid_lookup(source, R, level_of_solid_angle(source, out_solid_angle), out);
        return;
    }
    double alpha = ggx_alpha(roughness), sum[3] = {0.0, 0.0, 0.0}, weight = 0.0;
    frame f = frame_from_normal(v3((float)R[0], (float)R[1], (float)R[2]));
    for (int i = 0; i < samples; ++i) {
        double l[3], d;
        double nl = sample_direction(i, samples, alpha, l, &d);
        if (nl <= 0.0)
            continue;
        vec3 lw = frame_to_world(&f, v3((float)l[0], (float)l[1], (float)l[2]));
        double w[3] = {lw.x, lw.y, lw.z}, omega = 4.0 / (samples * d);
        float L[3];
        equirect_pyramid_lookup(source, w, fmax(0.0, level_of_solid_angle(source, omega) + 1.0), L);
        for (int c = 0; c < 3; ++c)
            sum[c] += L[c] * nl;
        weight += nl;
    }
    for (int c = 0; c < 3; ++c)
        out[c] = (float)(sum[c] / weight);
}

static int level_build(prefiltered_radiance *p, const equirect_pyramid *src, int k, int threads)
{
    int w = p->width[k], h = p->height[k];
    p->rgb[k] = malloc((size_t)w * h * 3 * sizeof(float));
    if (!p->rgb[k])
        return -1;
    double r = prefiltered_level_roughness(k, p->levels), omega = mean_texel_solid_angle(w, h);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads > 0 ? threads : 1)
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            double R[3];
            equirect_texel_direction(w, h, i, j, R);
            prefiltered_radiance_filter(src, R, r, p->samples, omega, p->rgb[k] + ((size_t)j * w + i) * 3);
        }
    return 0;
}

int prefiltered_radiance_build(prefiltered_radiance *p, const environment_equirect *env, int width, int levels,
                               int samples, int threads)
{
    memset(p, 0, sizeof *p);
    if (width < PREFILTERED_MIN_WIDTH || width % 2 || levels < 2 || levels > PREFILTERED_MAX_LEVELS || samples < 1)
        return -1;
    equirect_pyramid src;
    if (equirect_pyramid_build(&src, env) != 0)
        return -1;
    p->levels = levels, p->samples = samples;
    int status = 0;
    for (int k = 0; k < levels && status == 0; ++k) {
        p->width[k] = width >> k < PREFILTERED_MIN_WIDTH ? PREFILTERED_MIN_WIDTH : width >> k;
        p->height[k] = p->width[k] / 2;
        status = level_build(p, &src, k, threads);
    }
    equirect_pyramid_free(&src);
    if (status != 0)
        prefiltered_radiance_free(p);
    return status;
}

void prefiltered_radiance_free(prefiltered_radiance *p)
{
    for (int k = 0; k < PREFILTERED_MAX_LEVELS; ++k)
        free(p->rgb[k]);
    memset(p, 0, sizeof *p);
}

void prefiltered_radiance_lookup(const prefiltered_radiance *p, const double R[3], double roughness, float out[3])
{
    double lod = fmax(0.0, fmin(1.0, roughness)) * (p->levels - 1);
    int k = (int)floor(lod);
    float a[3], b[3], t = (float)(lod - k);
    equirect_bilinear(p->rgb[k], p->width[k], p->height[k], R, a);
    if (k + 1 >= p->levels || t == 0.0f) {
        memcpy(out, a, sizeof a);
        return;
    }
    equirect_bilinear(p->rgb[k + 1], p->width[k + 1], p->height[k + 1], R, b);
    for (int c = 0; c < 3; ++c)
        out[c] = a[c] + (b[c] - a[c]) * t;
}

void split_sum_specular(const prefiltered_radiance *p, const dfg_lut *dfg, const double R[3], double n_dot_v,
                        double roughness, const double f0[3], double out[3])
{
    float pre[3], ab[3];
    prefiltered_radiance_lookup(p, R, roughness, pre);
    dfg_lut_sample(dfg, (float)n_dot_v, (float)roughness, ab);
    for (int c = 0; c < 3; ++c)
        out[c] = pre[c] * (f0[c] * ab[DFG_SCALE] + ab[DFG_BIAS]);
}
