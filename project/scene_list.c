#include "project/scene_list.h"

#include <stdio.h>
#include <string.h>

#include "scene/builtin_scenes.h"
#include "scene/gltf/gltf_reader.h"
#include "scene/scene_loaders.h"

const study_scene_list *study_scenes_builtin(void)
{
    static study_scene_list list;
    if (list.count == 0)
        for (int i = 0; i < builtin_study_scene_count() && list.count < STUDY_SCENES_MAX; ++i, ++list.count) {
            study_scene_entry *x = &list.scenes[list.count];
            snprintf(x->spec, sizeof x->spec, "builtin:%s", builtin_study_scene_at(i)->name);
            snprintf(x->label, sizeof x->label, "%s", builtin_study_scene_at(i)->name);
            x->gltf_camera = -1;
        }
    return &list;
}

const study_scene_list *study_scenes_of(const study_context *ctx)
{
    return ctx && ctx->scenes ? ctx->scenes : study_scenes_builtin();
}

int study_scene_count(const study_context *ctx) { return study_scenes_of(ctx)->count; }

const study_scene_entry *study_scene_at(const study_context *ctx, int index)
{
    const study_scene_list *list = study_scenes_of(ctx);
    return index >= 0 && index < list->count ? &list->scenes[index] : NULL;
}

const study_scene_entry *study_scene_find(const study_context *ctx, const char *label)
{
    const study_scene_list *list = study_scenes_of(ctx);
    for (int i = 0; i < list->count; ++i)
        if (strcmp(list->scenes[i].label, label) == 0)
            return &list->scenes[i];
    return NULL;
}

const char *study_scene_spec(const study_context *ctx, const char *label)
{
    const study_scene_entry *x = study_scene_find(ctx, label);
    return x ? x->spec : label;
}

int study_scene_label_check(const char *label, const char *what, gt_error *e)
{
    size_t n = strlen(label);
    if (n == 0 || n >= STUDY_SCENE_LABEL_MAX)
        return gt_error_set(e, what, "label '%s' must be 1 to %d characters", label, STUDY_SCENE_LABEL_MAX - 1);
    if (label[0] == '.' || label[0] == '-')
        return gt_error_set(e, what, "label '%s' must not start with '%c'", label, label[0]);
    if (strspn(label, "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_.-") != n)
        return gt_error_set(e, what, "label '%s' may hold only letters, digits, '_', '.' and '-'", label);
    return 0;
}

int study_scene_list_add(study_scene_list *list, const study_scene_entry *entry, const char *what, gt_error *e)
{
    if (study_scene_label_check(entry->label, what, e) != 0)
        return -1;
    if (list->count == STUDY_SCENES_MAX)
        return gt_error_set(e, what, "more than %d scenes", STUDY_SCENES_MAX);
    for (int i = 0; i < list->count; ++i)
        if (strcmp(list->scenes[i].label, entry->label) == 0)
            return gt_error_set(e, what, "label '%s' is used twice", entry->label);
    list->scenes[list->count++] = *entry;
    return 0;
}

int study_scene_view(const study_scene_entry *entry, int width, int height, scene *s, camera *cam, gt_error *e)
{
    const gltf_camera_choice choice = {entry->gltf_camera, entry->gltf_camera_name[0] ? entry->gltf_camera_name : NULL};
    const int chosen = choice.index >= 0 || choice.name;
    if (chosen && strncmp(entry->spec, "builtin:", 8) == 0)
        return gt_error_set(e, entry->spec, "a built-in scene has one camera: give no glTF camera");
    if ((chosen ? gltf_load_with_camera(entry->spec, &choice, s, e) : scene_load(entry->spec, s, e)) != 0)
        return -1;
    const char *json = entry->camera_json[0] ? entry->camera_json : NULL;
    if (scene_choose_camera(s, json, width, height, cam, e) != 0) {
        scene_free(s);
        return -1;
    }
    return 0;
}
