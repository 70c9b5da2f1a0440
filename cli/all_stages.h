/* The stages of `gtlab all`: each renders, fits or measures what it owns,
 * writes its files under the output folder, adds its section to the report
 * and its figures to summary.json. Later work adds stages to the table in
 * verb_all.c. */
#ifndef GTLAB_CLI_ALL_STAGES_H
#define GTLAB_CLI_ALL_STAGES_H

#include <cjson/cJSON.h>

#include "cli/report_writer.h"
#include "core/error.h"
#include "studies/study.h"

typedef struct {
    study_context study; /* output folder, quality, threads: what the studies see */
    report *doc;
    cJSON *summary; /* summary.json: one member per stage */
} all_context;

/* AO and bent-normal references of every built-in scene. */
int all_stage_ao_references(all_context *ctx, gt_error *e);
/* Multi-bounce references, the GTAO multi-bounce refit and its validation. */
int all_stage_multibounce(all_context *ctx, gt_error *e);
/* Specular occlusion: references, every variant scored, LUT axes, aperture fit. */
int all_stage_specular_occlusion(all_context *ctx, gt_error *e);
/* Ray throughput: raw Embree against the AO reference loop. */
int all_stage_ray_throughput(all_context *ctx, gt_error *e);

/* GGX sphere lights: GetNoHSquared accuracy, Decima refit, error maps, cost. */
int all_stage_sphere_light(all_context *ctx, gt_error *e);

/* GTAO, HBAO and VO against the height-field and 3-D AO references. */
int all_stage_gtao(all_context *ctx, gt_error *e);

#endif
