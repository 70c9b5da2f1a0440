/* glTF 2.0 in through tinygltf (a C++ adapter, gltf_reader.cpp, behind this
 * C header); the writer is gltf_writer.h.
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
#ifndef GTLAB_SCENE_GLTF_READER_H
#define GTLAB_SCENE_GLTF_READER_H

#include <stddef.h>

#include "core/error.h"
#include "scene/scene.h"

int gltf_load(const char *path, scene *s, gt_error *e);
/* The same from the file's bytes in memory: `name` stands for the file in
 * messages (and ".glb" at its end asks for a binary file, as for a path);
 * external buffers and images are looked up in base_dir. */
int gltf_load_memory(const void *bytes, size_t size, const char *name, const char *base_dir, scene *s,
                     gt_error *e);

#endif
