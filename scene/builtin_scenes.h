/* Built-in procedural scenes, each with a closed-form or well-known purpose
 * and a camera; `gtlab scene list` prints their exact geometry and
 * `gtlab scene write NAME -o F.glb` writes them as real glTF. */
#ifndef GTLAB_SCENE_BUILTIN_SCENES_H
#define GTLAB_SCENE_BUILTIN_SCENES_H

#include "core/error.h"
#include "scene/scene.h"

typedef struct {
    const char *name;
    const char *description; /* exact geometry, several lines */
    int (*build)(scene *s);  /* 0 on success, -1 out of memory */
} builtin_scene;

int builtin_scene_count(void);
const builtin_scene *builtin_scene_at(int index);
const builtin_scene *builtin_scene_find(const char *name);

/* Builds the named built-in scene. Error names "builtin:NAME" if unknown. */
int builtin_scene_build(const char *name, scene *s, gt_error *e);

#endif
