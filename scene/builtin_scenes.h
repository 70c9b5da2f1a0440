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
    int outside_studies;     /* 1: not in the studies' list (terrain: km scale, for the fog) */
} builtin_scene;

/* Every built-in scene, in table order (`gtlab scene list`). */
int builtin_scene_count(void);
const builtin_scene *builtin_scene_at(int index);
/* The scenes the studies run over (every scene but those outside_studies),
 * in table order: a scene added for one technique does not change the
 * other studies' results. */
int builtin_study_scene_count(void);
const builtin_scene *builtin_study_scene_at(int index);
const builtin_scene *builtin_scene_find(const char *name);

/* Builds the named built-in scene. Error names "builtin:NAME" if unknown. */
int builtin_scene_build(const char *name, scene *s, gt_error *e);

#endif
