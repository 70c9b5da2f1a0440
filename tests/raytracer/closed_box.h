/* The cube [-1, 1]^3 as six inward-facing quads (one mesh, the default
 * material: white, base colour 1),
 * for tests that need a scene from which no ray escapes. */
#ifndef GTLAB_TESTS_RAYTRACER_CLOSED_BOX_H
#define GTLAB_TESTS_RAYTRACER_CLOSED_BOX_H

#include "scene/scene.h"

static inline int add_closed_box(scene *s)
{
    scene_mesh *m = scene_add_mesh(s, 24, 12, 0);
    if (!m)
        return -1;
    static const float corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int face = 0; face < 6; ++face) {
        int axis = face / 2, b = (axis + 1) % 3, c = (axis + 2) % 3;
        float side = face % 2 ? 1.0f : -1.0f;
        for (int k = 0; k < 4; ++k) {
            float *p = &m->positions[3 * (4 * face + k)], *n = &m->normals[3 * (4 * face + k)];
            p[axis] = side, p[b] = corner[k][0], p[c] = corner[k][1];
            n[axis] = -side, n[b] = 0.0f, n[c] = 0.0f;
        }
        static const uint32_t quad[6] = {0, 1, 2, 0, 2, 3};
        for (int k = 0; k < 6; ++k)
            m->indices[6 * face + k] = 4u * (uint32_t)face + quad[k];
    }
    return 0;
}

#endif
