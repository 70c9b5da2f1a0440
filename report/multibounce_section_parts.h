/* The multi-bounce section's parts kept in their own files: the
 * measurements of the talk's shortcuts and assumptions (issue 25), each a
 * subsection, an object of the section's summary.json object and rows of
 * the claims table. Internal to report/. */
#ifndef GTLAB_REPORT_MULTIBOUNCE_SECTION_PARTS_H
#define GTLAB_REPORT_MULTIBOUNCE_SECTION_PARTS_H

#include "report/report_context.h"
#include "studies/multibounce.h"

/* The shader's clamp (item 4; multibounce_clamp_section.c). */
void multibounce_clamp_section(report_context *ctx, const multibounce_study_result *r, cJSON *summary);

/* The bounce count (item 3; multibounce_bounces_section.c). */
void multibounce_bounces_section(report_context *ctx, const multibounce_study_result *r, cJSON *summary);

/* f on GTAO's V_d (item 5; multibounce_gtao_section.c). */
void multibounce_gtao_section(report_context *ctx, const multibounce_study_result *r, cJSON *summary);

/* The premise, albedo contrast (item 1; multibounce_contrast_section.c). */
void multibounce_contrast_section(report_context *ctx, const multibounce_study_result *r, cJSON *summary);

/* Colour (item 2; multibounce_colour_section.c). */
void multibounce_colour_section(report_context *ctx, const multibounce_study_result *r, cJSON *summary);

#endif
