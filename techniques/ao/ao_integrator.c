#include "ao/ao_integrator.h"

#include "core/sampling/hemisphere_sampling.h"
#include "core/reference_schema.h"

enum { AO_V, AO_VUNIFORM, BENT_X, BENT_Y, BENT_Z, AO_QUANTITY_COUNT };

/* All AO estimates lie in [-1, 1]: scale exponent 0. */
static const mc_quantity ao_quantities[AO_QUANTITY_COUNT] = {
    {CH_AO, 0}, {CH_AO_UNIFORM, 0}, {CH_BENT_X, 0}, {CH_BENT_Y, 0}, {CH_BENT_Z, 0}};
/* With the control variate, V - g + G lies in [-1, 2]: scale exponent 1. */
static const mc_quantity ao_cv_quantities[AO_QUANTITY_COUNT] = {
    {CH_AO, 1}, {CH_AO_UNIFORM, 1}, {CH_BENT_X, 0}, {CH_BENT_Y, 0}, {CH_BENT_Z, 0}};

/* V(w) - beta (g(w) - G) for both visibility estimators of a batch
 * (techniques/ao/slice_horizons.h); the ray directions are the sample's. */
static void apply_control_variate(const slice_horizons *h, const struct RTCRay *rays, int count, float *values)
{
    frame f = slice_horizons_frame(h);
    for (int k = 0; k < count; ++k)
        for (int q = 0; q < 2; ++q) {
            const struct RTCRay *r = &rays[2 * k + q];
            float g = slice_horizons_visible(h, &f, v3(r->dir_x, r->dir_y, r->dir_z));
            float *value = &values[(q == 0 ? AO_V : AO_VUNIFORM) * SAMPLE_BATCH + k];
            *value = *value - h->beta[q] * (g - h->integral[q]);
        }
}

/* Per sample: ray 2k is cosine-distributed, ray 2k+1 uniform, both mapped
 * from the sample's one 2-D point (pair `pair`; the estimates use pair 0).
 * Each estimator on its own is a scrambled-Sobol' estimator of its
 * integral; that the two are correlated with each other matters to neither.
 * A direction below the geometric surface counts as blocked (V = 0): its ray
 * is left in the stream but inactive (tfar < tnear, which Embree skips and
 * leaves untouched), so the loop has no unpredictable branch. */
/* Each ray's cutoff: max_distance, or with a fade one drawn uniformly on
 * [fade_start, max_distance] from dimension pair FADE_PAIR (see ao_integrator.h). */
#define FADE_PAIR 2u
static void ray_cutoffs(const pixel_context *px, float max_distance, float fade_start, uint32_t first_index, int count,
                        float cutoff[2][SAMPLE_BATCH])
{
    int fade = fade_start > 0.0f && fade_start < max_distance;
    if (fade) {
        const sample_pair_seeds seeds = sample_pair_seeds_for(px, FADE_PAIR);
        sample_pair_points(&seeds, first_index, count, cutoff[0], cutoff[1]);
    }
    for (int k = 0; k < count; ++k)
        for (int r = 0; r < 2; ++r)
            cutoff[r][k] = fade ? fade_start + (max_distance - fade_start) * cutoff[r][k] : max_distance;
}

int ao_trace_batch(const embree_scene *es, const pixel_context *px, float max_distance, float fade_start, uint32_t pair,
                   uint32_t first_index, int count, struct RTCRay *rays)
{
    const sample_pair_seeds seeds = sample_pair_seeds_for(px, pair);
    float u0[SAMPLE_BATCH], u1[SAMPLE_BATCH], cutoff[2][SAMPLE_BATCH];
    vec3 local[2][SAMPLE_BATCH]; /* [0]: cosine, [1]: uniform */
    sample_pair_points(&seeds, first_index, count, u0, u1);
    sample_hemisphere_batch(u0, u1, count, local[0], local[1]);
    ray_cutoffs(px, max_distance, fade_start, first_index, count, cutoff);
    int traced = 0;
    for (int r = 0; r < 2 * count; ++r) {
        vec3 d = frame_to_world(&px->shading, local[r & 1][r >> 1]);
        int above = v3_dot(d, px->surface->ng) > 0.0f;
        embree_ray_init(&rays[r], px->ray_origin, d, above ? cutoff[r & 1][r >> 1] : -1.0f);
        traced += above;
    }
    embree_unoccluded_stream(es, rays, (unsigned)(2 * count));
    return traced;
}

static int ao_sample_batch(const integrator *self, const pixel_context *px, uint32_t first_index, int count,
                           float *values)
{
    const ao_settings *settings = self->settings;
    _Alignas(16) struct RTCRay rays[2 * SAMPLE_BATCH];
    int traced =
        ao_trace_batch(self->scene, px, settings->max_distance, settings->fade_start, 0, first_index, count, rays);
    for (int k = 0; k < count; ++k) {
        const struct RTCRay *cosine = &rays[2 * k], *uniform = &rays[2 * k + 1];
        float v_cos = cosine->tfar >= 0.0f ? 1.0f : 0.0f;
        values[AO_V * SAMPLE_BATCH + k] = v_cos;
        values[AO_VUNIFORM * SAMPLE_BATCH + k] = uniform->tfar >= 0.0f ? 1.0f : 0.0f;
        values[BENT_X * SAMPLE_BATCH + k] = v_cos * cosine->dir_x;
        values[BENT_Y * SAMPLE_BATCH + k] = v_cos * cosine->dir_y;
        values[BENT_Z * SAMPLE_BATCH + k] = v_cos * cosine->dir_z;
    }
    if (settings->control_variate)
        apply_control_variate(&settings->control_variate[px->pixel], rays, count, values);
    return traced;
}

integrator ao_integrator(const embree_scene *es, const ao_settings *settings)
{
    integrator it = {"ao", AO_QUANTITY_COUNT, settings->control_variate ? ao_cv_quantities : ao_quantities, "bent",
                     ao_sample_batch, es, settings, 0};
    return it;
}
