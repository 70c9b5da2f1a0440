/* What gtlab made of a scene, for people (`gtlab scene list` and `gtlab
 * scene info`): a built-in scene's name and description, a loaded scene's
 * meshes, triangles, materials and which meshes had no normals (flat-
 * shaded, as glTF 2.0 requires), and how a glTF file was read (extensions,
 * primitive modes, quantized and compressed data, sparse accessors, morph
 * targets, skins). */
#ifndef GTLAB_SCENE_SCENE_DESCRIBE_H
#define GTLAB_SCENE_SCENE_DESCRIBE_H

#include <stdio.h>

#include "scene/builtin_scenes.h"
#include "scene/gltf/gltf_reader.h"

void builtin_scene_describe(FILE *f, const builtin_scene *b);
void scene_describe(FILE *f, const scene *s);
void gltf_report_describe(FILE *f, const gltf_report *r);

#endif
