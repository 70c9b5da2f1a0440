/* The GTAO section's part on the talk's bent-normal estimators (issue 25,
 * item 10; gtao_bent_normals.h): angular error against the 3-D
 * reference per scene and estimator, paired differences, the claims row. */
#include <math.h>
#include <stdio.h>

#include "gtao/gtao_checks_section.h"
#include "report/claim_thresholds.h"
#include "report/report_table.h"

#define COLUMNS(c) (int)(sizeof(c) / sizeof((c)[0]))

static const report_column columns[] = {
    REPORT_TEXT("scene", "scene", bent_row, scene),
    REPORT_TEXT("estimator", "estimator", bent_row, estimator),
    REPORT_REAL("mean angle to the reference (deg)", "mean_angle", "%.2f", bent_row, angle.mean),
    REPORT_REAL("s.e. (8x8 blocks)", "mean_angle_se", "%.2f", bent_row, angle.se),
    REPORT_REAL("median (deg)", "median_angle", "%.2f", bent_row, median),
    REPORT_REAL("90th percentile (deg)", "p90_angle", "%.2f", bent_row, p90),
    REPORT_REAL("minus the arc mean's (deg)", "vs_arc_mean", "%+.2f", bent_row, vs_arc_mean.mean),
    REPORT_REAL("s.e.", "vs_arc_mean_se", "%.2f", bent_row, vs_arc_mean.se),
};

/* Claim: the faster estimator (averaged angles) stands in for the average
 * of the horizon vectors: as good, within one code value of a bent normal
 * stored in an RGBA8 target. */
static const claim_record bent_claim = {
    .talk = "Jimenez et al. 2016 (GTAO)",
    .seed = "001",
    .section = "Bent Normal",
    .quote = "Average of horizon vectors: ... Or faster: average both horizon angles and recover 3d vector",
    .setting = "the bent normal GTAO returns beside its AO for the specular occlusion's visibility cone, from the "
               "same horizons, at 1080p (half resolution)",
    .setting_match = CLAIM_SETTING_INDEPENDENT,
    .setting_note = "GTAO with regular slices and no denoiser on gtlab's preview scenes, angles to the 3-D "
                    "reference's bent normal: both estimators read the same two horizon angles per slice, so their "
                    "difference is a function of those angles, which the resolution does not change",
    .reading = "the faster estimator is offered in place of the average of the horizon vectors, so its angle to "
               "the true bent normal should be no larger, within a visible angle",
    .form = CLAIM_AS_GOOD,
    .margin = CLAIM_ONE_CODE_VALUE_8BIT_NORMAL_DEG,
    .tolerance_source = CLAIM_TOLERANCE_TALK_COMPARISON,
    .tolerance = "as good as the horizon vectors' average, within one code value of a normal in an RGBA8 target "
                 "(CLAIM_ONE_CODE_VALUE_8BIT_NORMAL_DEG, 0.45 deg)"};

static void add_claim(report_context *ctx, const gtao_bent_normals_result *r)
{
    claims_table_add(ctx->claims, &bent_claim, r->pooled_halfway_vs_horizons.mean, r->pooled_halfway_vs_horizons.se,
                     "angle to the 3-D reference's bent normal of the averaged horizon angles minus that of the "
                     "averaged horizon vectors, degrees, pooled over %d scenes (8x8-block s.e.)",
                     r->scene_count);
}

void gtao_bent_normals_section(report_context *ctx, const gtao_bent_normals_result *r, cJSON *summary)
{
    cJSON *o = cJSON_AddObjectToObject(summary, "bent_normals");
    report_heading(ctx->doc, 3, "Bent normals: the talk's estimators");
    report_paragraph(
        ctx->doc,
        "GTAO with %d regular slices x %d samples per side (no pattern, no denoiser, no radius limit), three "
        "estimators on the same horizons: the talk's average of the two horizon vectors per slice (each slice "
        "then points halfway between its horizons with length cos of half its open angle, so open slices count "
        "for nothing); the talk's faster averaged horizon angles (the halfway direction weighted by the slice's "
        "visibility); and gtlab's cosine-weighted mean direction of the visible arc, the reference's own "
        "definition. Angles to the 3-D reference's bent normal (which includes its Monte Carlo noise and the "
        "height-field assumption's error), pooled over the scenes: horizon vectors %.2f ± %.2f deg, averaged "
        "angles %.2f ± %.2f, arc mean %.2f ± %.2f. Averaged angles minus horizon vectors: %+.2f ± %.2f deg.",
        r->slices, r->steps, r->pooled_angle[BENT_HORIZON_VECTORS].mean, r->pooled_angle[BENT_HORIZON_VECTORS].se,
        r->pooled_angle[BENT_HALFWAY_ANGLES].mean, r->pooled_angle[BENT_HALFWAY_ANGLES].se,
        r->pooled_angle[BENT_ARC_MEAN].mean, r->pooled_angle[BENT_ARC_MEAN].se, r->pooled_halfway_vs_horizons.mean,
        r->pooled_halfway_vs_horizons.se);
    report_rows(ctx->doc, cJSON_AddArrayToObject(o, "rows"), columns, COLUMNS(columns), r->rows, sizeof r->rows[0][0],
                r->scene_count * BENT_ESTIMATORS);
    cJSON_AddNumberToObject(o, "pooled_halfway_minus_horizons", r->pooled_halfway_vs_horizons.mean);
    cJSON_AddNumberToObject(o, "pooled_halfway_minus_horizons_se", r->pooled_halfway_vs_horizons.se);
    add_claim(ctx, r);
}
