/* The scenes a study runs over: each entry a scene spec (builtin:NAME or a
 * glTF file), a label that names the study's rows and files, and the camera
 * to render it from. Unless a project file (project/project_file.h) lists the
 * user's scenes, `gtlab all` runs on the built-in set: the built-in study
 * scenes (builtin_study_scene_at), then members of the procedural family
 * (scene/builtin_scene_family.h, family_member_name's order: room-0,
 * railing-0, ..., terrain-0, room-1, ...), study_context.study_scenes in all
 * (the quality table's `ao study_scenes`), each at its own camera and
 * labelled by its name. The studies take their scenes from the context
 * through these functions only. */
#ifndef GTLAB_PROJECT_SCENE_LIST_H
#define GTLAB_PROJECT_SCENE_LIST_H

#include "core/error.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "project/study_context.h"

enum { STUDY_SCENES_MAX = 32, STUDY_SCENE_LABEL_MAX = 48, STUDY_SCENE_PATH_MAX = 1024 };

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

/* How many scenes the studies run over: ctx->scenes' count, else
 * ctx->study_scenes (at least the built-in study scenes, at most
 * STUDY_SCENES_MAX); a NULL ctx is the built-in study scenes. */
int study_scene_count(const study_context *ctx);
/* The index-th of them, or NULL past the last. */
const study_scene_entry *study_scene_at(const study_context *ctx, int index);
/* Whether the scenes are a project's (the user's) rather than the built-in set. */
int study_scenes_from_project(const study_context *ctx);
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
