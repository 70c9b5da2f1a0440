/* Triangle primitives of glTF 2.0 ("Meshes", "Primitive topology") as
 * triangle lists. For a vertex (or index) sequence v_0 .. v_{n-1}:
 *   TRIANGLES (4)       p_i = {v_3i, v_3i+1, v_3i+2},            n / 3 triangles
 *   TRIANGLE_STRIP (5)  p_i = {v_i, v_i+(1+i%2), v_i+(2-i%2)},   n - 2 triangles
 *   TRIANGLE_FAN (6)    p_i = {v_i+1, v_i+2, v_0},               n - 2 triangles
 * The strip's formula alternates the order of the last two corners, so that
 * every triangle of the strip keeps the first one's winding (front faces stay
 * counter-clockwise). Points and lines (modes 0-3) have no triangles. */
#ifndef GTLAB_SCENE_GLTF_PRIMITIVE_TOPOLOGY_H
#define GTLAB_SCENE_GLTF_PRIMITIVE_TOPOLOGY_H

#include <stddef.h>
#include <stdint.h>

enum { GLTF_MODE_TRIANGLES = 4, GLTF_MODE_TRIANGLE_STRIP = 5, GLTF_MODE_TRIANGLE_FAN = 6 };

/* 1 for modes 4, 5 and 6. */
int gltf_mode_has_triangles(int mode);

/* Triangles a sequence of n vertices of a triangle mode makes (0 when too
 * short). For TRIANGLES, n must be a multiple of 3 (the caller checks). */
size_t gltf_mode_triangle_count(int mode, size_t n);

/* Writes the 3 * gltf_mode_triangle_count(mode, n) corners of the
 * triangles, in order, as indices into v (not v's values: compose with the
 * index buffer by the caller). */
void gltf_triangulate(int mode, size_t n, const uint32_t *v, uint32_t *out);

#endif
