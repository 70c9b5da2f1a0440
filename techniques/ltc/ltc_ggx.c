/* The LTC table's layout, its distribution and its lookup (ltc/ltc_ggx.h). */
#include "ltc/ltc_ggx.h"

#include <math.h>
#include <stdlib.h>

#include "core/vec3.h" /* M_PI */
#include "luts/table_lookup_c.h"
#include "luts/table_lookup.inc"

const char *ltc_ggx_description(void)
{
    return "GGX linearly transformed cosines (Heitz et al. 2016) at data[(j*N + i)*6 + c]; texel centres: "
           "i: u = (i + 0.5)/N, n.v = 1 - u^2; j: r = (j + 0.5)/N perceptual roughness (GGX alpha = max(r^2, 1e-3), "
           "height-correlated Smith G2); c = 0..3: a, b, c, d of M^-1 = [[a,0,b],[0,c,0],[d,0,1]] in the frame n = +z, "
           "v in the xz plane; 4: magnitude E (directional albedo), 5: Fresnel term B; "
           "specular = (F0*E + (1 - F0)*B) * form factor of M^-1 P";
}

double ltc_n_dot_v_of_column(int i, int size)
{
    double u = (i + 0.5) / size;
    return 1.0 - u * u;
}

double ltc_roughness_of_row(int j, int size) { return (j + 0.5) / size; }

void ltc_apply_inverse(const double m[4], const double w[3], double out[3])
{
    out[0] = m[0] * w[0] + m[1] * w[2];
    out[1] = m[2] * w[1];
    out[2] = m[3] * w[0] + w[2];
}

double ltc_density(const double m[4], const double w[3])
{
    double len_w = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]), o[3];
    ltc_apply_inverse(m, w, o);
    double len = sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]) / len_w;
    double det = fabs(m[2] * (m[0] - m[1] * m[3]));
    double cos_o = o[2] / (len * len_w);
    return cos_o > 0.0 ? cos_o / M_PI * det / (len * len * len) : 0.0;
}

int ltc_table_alloc(ltc_table *t, int size)
{
    t->size = 0, t->data = NULL, t->error = NULL, t->max_error = t->mean_error = 0.0;
    if (size < LTC_MIN_SIZE || size > LTC_MAX_SIZE)
        return -1;
    size_t texels = (size_t)size * (size_t)size;
    t->data = calloc(texels * LTC_CHANNELS, sizeof *t->data);
    t->error = calloc(texels, sizeof *t->error);
    if (!t->data || !t->error) {
        ltc_table_free(t);
        return -1;
    }
    t->size = size;
    return 0;
}

void ltc_table_free(ltc_table *t)
{
    free(t->data), free(t->error);
    t->data = NULL, t->error = NULL, t->size = 0;
}

void ltc_table_sample(const ltc_table *t, float n_dot_v, float roughness, float out[LTC_CHANNELS])
{
    float u = sqrtf(fmaxf(0.0f, 1.0f - n_dot_v));
    for (int c = 0; c < LTC_CHANNELS; ++c) {
        dfg_table table = {t->data, t->size, LTC_CHANNELS, c};
        out[c] = dfg_lookup(table, u, roughness);
    }
}
