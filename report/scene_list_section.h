/* The scenes of a run (project/scene_list.h) at the top of the report:
 * when `gtlab all --project` gave the user's scenes, a table of each entry's
 * label, scene file and camera, and in summary.json "project" (the file, its
 * scenes, and the shaders and plug-ins it lists). Without one, a sentence
 * naming the built-in set the scene-driven sections run on (the built-in
 * study scenes and the procedural family's members, with how to write each
 * as glTF), and summary.json "study_scenes", their names. */
#ifndef GTLAB_REPORT_SCENE_LIST_SECTION_H
#define GTLAB_REPORT_SCENE_LIST_SECTION_H

#include "report/report_context.h"
#include "project/project_file.h"

/* parent's "scenes": the names of the scenes a section averaged over, so
 * that summary.json says which scenes (a project's, or the built-in ones)
 * stand behind every section. */
void scene_names_json(cJSON *parent, const char (*names)[64], int count);

/* path: the project file, or NULL. */
void scene_list_section(report_context *ctx, const study_project *project, const char *path);

#endif
