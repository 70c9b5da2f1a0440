/* Loading a scene by its spec: "builtin:NAME" (builtin_scenes.h) or the path
 * of a .gltf/.glb file (gltf_reader.h). scene_loaders.c holds the table of
 * loaders and walks it; scene.c, below it, knows no file format. Adding a
 * format is a new file with its loader plus one line in that table. */
#ifndef GTLAB_SCENE_SCENE_LOADERS_H
#define GTLAB_SCENE_SCENE_LOADERS_H

#include "core/error.h"
#include "scene/scene.h"

/* Loads the scene the spec names into s (which need not be initialised) and
 * validates it (scene_validate). Returns 0, or -1 with e set and s empty. */
int scene_load(const char *spec, scene *s, gt_error *e);

#endif
