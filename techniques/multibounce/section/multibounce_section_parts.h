/* The multi-bounce section's parts kept in their own files: the
 * measurements of the talk's shortcuts and assumptions (issue 25), each a
 * subsection, an object of the section's summary.json object and rows of
 * the claims table. Internal to report/. */
#ifndef GTLAB_MULTIBOUNCE_MULTIBOUNCE_SECTION_PARTS_H
#define GTLAB_MULTIBOUNCE_MULTIBOUNCE_SECTION_PARTS_H

#include "multibounce/multibounce_study.h"
#include "report/claim_thresholds.h"
#include "report/claims_table.h"
#include "report/report_context.h"

/* What the claim records of the section share (docs/claims-protocol.md):
 * the talk, and its setting for the multi-bounce fit (seed 001, "Multiple
 * Bounces" to "Final Fit Over All Data") against gtlab's. */
#define MB_TALK "Jimenez et al. 2016 (GTAO)"
#define MB_SETTING                                                                                                    \
    "single- and multi-bounce (4 bounces) Monte Carlo references under a white dome, every surface of one albedo, " \
    "seven albedos from 0.1 to 0.9; first a human head, then a larger dataset of scenes fitted jointly (the fits "  \
    "of single scenes 'not exactly the same'); a cubic in V_d, its coefficients linear in the albedo; for GTAO's "  \
    "output in engine"
#define MB_SETTING_NOTE                                                                                               \
    "gtlab's five built-in scenes (sphere-on-plane, corner, menger, boxes, cornell), not the talk's head and "     \
    "dataset, at the quality table's image size, each pixel's paths stopping at its noise budget (the section "   \
    "states both), albedos 0.1, 0.2, 0.3, 0.4, 0.5, 0.7, 0.9"

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
