/* KHR_draco_mesh_compression: a Draco-compressed triangle mesh (Google's
 * Draco, libdraco 1.5) decoded into plain arrays, behind this C header
 * (draco_decode.cpp is the thin C++ adapter). The glTF primitive's extension
 * names the bufferView holding the compressed bytes and, per glTF attribute,
 * the Draco attribute's unique id; the decoded mesh replaces the primitive's
 * accessors. Draco dequantizes its own quantized attributes; integer
 * attributes marked normalized become floats by Draco's normalization. */
#ifndef GTLAB_SCENE_GLTF_DRACO_DECODE_H
#define GTLAB_SCENE_GLTF_DRACO_DECODE_H

#include <stddef.h>
#include <stdint.h>

#include "core/error.h"

typedef struct draco_geometry draco_geometry;

/* Decodes a Draco triangle mesh. Returns 0 and *out (free with
 * draco_geometry_free; bytes must outlive it), or -1 with
 * e = "<what>: <problem>". */
int draco_geometry_decode(const unsigned char *bytes, size_t size, draco_geometry **out, const char *what,
                          gt_error *e);
uint32_t draco_geometry_vertex_count(const draco_geometry *g);
uint32_t draco_geometry_triangle_count(const draco_geometry *g);
/* The 3 * triangle_count corners, each < vertex_count. */
void draco_geometry_indices(const draco_geometry *g, uint32_t *out);
/* The attribute with Draco unique id `id` as `components` floats per vertex
 * (vertex_count * components values). Returns 0, or -1 with e when there is
 * no such attribute or it has fewer components. */
int draco_geometry_attribute(const draco_geometry *g, int id, int components, float *out, const char *what,
                             gt_error *e);
/* The grid step Draco quantized attribute `id` to, range / (2^bits - 1)
 * (in the attribute's units), or 0 when it was stored unquantized. */
double draco_geometry_step(const draco_geometry *g, int id);
void draco_geometry_free(draco_geometry *g);

#endif
