/* What every study shares. A study is one technique's experiment as a
 * function: it renders its references, runs its approximations and fits, and
 * returns a plain results struct (techniques/<name>/<name>_study.h). It writes its data
 * files (references, previews, error maps) under the output folder, and
 * nothing else: no report, no JSON, no plot. cli/ renders the results into
 * the report and summary.json; tests check the numbers without any prose. */
#ifndef GTLAB_PROJECT_STUDY_CONTEXT_H
#define GTLAB_PROJECT_STUDY_CONTEXT_H

#include <stddef.h>

#include "core/error.h"
#include "scene/camera.h"
#include "scene/scene.h"

typedef enum { QUALITY_PREVIEW, QUALITY_PRODUCTION } study_quality;
enum { STUDY_QUALITY_COUNT = 2 };

/* "preview" or "production", as --quality and the project file spell it.
 * What each means is techniques/quality_table.txt. */
const char *study_quality_name(study_quality quality);

typedef struct study_scene_list study_scene_list; /* project/scene_list.h */
typedef struct study_project study_project;       /* project/project_file.h */

typedef struct {
    const char *output_dir; /* everything a study writes goes below it */
    study_quality quality;
    int threads;            /* results do not depend on it */
    const study_scene_list *scenes; /* the scenes the studies run over; NULL: the built-in ones */
    const study_project *project;   /* the project file (its shaders and plug-ins); NULL: none */
    int study_scenes; /* without a project's scenes: how many the studies run over, the built-in study
                         scenes first, then the procedural family's members in order (room-0,
                         railing-0, ...; project/scene_list.h); 0: the built-in study scenes only */
} study_context;

/* "<output_dir>/<sub>" with the folder created. */
int study_make_dir(const study_context *ctx, const char *sub, char *path, size_t size, gt_error *e);

/* Scene `spec` (builtin:NAME or a glTF file) and its default camera for a
 * width x height image, as the benchmarks measure on them. Returns 0 (free
 * s with scene_free), or -1 with e set and nothing to free. */
int study_load_view(const char *spec, int width, int height, scene *s, camera *cam, gt_error *e);

#endif
