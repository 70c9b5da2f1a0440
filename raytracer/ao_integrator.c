#include "raytracer/ao_integrator.h"

#include "core/hemisphere_sampling.h"

enum { AO_V, AO_VUNIFORM, BENT_X, BENT_Y, BENT_Z, AO_QUANTITY_COUNT };

/* All AO estimates lie in [-1, 1]: scale exponent 0. */
static const mc_quantity ao_quantities[AO_QUANTITY_COUNT] = {
    {"ao.V", 0}, {"ao.Vuniform", 0}, {"bent.X", 0}, {"bent.Y", 0}, {"bent.Z", 0}};

/* Per sample: ray 2k is cosine-distributed, ray 2k+1 uniform, both mapped
 * from the sample's one 2-D point (pair 0). Each estimator on its own is a
 * scrambled-Sobol' estimator of its integral; that the two are correlated
 * with each other matters to neither. A direction below the geometric
 * surface is not traced: V = 0. */
static int ao_sample_batch(const integrator *self, const pixel_context *px, uint32_t first_index, int count,
                           float *values)
{
    const ao_settings *settings = self->settings;
    const sample_pair_seeds pair = sample_pair_seeds_for(px, 0);
    vec3 directions[2 * SAMPLE_BATCH];
    int traced_as[2 * SAMPLE_BATCH]; /* index into rays, or -1: under the surface */
    _Alignas(16) struct RTCRay rays[2 * SAMPLE_BATCH];
    unsigned ray_count = 0;
    float u0[SAMPLE_BATCH], u1[SAMPLE_BATCH];
    vec3 cosine[SAMPLE_BATCH], uniform[SAMPLE_BATCH];
    sample_pair_points(&pair, first_index, count, u0, u1);
    sample_hemisphere_batch(u0, u1, count, cosine, uniform);
    for (int k = 0; k < count; ++k) {
        directions[2 * k] = frame_to_world(&px->shading, cosine[k]);
        directions[2 * k + 1] = frame_to_world(&px->shading, uniform[k]);
    }
    for (int r = 0; r < 2 * count; ++r) {
        traced_as[r] = -1;
        if (v3_dot(directions[r], px->surface->ng) > 0.0f) {
            traced_as[r] = (int)ray_count;
            embree_ray_init(&rays[ray_count++], px->ray_origin, directions[r], settings->max_distance);
        }
    }
    embree_unoccluded_stream(self->scene, rays, ray_count);
    for (int k = 0; k < count; ++k) {
        int c = traced_as[2 * k], u = traced_as[2 * k + 1];
        float v_cos = c >= 0 && rays[c].tfar >= 0.0f ? 1.0f : 0.0f;
        float v_uni = u >= 0 && rays[u].tfar >= 0.0f ? 1.0f : 0.0f;
        float *out = &values[k * AO_QUANTITY_COUNT];
        vec3 w = directions[2 * k];
        out[AO_V] = v_cos;
        out[AO_VUNIFORM] = v_uni;
        out[BENT_X] = v_cos * w.x;
        out[BENT_Y] = v_cos * w.y;
        out[BENT_Z] = v_cos * w.z;
    }
    return (int)ray_count;
}

integrator ao_integrator(const embree_scene *es, const ao_settings *settings)
{
    integrator it = {"ao", AO_QUANTITY_COUNT, ao_quantities, "bent", ao_sample_batch, es, settings};
    return it;
}
