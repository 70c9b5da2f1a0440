#include "report/scene_list_section.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "report/report_table.h"
#include "scene/builtin_scenes.h"

/* "its own", "glTF camera 2", "glTF camera 'Top'" or the camera file. */
static void camera_cell(const void *row, char *text, size_t size)
{
    const study_scene_entry *x = row;
    if (x->camera_json[0])
        snprintf(text, size, "%s", x->camera_json);
    else if (x->gltf_camera_name[0])
        snprintf(text, size, "glTF camera '%s'", x->gltf_camera_name);
    else if (x->gltf_camera >= 0)
        snprintf(text, size, "glTF camera %d", x->gltf_camera);
    else
        snprintf(text, size, "the scene's own");
}

static const report_column columns[] = {
    REPORT_TEXT("label", "label", study_scene_entry, label),
    REPORT_TEXT("scene", "scene", study_scene_entry, spec),
    REPORT_CELL("camera", camera_cell),
    REPORT_TEXT(NULL, "camera_json", study_scene_entry, camera_json),
    REPORT_INT(NULL, "gltf_camera", study_scene_entry, gltf_camera),
    REPORT_TEXT(NULL, "gltf_camera_name", study_scene_entry, gltf_camera_name),
};

/* A list of file names as a JSON array. */
static cJSON *files_json(const char (*files)[STUDY_SCENE_PATH_MAX], int count)
{
    cJSON *a = cJSON_CreateArray();
    for (int i = 0; i < count; ++i)
        cJSON_AddItemToArray(a, cJSON_CreateString(files[i]));
    return a;
}

void scene_names_json(cJSON *parent, const char (*names)[64], int count)
{
    cJSON *a = cJSON_AddArrayToObject(parent, "scenes");
    for (int i = 0; i < count; ++i)
        cJSON_AddItemToArray(a, cJSON_CreateString(names[i]));
}

/* The project's screen shaders: [{"path": ..., "params": {"name": value, ...}}, ...]. */
static cJSON *screen_shaders_json(const study_project *project)
{
    cJSON *a = cJSON_CreateArray();
    for (int i = 0; i < project->screen_shader_count; ++i) {
        const study_screen_shader *x = &project->screen_shaders[i];
        cJSON *o = cJSON_CreateObject(), *params;
        cJSON_AddItemToArray(a, o);
        cJSON_AddStringToObject(o, "path", x->path);
        params = cJSON_AddObjectToObject(o, "params");
        for (int k = 0; k < x->param_count; ++k) {
            const char *eq = strchr(x->params[k], '=');
            char name[PROJECT_PARAM_TEXT];
            snprintf(name, sizeof name, "%.*s", (int)(eq - x->params[k]), x->params[k]);
            cJSON_AddNumberToObject(params, name, strtod(eq + 1, NULL));
        }
    }
    return a;
}

/* The built-in set in the report ("the 6 study scenes (plane, ...) and 2
 * members of the procedural family (room-0, railing-0)"), every name in
 * summary.json's "study_scenes". */
static void builtin_set_section(report_context *ctx)
{
    const int count = study_scene_count(&ctx->study), builtins = builtin_study_scene_count();
    char lists[2][STUDY_SCENES_MAX * STUDY_SCENE_LABEL_MAX] = {"", ""};
    cJSON *json = cJSON_AddArrayToObject(ctx->summary, "study_scenes");
    for (int i = 0; i < count; ++i) {
        const char *label = study_scene_at(&ctx->study, i)->label;
        char *list = lists[i >= builtins];
        size_t used = strlen(list);
        snprintf(list + used, sizeof lists[0] - used, "%s%s", used ? ", " : "", label);
        cJSON_AddItemToArray(json, cJSON_CreateString(label));
    }
    char family[sizeof lists[1] + 128] = "";
    if (count > builtins)
        snprintf(family, sizeof family, " and %d member%s of the procedural family (%s; each deterministic from its "
                 "seed)", count - builtins, count - builtins == 1 ? "" : "s", lists[1]);
    report_paragraph(ctx->doc,
                     "The scene-driven sections run on %d built-in scenes: the %d study scenes (%s)%s. The other "
                     "sections keep their purpose-built scenes. 'gtlab scene list' describes every scene; 'gtlab "
                     "scene write NAME -o NAME.glb' writes it as glTF for any other renderer.",
                     count, builtins, lists[0], family);
}

void scene_list_section(report_context *ctx, const study_project *project, const char *path)
{
    const int from_project = study_scenes_from_project(&ctx->study);
    if (!from_project)
        builtin_set_section(ctx);
    if (!path)
        return;
    const int count = from_project ? study_scene_count(&ctx->study) : 0;
    cJSON *json = cJSON_AddObjectToObject(ctx->summary, "project");
    cJSON_AddStringToObject(json, "file", path);
    cJSON *rows = cJSON_AddArrayToObject(json, "scenes");
    if (from_project) {
        report_paragraph(ctx->doc, "The scene-driven sections run on the %d scene view%s of the project file %s "
                         "(the other sections keep their purpose-built scenes):", count,
                         count == 1 ? "" : "s", path);
        report_rows(ctx->doc, rows, columns, (int)(sizeof columns / sizeof columns[0]),
                    study_scene_at(&ctx->study, 0), sizeof(study_scene_entry), count);
    }
    cJSON_AddItemToObject(json, "shaders", files_json((const char(*)[STUDY_SCENE_PATH_MAX])project->shaders,
                                                      project->shader_count));
    cJSON_AddItemToObject(json, "plugins", files_json((const char(*)[STUDY_SCENE_PATH_MAX])project->plugins,
                                                      project->plugin_count));
    cJSON_AddItemToObject(json, "screen_shaders", screen_shaders_json(project));
}
