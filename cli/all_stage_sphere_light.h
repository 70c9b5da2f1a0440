/* The scene part of the sphere-light stage of `gtlab all`
 * (cli/all_stage_sphere_light_scenes.c), called by all_stage_sphere_light. */
#ifndef GTLAB_CLI_ALL_STAGE_SPHERE_LIGHT_H
#define GTLAB_CLI_ALL_STAGE_SPHERE_LIGHT_H

#include "cli/all_stages.h"
#include "realtime/sphere_light.h"

/* Renders the sun and large-light floor scenes into dir, compares Karis,
 * Decima and Decima with `refit`, and adds the report section and json. */
int all_stage_sphere_light_scenes(all_context *ctx, const char *dir, const decima_sphere_constants *refit,
                                  cJSON *json, gt_error *e);

#endif
