/* A spot light's shadow map; see volumetric_light_shadow_map.h. */
#include "volumetric_light/volumetric_light_shadow_map.h"

#include <math.h>
#include <stdlib.h>

int shadow_map_alloc(shadow_map *m, int size, vec3 position, vec3 forward, double half_fov_deg, double bias,
                     gt_error *e)
{
    if (size < 1 || size > 8192 || !(half_fov_deg > 0.0 && half_fov_deg < 89.0))
        return gt_error_set(e, "shadow map", "size %d or half field of view %g out of range", size, half_fov_deg);
    m->distance = malloc(sizeof *m->distance * (size_t)size * (size_t)size);
    if (!m->distance)
        return gt_error_set(e, "shadow map", "out of memory");
    for (long i = 0; i < (long)size * size; ++i)
        m->distance[i] = INFINITY;
    m->size = size;
    m->position = position;
    m->forward = v3_normalize(forward);
    vec3 helper = fabsf(m->forward.y) < 0.9f ? v3(0.0f, 1.0f, 0.0f) : v3(1.0f, 0.0f, 0.0f);
    m->right = v3_normalize(v3_cross(m->forward, helper));
    m->up = v3_cross(m->right, m->forward);
    m->tan_half = tan(half_fov_deg * M_PI / 180.0);
    m->bias = bias;
    return 0;
}

void shadow_map_free(shadow_map *m)
{
    free(m->distance);
    m->distance = NULL;
}

vec3 shadow_map_direction(const shadow_map *m, double u, double v)
{
    double a = (2.0 * u / m->size - 1.0) * m->tan_half, b = (2.0 * v / m->size - 1.0) * m->tan_half;
    return v3_normalize(v3_add(m->forward, v3_add(v3_scale(m->right, (float)a), v3_scale(m->up, (float)b))));
}

static double texel_lit(const shadow_map *m, int i, int j, double r)
{
    i = i < 0 ? 0 : i >= m->size ? m->size - 1 : i;
    j = j < 0 ? 0 : j >= m->size ? m->size - 1 : j;
    return r <= (1.0 + m->bias) * m->distance[(long)j * m->size + i] ? 1.0 : 0.0;
}

double shadow_map_visibility(const shadow_map *m, vec3 x)
{
    vec3 d = v3_sub(x, m->position);
    double z = v3_dot(d, m->forward);
    if (!(z > 0.0))
        return 0.0;
    double a = v3_dot(d, m->right) / (z * m->tan_half), b = v3_dot(d, m->up) / (z * m->tan_half);
    if (!(fabs(a) <= 1.0 && fabs(b) <= 1.0))
        return 0.0;
    double u = 0.5 * (a + 1.0) * m->size - 0.5, v = 0.5 * (b + 1.0) * m->size - 0.5, r = v3_length(d);
    int i = (int)floor(u), j = (int)floor(v);
    double fu = u - i, fv = v - j;
    return (1.0 - fv) * ((1.0 - fu) * texel_lit(m, i, j, r) + fu * texel_lit(m, i + 1, j, r)) +
           fv * ((1.0 - fu) * texel_lit(m, i, j + 1, r) + fu * texel_lit(m, i + 1, j + 1, r));
}

vec3 shadow_cube_axis(int k)
{
    float sign = k & 1 ? -1.0f : 1.0f;
    return k < 2 ? v3(sign, 0.0f, 0.0f) : k < 4 ? v3(0.0f, sign, 0.0f) : v3(0.0f, 0.0f, sign);
}

double shadow_cube_visibility(const shadow_cube *c, vec3 x)
{
    vec3 d = v3_sub(x, c->face[0].position);
    float ax = fabsf(d.x), ay = fabsf(d.y), az = fabsf(d.z);
    int k = ax >= ay && ax >= az ? (d.x < 0.0f) : ay >= az ? 2 + (d.y < 0.0f) : 4 + (d.z < 0.0f);
    return shadow_map_visibility(&c->face[k], x);
}

void shadow_cube_free(shadow_cube *c)
{
    for (int k = 0; k < 6; ++k)
        shadow_map_free(&c->face[k]);
}
