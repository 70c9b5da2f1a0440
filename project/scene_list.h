/* The scenes a study runs over: each entry a scene spec (builtin:NAME or a
 * glTF file), a label that names the study's rows and files, and the camera
 * to render it from. `gtlab all` runs on the built-in study scenes
 * (builtin_study_scene_at, each at its own camera) unless a project file
 * (project/project_file.h) lists the user's scenes; the studies take their
 * scenes from study_context.scenes through these functions only. */
#ifndef GTLAB_PROJECT_SCENE_LIST_H
#define GTLAB_PROJECT_SCENE_LIST_H

#include "core/error.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "project/study_context.h"

enum { STUDY_SCENES_MAX = 16, STUDY_SCENE_LABEL_MAX = 48, STUDY_SCENE_PATH_MAX = 1024 };

typedef struct {
    char spec[STUDY_SCENE_PATH_MAX];        /* builtin:NAME or a .gltf/.glb path */
    char label[STUDY_SCENE_LABEL_MAX];      /* a safe file name (study_scene_label_check) */
    char camera_json[STUDY_SCENE_PATH_MAX]; /* a camera JSON file, or "" */
    int gltf_camera;                        /* -1: none; else the glTF camera of that index */
    char gltf_camera_name[STUDY_SCENE_LABEL_MAX * 2]; /* or of that name ("": none) */
} study_scene_entry;

struct study_scene_list {
    int count;
    study_scene_entry scenes[STUDY_SCENES_MAX];
};

/* The built-in study scenes, labelled by their names, at their own cameras. */
const study_scene_list *study_scenes_builtin(void);
/* ctx->scenes, or the built-in list when it is NULL. */
const study_scene_list *study_scenes_of(const study_context *ctx);
int study_scene_count(const study_context *ctx);
const study_scene_entry *study_scene_at(const study_context *ctx, int index);
/* The entry labelled `label`, or NULL. */
const study_scene_entry *study_scene_find(const study_context *ctx, const char *label);
/* The scene spec of the entry labelled `label` (the label itself if none is:
 * loading it then fails naming it). */
const char *study_scene_spec(const study_context *ctx, const char *label);

/* A label is 1..47 of [A-Za-z0-9_.-], not starting with '.' or '-': it
 * becomes part of file names. 0, or -1 with e naming `what`. */
int study_scene_label_check(const char *label, const char *what, gt_error *e);
/* Appends an entry (label checked, unique in the list); -1 with e naming `what`. */
int study_scene_list_add(study_scene_list *list, const study_scene_entry *entry, const char *what, gt_error *e);

/* Loads the entry's scene and its camera for a width x height image (as
 * scene_choose_camera sizes it). Returns 0 (free s with scene_free), or -1
 * with e set and nothing to free. */
int study_scene_view(const study_scene_entry *entry, int width, int height, scene *s, camera *cam, gt_error *e);

#endif
