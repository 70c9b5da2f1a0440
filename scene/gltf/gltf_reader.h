/* glTF 2.0 in through tinygltf (a C++ adapter, gltf_reader.cpp, behind this
 * C header); the writer is gltf_writer.h.
 *
 * Loading (.gltf with external or embedded buffers, or .glb): the default scene
 * (or scene 0, or all root nodes), its node hierarchy with TRS and matrix
 * transforms flattened into world-space meshes (normals by the inverse
 * transpose), triangle primitives (lists, strips and fans:
 * primitive_topology.h) with u8/u16/u32 or no indices, POSITION, NORMAL
 * (flat-shaded when absent), TEXCOORD_0, sparse accessors, integer
 * attributes of KHR_mesh_quantization (accessor_decode.h), morph targets and
 * skins in their default pose (vertex_pose.h), bufferViews compressed with
 * EXT_meshopt_compression (meshopt_decode.h), primitives compressed with
 * KHR_draco_mesh_compression (draco_decode.h), KHR_texture_transform baked
 * into TEXCOORD_0 (uv_transform.h), base-colour and
 * metallic-roughness factors and textures, and the first perspective camera
 * met in the hierarchy. A file that requires any other extension is refused
 * naming it, before anything else is read. Every problem that would make the render wrong is an
 * error naming the file; what can be safely skipped (non-triangle primitives,
 * a texture that cannot be decoded) is a warning. */
#ifndef GTLAB_SCENE_GLTF_GLTF_READER_H
#define GTLAB_SCENE_GLTF_GLTF_READER_H

#include <stddef.h>

#include "core/error.h"
#include "scene/scene.h"

int gltf_load(const char *path, scene *s, gt_error *e);

/* Which glTF camera becomes the scene camera: the one at `index` in the
 * file's cameras, or (name not NULL) the one named so; the first node of the
 * hierarchy walk that instances it places it. Index -1 and name NULL: the
 * first perspective camera met, as gltf_load. */
typedef struct {
    int index;
    const char *name;
} gltf_camera_choice;

/* gltf_load with the scene camera chosen; an unknown camera, or one no node
 * of the scene places (or not perspective), is an error naming the file. */
int gltf_load_with_camera(const char *path, const gltf_camera_choice *choice, scene *s, gt_error *e);

/* What the reader met and did, for `gtlab scene info`: counts over the
 * primitives drawn (a mesh used by two nodes counts twice). */
typedef struct {
    int primitives_by_mode[7];      /* glTF mode 0-6; modes 0-3 (points, lines) are skipped */
    int quantized_primitives;       /* an integer POSITION, NORMAL or TEXCOORD_0 (KHR_mesh_quantization) */
    int draco_primitives;           /* decoded from KHR_draco_mesh_compression */
    int meshopt_views;              /* bufferViews decoded from EXT_meshopt_compression */
    int sparse_accessors;           /* accessors read with sparse substitution */
    int morphed_primitives;         /* morph targets applied with a non-zero weight */
    int skinned_primitives;         /* posed by a skin (default pose) */
    int primitives_without_normals; /* flat-shaded */
    double position_step;           /* the largest quantization step of a position, in world units (the
                                     * integer unit, or Draco's grid step, times the node's largest
                                     * axis scale); 0 when every position is a float */
    char extensions_used[512];      /* the file's extensionsUsed, ", "-separated */
} gltf_report;

/* gltf_load that also fills *report (may be NULL). */
int gltf_load_report(const char *path, scene *s, gltf_report *report, gt_error *e);
/* The same from the file's bytes in memory: `name` stands for the file in
 * messages (and ".glb" at its end asks for a binary file, as for a path);
 * external buffers and images are looked up in base_dir. */
int gltf_load_memory(const void *bytes, size_t size, const char *name, const char *base_dir, scene *s,
                     gt_error *e);

#endif
