/* The published HeightFog() batched over rows (height_fog_published_batch)
 * against the one-pixel function (height_fog_published), on random views
 * in every regime (world points above and below the camera, thin to dense
 * fog, H from 10 m to 100 km, every sun-view cosine):
 *
 *   - the two run the same float operations and differ only in expf's last
 *     bits (libmvec's vector expf: within 4 ulp, glibc manual; the scalar
 *     within 1): so each output is within that error propagated through
 *     the formula, the bound below;
 *   - the batch gives the same bits however the pixels are split into calls. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "core/sampling/splitmix64.h"
#include "height_fog/height_fog_published.h"
#include "tests/check.h"

enum { PIXELS = 3000 };

/* 5 ulp (4 + 1) of one expf and one ulp of a float operation, relative. */
#define EXP_EPS (5.0 * FLT_EPSILON)
#define OP_EPS FLT_EPSILON

typedef struct {
    float distance[PIXELS], world_y[PIXELS], sov[PIXELS];
} height_fog_views;

static void random_views(unsigned long long seed, height_fog_views *v, float *camera_y)
{
    *camera_y = (float)(3000.0 * splitmix64_uniform01(&seed) - 500.0);
    for (int i = 0; i < PIXELS; ++i) {
        v->distance[i] = (float)(20000.0 * splitmix64_uniform01(&seed));
        v->world_y[i] = (float)(4000.0 * splitmix64_uniform01(&seed) - 1000.0);
        v->sov[i] = (float)(2.0 * splitmix64_uniform01(&seed) - 1.0);
    }
}

/* |batch - scalar| allowed for T and L of channel c at one view: the
 * density factor (1 - e^-t) / t e^(-y_w/H) carries expf's error amplified by
 * e^-t / (1 - e^-t) from the cancellation, the optical depth tau multiplies
 * that, the outer expf adds its own, and L = source (1 - T) inherits T's. */
static void allowed_difference(const height_fog_uniforms *u, int c, float camera_y, float distance, float world_y,
                               float sov, double *dt, double *dl)
{
    double t = height_fog_clamped_t(u, camera_y, world_y), a = exp(-t);
    double density = -expm1(-t) / t * exp(-world_y / (double)u->scale_height);
    double tau = distance * density * u->beta_t[c], transmittance = exp(-tau);
    double rel_density = EXP_EPS * (a / (1.0 - a) + 1.0) + 6.0 * OP_EPS;
    *dt = transmittance * (tau * (rel_density + 3.0 * OP_EPS) + EXP_EPS) + 2.0 * FLT_MIN;
    double pr = height_fog_rayleigh(sov), pm = height_fog_henyey_greenstein(u, sov);
    double source = height_fog_source(u, c, height_fog_single(u, c, (float)pr, (float)pm));
    *dl = source * (*dt + 4.0 * OP_EPS * (1.0 - transmittance)) + 2.0 * FLT_MIN;
}

/* Largest |batch - scalar| over the allowed difference, over every output. */
static double worst_ratio(const height_fog_param *p, const height_fog_views *v, float camera_y)
{
    static float planes[6][PIXELS];
    float *l[3] = {planes[0], planes[1], planes[2]}, *t[3] = {planes[3], planes[4], planes[5]};
    height_fog_uniforms u;
    height_fog_uniforms_init(p, &u);
    height_fog_published_batch(&u, camera_y, PIXELS, v->distance, v->world_y, v->sov, l, t);
    double worst = 0.0;
    for (int i = 0; i < PIXELS; ++i) {
        float in[3], tr[3];
        height_fog_published(p, v->distance[i], camera_y, v->world_y[i], v->sov[i], in, tr);
        for (int c = 0; c < 3; ++c) {
            double dt, dl;
            allowed_difference(&u, c, camera_y, v->distance[i], v->world_y[i], v->sov[i], &dt, &dl);
            worst = fmax(worst, fmax(fabs(t[c][i] - tr[c]) / dt, fabs(l[c][i] - in[c]) / dl));
        }
    }
    return worst;
}

static height_fog_param medium(unsigned long long seed)
{
    height_fog_param p = height_fog_param_default();
    double thickness = pow(10.0, 3.0 * splitmix64_uniform01(&seed)); /* clear air to x1000 */
    for (int c = 0; c < 3; ++c)
        p.beta_rs[c] *= thickness;
    p.beta_ms *= thickness;
    p.beta_ma *= thickness;
    p.scale_height = pow(10.0, 1.0 + 4.0 * splitmix64_uniform01(&seed));
    p.mie_g = 1.6 * splitmix64_uniform01(&seed) - 0.8;
    p.sun_color[1] = 0.9, p.sun_color[2] = 0.7;
    return p;
}

static void test_batch_within_expf_error(void)
{
    static height_fog_views v;
    for (unsigned long long k = 1; k <= 12; ++k) {
        height_fog_param p = medium(k * 7919ULL);
        float camera_y;
        random_views(k, &v, &camera_y);
        double worst = worst_ratio(&p, &v, camera_y);
        CHECK_MSG(worst <= 1.0, "medium %llu: |batch - scalar| reaches %.3g of the allowed difference", k, worst);
    }
}

/* One call of PIXELS against calls of 1, 7 and 300 pixels: the same bits. */
static void test_batch_split_invariant(void)
{
    static height_fog_views v;
    static float whole[6][PIXELS], split[6][PIXELS];
    float camera_y;
    random_views(99, &v, &camera_y);
    height_fog_param p = medium(5);
    height_fog_uniforms u;
    height_fog_uniforms_init(&p, &u);
    float *wl[3] = {whole[0], whole[1], whole[2]}, *wt[3] = {whole[3], whole[4], whole[5]};
    height_fog_published_batch(&u, camera_y, PIXELS, v.distance, v.world_y, v.sov, wl, wt);
    const int sizes[3] = {1, 7, 300};
    for (int k = 0; k < 3; ++k) {
        memset(split, 0xff, sizeof split);
        for (int s = 0; s < PIXELS; s += sizes[k]) {
            int n = PIXELS - s < sizes[k] ? PIXELS - s : sizes[k];
            float *l[3] = {split[0] + s, split[1] + s, split[2] + s}, *t[3] = {split[3] + s, split[4] + s, split[5] + s};
            height_fog_published_batch(&u, camera_y, (size_t)n, v.distance + s, v.world_y + s, v.sov + s, l, t);
        }
        CHECK_MSG(memcmp(whole, split, sizeof whole) == 0, "calls of %d pixels differ from one call", sizes[k]);
    }
}

int main(void)
{
    test_batch_within_expf_error();
    test_batch_split_invariant();
    return check_report("test_height_fog_batch");
}
