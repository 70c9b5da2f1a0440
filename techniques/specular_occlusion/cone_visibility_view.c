#include "specular_occlusion/cone_visibility_view.h"

#include <stdint.h>

#include "core/optics/ggx.h"

/* The jitter in [0, 1) of stratum (i, j), coordinate c, for a seed: a
 * 32-bit integer hash (Wellons' lowbias32), uniform over the stratum. */
static float jitter(int i, int j, int c, uint32_t seed)
{
    uint32_t x = (uint32_t)i * 73856093u ^ (uint32_t)j * 19349663u ^ (uint32_t)c * 83492791u ^ seed * 2654435761u;
    x ^= x >> 16, x *= 0x7feb352du, x ^= x >> 15, x *= 0x846ca68bu, x ^= x >> 16;
    return (float)(x >> 8) / 16777216.0f;
}

double so_cone_visibility_view(vec3 v, vec3 axis, double cos_av, double alpha, int strata, uint32_t seed)
{
    double inside = 0.0, total = 0.0;
    for (int j = 0; j < strata; ++j)
        for (int i = 0; i < strata; ++i) {
            float u[2] = {(i + jitter(i, j, 0, seed)) / (float)strata, (j + jitter(i, j, 1, seed)) / (float)strata};
            vec3 l = ggx_reflect(v, ggx_sample_visible_normal(v, alpha, u));
            double w = ggx_reflection_weight_brdf(v, l, alpha);
            total += w;
            if (v3_dot(l, axis) >= cos_av)
                inside += w;
        }
    return total > 0.0 ? inside / total : 1.0;
}
