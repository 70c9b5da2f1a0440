/* The project file (gtlab.json, docs/design.md "Project file", schema
 * docs/gtlab.schema.json): the user's scenes, each with one or more
 * cameras, and what `gtlab all --project` runs on them — its stages, quality
 * and output folder — with the user's shaders and plug-ins (validated,
 * recorded, scored by techniques/shader/shader_scores.h) and screen-space
 * shaders (compiled, scored by techniques/shader/screen_shader_score.h).
 * Paths in the file are relative to the file's folder. Keys starting with
 * '_' are comments; any other unknown key is an error, as is every
 * problem, named by the file and the JSON path of the value at fault
 * ("gtlab.json: scenes[0].cameras[1].gltf: no camera named 'Top'"). */
#ifndef GTLAB_PROJECT_PROJECT_FILE_H
#define GTLAB_PROJECT_PROJECT_FILE_H

#include "core/error.h"
#include "scoring/screen_shader_program.h"
#include "project/scene_list.h"

enum { PROJECT_MAX_FILES = 16, PROJECT_STAGES_MAX = 512, PROJECT_MAX_PARAMS = 16, PROJECT_PARAM_TEXT = 96 };

/* A screen-space shader of the project (`screen_shaders`, docs/shaders.md's
 * contract): scored by the stage screen-shaders on the AO references. */
typedef struct {
    char path[STUDY_SCENE_PATH_MAX];
    int param_count;
    char params[PROJECT_MAX_PARAMS][PROJECT_PARAM_TEXT]; /* "name=value", as --param takes them */
} study_screen_shader;

/* s compiled with its parameters, scored on ao.V (scoring/screen_shader_program.h). */
int study_screen_shader_prepare(const study_screen_shader *s, screen_shader_program *out, gt_error *e);

typedef struct study_project {
    study_scene_list scenes;        /* one entry per scene and camera */
    char stages[PROJECT_STAGES_MAX]; /* comma-separated stage keys; "" when the file names none */
    int quality;                    /* a study_quality, or -1 when the file names none */
    char output_dir[STUDY_SCENE_PATH_MAX]; /* "" when the file names none */
    int shader_count, plugin_count;
    char shaders[PROJECT_MAX_FILES][STUDY_SCENE_PATH_MAX];
    char plugins[PROJECT_MAX_FILES][STUDY_SCENE_PATH_MAX];
    int screen_shader_count;
    study_screen_shader screen_shaders[PROJECT_MAX_FILES];
} study_project;

/* Whether `key` names a stage (the caller's registry); when it does not
 * but a stage went by that name before, *now is the stage's name today,
 * else NULL. NULL: any name. */
typedef int (*study_project_stage_known)(const char *key, const char **now);

/* Reads and checks the project file: its JSON, every key and value, that
 * each scene file and camera file exists, and that each scene loads with
 * each of its cameras, and that each screen shader compiles with its
 * parameters and writes ao.V (so a run fails before any work). Returns 0, or -1
 * with e = "<path>: <json path>: <problem>". p is large: give a static one. */
int study_project_read(const char *path, study_project_stage_known known, study_project *p, gt_error *e);

/* The project's scenes into ctx, and its quality, output folder and stage
 * list where the command line gave none (ctx->quality < 0, output_dir NULL,
 * *stage_list NULL); then the defaults: preview, "results", every stage.
 * p NULL: no project (the built-in scenes). */
void study_project_apply(const study_project *p, study_context *ctx, const char **stage_list);

/* The commented example `gtlab init` writes: it runs as written (the
 * built-in sphere-on-plane at its own camera, the ao and gtao stages). */
const char *study_project_example(void);
/* Writes the example to path, refusing to overwrite an existing file. */
int study_project_write_example(const char *path, gt_error *e);

#endif
