/* Double-precision helpers shared by the built-in scene tests: a triangle's
 * corners and normals, read straight from a scene_mesh, and the sums the
 * tests compare with closed forms. */
#ifndef GTLAB_TESTS_SCENE_BUILTIN_MESH_MATH_H
#define GTLAB_TESTS_SCENE_BUILTIN_MESH_MATH_H

#include <math.h>
#include <stdint.h>

#include "scene/scene.h"

typedef struct {
    double x, y, z;
} d3;

static inline d3 d3_of(const float *p) { return (d3){p[0], p[1], p[2]}; }
static inline d3 d3_sub(d3 a, d3 b) { return (d3){a.x - b.x, a.y - b.y, a.z - b.z}; }
static inline double d3_dot(d3 a, d3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline double d3_length(d3 a) { return sqrt(d3_dot(a, a)); }
static inline d3 d3_cross(d3 a, d3 b)
{
    return (d3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/* Corner k (0..2) of triangle t: its position and its stored vertex normal. */
static inline d3 tri_position(const scene_mesh *m, uint32_t t, int k)
{
    return d3_of(&m->positions[3 * m->indices[3 * t + k]]);
}
static inline d3 tri_normal(const scene_mesh *m, uint32_t t, int k)
{
    return d3_of(&m->normals[3 * m->indices[3 * t + k]]);
}

/* (b - a) x (c - a): the geometric normal given by the winding, with length
 * twice the triangle's area. */
static inline d3 tri_area_vector(const scene_mesh *m, uint32_t t)
{
    d3 a = tri_position(m, t, 0);
    return d3_cross(d3_sub(tri_position(m, t, 1), a), d3_sub(tri_position(m, t, 2), a));
}

static inline double mesh_area(const scene_mesh *m)
{
    double area = 0.0;
    for (uint32_t t = 0; t < m->triangle_count; ++t)
        area += 0.5 * d3_length(tri_area_vector(m, t));
    return area;
}

#endif
