/* The sphere-light section's parts kept in their own files: the talk's
 * statements it measures (issue 26), each a subsection, an object of the
 * section's summary.json object and rows of the claims table. Internal to
 * report/. */
#ifndef GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_SECTION_PARTS_H
#define GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_SECTION_PARTS_H

#include <cjson/cJSON.h>

#include "report/report_context.h"
#include "sphere_light/sphere_light_study.h"

/* Near the terminator (item 8; sphere_light_terminator_section.c). */
void sphere_terminator_section(report_context *ctx, const sphere_terminator_result *t, cJSON *summary);

/* The normalisation's units (item 7; sphere_light_units_section.c). */
void sphere_units_section(report_context *ctx, const sphere_units_result *u, cJSON *summary);

/* The sun at grazing angles (item 9; sphere_light_sun_section.c). */
void sphere_sun_section(report_context *ctx, const sphere_sun_result *s, cJSON *summary);

/* LTC sphere lights (issue 27, item 2; sphere_light_ltc_section.c): the
 * table's fit, the held-out scores with paired differences, the N-gon's
 * error and the cost per pixel. */
void sphere_ltc_section(report_context *ctx, const sphere_light_result *r, cJSON *summary);

/* The held-out headline of the section: the four methods ranked by mean
 * |log error|, the gap between the two best from their difference paired
 * over the held-out configurations. */
void sphere_ltc_headline(report *doc, const sphere_light_result *r);

#endif
