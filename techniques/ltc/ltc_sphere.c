/* LTC sphere lights (ltc/ltc_sphere.h): the clipped polygon's
 * form factor and the sphere as an equal-area N-gon facing the point. */
#include "ltc/ltc_sphere.h"

#include <math.h>

/* Sutherland-Hodgman against z >= 0 for vertices centre + offsets: writes
 * at most count + 1 offsets to out and returns their number. */
static int clip_to_upper(vec3 centre, const vec3 *in, int count, vec3 *out)
{
    int n = 0;
    for (int k = 0; k < count; ++k) {
        vec3 a = in[k], b = in[(k + 1) % count];
        float za = centre.z + a.z, zb = centre.z + b.z;
        if (za >= 0.0f)
            out[n++] = a;
        if ((za >= 0.0f) != (zb >= 0.0f))
            out[n++] = v3_add(a, v3_scale(v3_sub(b, a), za / (za - zb)));
    }
    return n;
}

/* (theta_ij / 2 pi) (p_i x p_j).z / |p_i x p_j| with p = centre + offset:
 * theta_ij = atan2(|p_i x p_j|, p_i . p_j), exact for any lengths of p.
 * (Heitz's shipped code replaces theta / sin(theta) by a rational fit in
 * p_i . p_j: its error, ~1e-4, multiplies each edge's term, which for a
 * light of angular size theta is ~theta while their sum is ~theta^2, so the
 * sun (theta ~ 0.005) would be off by percents; atan2 costs no more here
 * (`gtlab bench sphere-light`).) */
static float edge_integral(vec3 centre, vec3 oi, vec3 oj)
{
    vec3 cross = v3_add(v3_cross(centre, v3_sub(oj, oi)), v3_cross(oi, oj));
    float s = v3_length(cross);
    if (!(s > 0.0f))
        return 0.0f;
    float theta = atan2f(s, v3_dot(v3_add(centre, oi), v3_add(centre, oj)));
    return theta * cross.z / (s * 2.0f * (float)M_PI);
}

float ltc_polygon_form_factor(vec3 centre, const vec3 *offsets, int count)
{
    vec3 clipped[LTC_MAX_SIDES + 1];
    int n = clip_to_upper(centre, offsets, count > LTC_MAX_SIDES ? LTC_MAX_SIDES : count, clipped);
    float sum = 0.0f;
    for (int k = 0; k < n; ++k)
        sum += edge_integral(centre, clipped[k], clipped[k + 1 < n ? k + 1 : 0]);
    return fabsf(sum);
}

/* x -> M^-1 x in the frame (t1, t2, n) with v in the t1-z plane. */
static vec3 to_cosine_space(const float m[4], vec3 t1, vec3 t2, vec3 x)
{
    float x1 = v3_dot(x, t1), x2 = v3_dot(x, t2);
    return v3(m[0] * x1 + m[1] * x.z, m[2] * x2, m[3] * x1 + x.z);
}

/* The view's frame: t1 towards v's azimuth (x when v = n). */
static void view_frame(vec3 v, vec3 *t1, vec3 *t2)
{
    float len = sqrtf(v.x * v.x + v.y * v.y);
    *t1 = len > 0.0f ? v3(v.x / len, v.y / len, 0.0f) : v3(1.0f, 0.0f, 0.0f);
    *t2 = v3(-t1->y, t1->x, 0.0f);
}

float ltc_sphere_integral(const float m[4], vec3 v, vec3 lc, float sin_sigma, int sides)
{
    vec3 t1, t2, offsets[LTC_MAX_SIDES];
    view_frame(v, &t1, &t2);
    sides = sides > LTC_MAX_SIDES ? LTC_MAX_SIDES : sides;
    float cos_sigma = sqrtf(fmaxf(0.0f, 1.0f - sin_sigma * sin_sigma));
    float step = 2.0f * (float)M_PI / (float)sides, cos_step = cosf(step), sin_step = sinf(step);
    float rho = sin_sigma / cos_sigma * sqrtf(step / sin_step);
    vec3 u = fabsf(lc.z) < 0.9f ? v3(0.0f, 0.0f, 1.0f) : v3(1.0f, 0.0f, 0.0f);
    vec3 a = v3_normalize(v3_cross(u, lc)), b = v3_cross(lc, a);
    vec3 ma = to_cosine_space(m, t1, t2, v3_scale(a, rho)), mb = to_cosine_space(m, t1, t2, v3_scale(b, rho));
    float c = 1.0f, s = 0.0f; /* cos, sin of step k, by rotation (exact at k = 0) */
    for (int k = 0; k < sides; ++k) {
        offsets[k] = v3_add(v3_scale(ma, c), v3_scale(mb, s));
        float next = c * cos_step - s * sin_step;
        s = s * cos_step + c * sin_step, c = next;
    }
    return ltc_polygon_form_factor(to_cosine_space(m, t1, t2, lc), offsets, sides);
}

/* The table's texel at (v.z, roughness) and the cap's LTC integral over
 * pi sin^2 sigma. */
static float unit_illuminance_integral(const ltc_table *t, vec3 v, vec3 lc, float sin_sigma, float roughness,
                                       float texel[LTC_CHANNELS])
{
    ltc_table_sample(t, v.z, roughness, texel);
    float integral = ltc_sphere_integral(texel, v, lc, sin_sigma, LTC_SPHERE_SIDES);
    return integral / ((float)M_PI * sin_sigma * sin_sigma);
}

float ltc_sphere_ggx(const ltc_table *t, vec3 v, vec3 lc, float sin_sigma, float roughness)
{
    float texel[LTC_CHANNELS];
    float per_unit = unit_illuminance_integral(t, v, lc, sin_sigma, roughness, texel);
    return texel[LTC_MAGNITUDE] * per_unit;
}

float ltc_sphere_ggx_fresnel(const ltc_table *t, vec3 v, vec3 lc, float sin_sigma, float roughness, float f0)
{
    float texel[LTC_CHANNELS];
    float per_unit = unit_illuminance_integral(t, v, lc, sin_sigma, roughness, texel);
    return (f0 * texel[LTC_MAGNITUDE] + (1.0f - f0) * texel[LTC_FRESNEL]) * per_unit;
}

float ltc_sphere_specular(const void *table, vec3 v, vec3 lc, float sin_sigma, float roughness, float f0)
{
    return ltc_sphere_ggx_fresnel(table, v, lc, sin_sigma, roughness, f0);
}
