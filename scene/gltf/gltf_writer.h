/* glTF 2.0 out through tinygltf (a C++ adapter, gltf_writer.cpp, behind this
 * C header); the reader is gltf_reader.h. */
#ifndef GTLAB_SCENE_GLTF_GLTF_WRITER_H
#define GTLAB_SCENE_GLTF_GLTF_WRITER_H

#include "core/error.h"
#include "scene/scene.h"

/* Writes the scene as a binary glTF (.glb): one mesh and node per scene mesh,
 * its materials and textures (PNG-encoded), and its camera if it has one.
 * Written atomically. */
int gltf_write_glb(const char *path, const scene *s, gt_error *e);

#endif
