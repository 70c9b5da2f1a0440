/* glTF 2.0 through tinygltf (a C++ adapter, gltf_io.cpp, behind this C header).
 *
 * Loading (.gltf with external or embedded buffers, or .glb): the default scene
 * (or scene 0, or all root nodes), its node hierarchy with TRS and matrix
 * transforms flattened into world-space meshes (normals by the inverse
 * transpose), triangle primitives with u8/u16/u32 or no indices, POSITION,
 * NORMAL (computed when absent), TEXCOORD_0, base-colour and
 * metallic-roughness factors and textures, and the first perspective camera
 * met in the hierarchy. Every problem that would make the render wrong is an
 * error naming the file; what can be safely skipped (non-triangle primitives,
 * a texture that cannot be decoded) is a warning. */
#ifndef GTLAB_SCENE_GLTF_IO_H
#define GTLAB_SCENE_GLTF_IO_H

#include "core/error.h"
#include "scene/scene.h"

int gltf_load(const char *path, scene *s, gt_error *e);

/* Writes the scene as a binary glTF (.glb): one mesh and node per scene mesh,
 * its materials and textures (PNG-encoded), and its camera if it has one.
 * Written atomically. */
int gltf_write_glb(const char *path, const scene *s, gt_error *e);

#endif
