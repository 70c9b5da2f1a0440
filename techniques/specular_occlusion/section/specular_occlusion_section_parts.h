/* The specular-occlusion section's parts kept in their own files: the
 * talk's statements it measures (issue 26), each a subsection, an object of
 * the section's summary.json object and rows of the claims table. Internal
 * to report/. */
#ifndef GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_SECTION_PARTS_H
#define GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_SECTION_PARTS_H

#include <cjson/cJSON.h>

#include "report/claim_thresholds.h"
#include "report/claims_table.h"
#include "report/report_context.h"
#include "specular_occlusion/specular_occlusion_study.h"

/* What the claim records of the section share (docs/claims-protocol.md):
 * the talk, and its setting for specular occlusion (seed 001, "GTSO" to
 * "Ground Truth Specular Occlusion") against gtlab's. */
#define SO_TALK "Jimenez et al. 2016 (GTAO)"
#define SO_SETTING                                                                                                    \
    "GTSO on a character's face lit by a probe, compared as images with a Monte Carlo reference; the cone/cone "   \
    "and cone/lobe comparisons with Phong ('as the previous work used Phong for gloss to aperture calculations'), " \
    "the final formulation with GGX; V_s baked into a 32x32x32 BC4 table of (alpha_v, beta, r)"
#define SO_SETTING_NOTE                                                                                               \
    "gtlab's built-in study scenes, not the talk's face, at the quality table's image size, each pixel's samples " \
    "stopping at its noise budget (the section states both), under the analytic sky, the three roughnesses 0.25, " \
    "0.5 and 0.8"

/* The talk's rankings and the gloss bands (items 2 and 3;
 * specular_occlusion_rankings_section.c). */
void so_rankings_section(report_context *ctx, const so_study_result *r, cJSON *summary);

/* The visibility cone and the dropped view angle (items 1 and 5;
 * specular_occlusion_cone_view_section.c). */
void so_cone_view_section(report_context *ctx, const so_study_result *r, cJSON *summary);

#endif
