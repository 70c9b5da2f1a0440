/* KHR_texture_transform as an affine map: see uv_transform.h. */
#include "scene/gltf/uv_transform.h"

#include <math.h>
#include <string.h>

uv_transform uv_transform_identity(void)
{
    uv_transform t = {{1, 0, 0, 0, 1, 0}};
    return t;
}

uv_transform uv_transform_from_khr(const double offset[2], double rotation, const double scale[2])
{
    const double c = cos(rotation), s = sin(rotation);
    uv_transform t = {{scale[0] * c, scale[1] * s, offset[0], -scale[0] * s, scale[1] * c, offset[1]}};
    return t;
}

int uv_transform_equal(const uv_transform *a, const uv_transform *b)
{
    return memcmp(a->m, b->m, sizeof a->m) == 0;
}

void uv_transform_apply(const uv_transform *t, float *uv, size_t count)
{
    for (size_t i = 0; i < count; ++i) {
        const double u = uv[2 * i], v = uv[2 * i + 1];
        uv[2 * i] = (float)(t->m[0] * u + t->m[1] * v + t->m[2]);
        uv[2 * i + 1] = (float)(t->m[3] * u + t->m[4] * v + t->m[5]);
    }
}
