/* The project's screen-space shaders (issue 15, item 6): the section "Your
 * screen-space shaders: ambient occlusion", one table with a row per
 * variant — gtlab's C GTAO, then each file of the project's
 * `screen_shaders` — scored as the GTAO study scores its own variants
 * (screen_shader_score.h), and summary.json's
 * `screen_shader_scores`. A run without screen shaders adds nothing. */
#ifndef GTLAB_SHADER_SCREEN_SHADER_SECTION_H
#define GTLAB_SHADER_SCREEN_SHADER_SECTION_H

#include "report/report_context.h"
#include "shader/screen_shader_score.h"

/* A variant's verdict against GTAO (C): "better"/"worse" past significance
 * and a visible margin (one 8-bit code value of RMSE), "no visible
 * difference", "not significant", or "-" for GTAO (C) itself. */
const char *screen_shader_verdict(const screen_shader_variant *x, const screen_shader_variant *gtao);

/* Adds the section (nothing when r->variant_count == 0); returns 0. */
int screen_shader_section(report_context *ctx, const screen_shader_score_result *r, gt_error *e);

#endif
