/* Strips and fans as triangle lists: see primitive_topology.h. */
#include "scene/gltf/primitive_topology.h"

int gltf_mode_has_triangles(int mode)
{
    return mode == GLTF_MODE_TRIANGLES || mode == GLTF_MODE_TRIANGLE_STRIP || mode == GLTF_MODE_TRIANGLE_FAN;
}

size_t gltf_mode_triangle_count(int mode, size_t n)
{
    if (mode == GLTF_MODE_TRIANGLES)
        return n / 3;
    if (gltf_mode_has_triangles(mode))
        return n >= 3 ? n - 2 : 0;
    return 0;
}

/* Corner k (0, 1, 2) of triangle i, as a position in the sequence. */
static size_t corner(int mode, size_t i, int k)
{
    if (mode == GLTF_MODE_TRIANGLE_STRIP) {
        const size_t odd = i % 2;
        return k == 0 ? i : k == 1 ? i + 1 + odd : i + 2 - odd;
    }
    if (mode == GLTF_MODE_TRIANGLE_FAN)
        return k == 2 ? 0 : i + 1 + (size_t)k;
    return 3 * i + (size_t)k;
}

void gltf_triangulate(int mode, size_t n, const uint32_t *v, uint32_t *out)
{
    const size_t count = gltf_mode_triangle_count(mode, n);
    for (size_t i = 0; i < count; ++i)
        for (int k = 0; k < 3; ++k)
            out[3 * i + (size_t)k] = v[corner(mode, i, k)];
}
