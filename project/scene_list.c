#include "project/scene_list.h"

#include <stdio.h>
#include <string.h>
#include <threads.h>

#include "scene/builtin_scene_family.h"
#include "scene/builtin_scenes.h"
#include "scene/gltf/gltf_reader.h"
#include "scene/scene_loaders.h"

static study_scene_list builtin_set;

static void add_builtin(const char *name)
{
    study_scene_entry *x = &builtin_set.scenes[builtin_set.count++];
    snprintf(x->spec, sizeof x->spec, "builtin:%s", name);
    snprintf(x->label, sizeof x->label, "%s", name);
    x->gltf_camera = -1;
}

/* The built-in study scenes, then the family's members, STUDY_SCENES_MAX in all. */
static void fill_builtin_set(void)
{
    for (int i = 0; i < builtin_study_scene_count() && builtin_set.count < STUDY_SCENES_MAX; ++i)
        add_builtin(builtin_study_scene_at(i)->name);
    for (int i = 0; builtin_set.count < STUDY_SCENES_MAX; ++i) {
        char name[STUDY_SCENE_LABEL_MAX];
        family_member_name(i, name, sizeof name);
        add_builtin(name);
    }
}

static const study_scene_list *scenes_of(const study_context *ctx)
{
    static once_flag filled = ONCE_FLAG_INIT;
    if (ctx && ctx->scenes)
        return ctx->scenes;
    call_once(&filled, fill_builtin_set);
    return &builtin_set;
}

int study_scenes_from_project(const study_context *ctx) { return ctx && ctx->scenes; }

int study_scene_count(const study_context *ctx)
{
    if (study_scenes_from_project(ctx))
        return ctx->scenes->count;
    int builtins = builtin_study_scene_count(), wanted = ctx ? ctx->study_scenes : 0;
    return wanted < builtins ? builtins : wanted > STUDY_SCENES_MAX ? STUDY_SCENES_MAX : wanted;
}

const study_scene_entry *study_scene_at(const study_context *ctx, int index)
{
    return index >= 0 && index < study_scene_count(ctx) ? &scenes_of(ctx)->scenes[index] : NULL;
}

const study_scene_entry *study_scene_find(const study_context *ctx, const char *label)
{
    for (int i = 0; i < study_scene_count(ctx); ++i)
        if (strcmp(study_scene_at(ctx, i)->label, label) == 0)
            return study_scene_at(ctx, i);
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
