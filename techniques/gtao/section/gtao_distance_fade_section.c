/* The GTAO section's part on the talk's conservative distance fade (issue
 * 25, item 12; gtao_distance_fade.h): GTAO with the fade against a
 * reference with the same fade and against the unbounded one, and the
 * claims row. */
#include <math.h>
#include <stdio.h>

#include "gtao/gtao_checks_section.h"
#include "report/claim_thresholds.h"
#include "report/report_table.h"

#define COLUMNS(c) (int)(sizeof(c) / sizeof((c)[0]))

static const report_column columns[] = {
    REPORT_TEXT("scene", "scene", fade_row, scene),
    REPORT_REAL("fade from", "fade_start", "%.3g", fade_row, fade_start),
    REPORT_REAL("fade to", "fade_end", "%.3g", fade_row, fade_end),
    REPORT_REAL("RMSE vs faded reference", "rmse_faded", "%.4f", fade_row, rmse_faded),
    REPORT_REAL("RMSE vs unbounded reference", "rmse_unbounded", "%.4f", fade_row, rmse_unbounded),
    REPORT_REAL("mean GTAO - faded reference", "signed_vs_faded", "%+.4f", fade_row, signed_vs_faded.mean),
    REPORT_REAL("s.e.", "signed_vs_faded_se", "%.4f", fade_row, signed_vs_faded.se),
    REPORT_REAL("mean faded - unbounded reference", "reference_gap", "%+.4f", fade_row, reference_gap.mean),
    REPORT_REAL("mean GTAO faded - GTAO cut off", "gtao_change", "%+.4f", fade_row, gtao_change.mean),
    REPORT_REAL("mean faded - cut-off reference", "reference_change", "%+.4f", fade_row, reference_change.mean),
    REPORT_REAL("the fade's change, GTAO - reference", "change_vs_truth", "%+.4f", fade_row, change_vs_truth.mean),
    REPORT_REAL("s.e.  ", "change_vs_truth_se", "%.4f", fade_row, change_vs_truth.se),
    REPORT_REAL("scoring bias (MSE unbounded - MSE faded)", "scoring_bias", "%+.2e", fade_row, scoring_bias.mean),
    REPORT_REAL("s.e. ", "scoring_bias_se", "%.1e", fade_row, scoring_bias.se),
};

/* Claim: the conservative attenuation keeps the near occlusion ground
 * truth. Scored as the soft clamp's own change (issue 42): what it does to
 * GTAO (faded - cut off hard at the same distance, the same samples)
 * against what the same fade does to the truth (faded - cut-off 3-D
 * reference), so GTAO's own error at that radius cancels. */
static const claim_record fade_claim = {
    .talk = "Jimenez et al. 2016 (GTAO)",
    .seed = "001",
    .section = "Minimizing Artifacts",
    .quote = "Conservative attenuation - Soft-clamp integration sampling distance - 150 inches of full effect - From "
             "150 to 200 soften sample contribution from 1 to 0 - Ensure ground truth near occlusion",
    .setting = "game levels measured in inches, 1080p at half resolution, GTAO's horizon samples faded from 150 to "
               "200 inches; the occlusion beyond comes from the baked lighting",
    .setting_match = CLAIM_SETTING_INDEPENDENT,
    .setting_note = "gtlab's 256x256 preview scenes with the fade's end D a quarter of the camera's distance to its "
                    "target and its start 0.75 D (the talk's 150/200); the fade weighs samples by their distance "
                    "in the world and GTAO places its samples at fractions of the projected radius, so the image's "
                    "resolution changes which depth texel a sample reads, not the fade it gets",
    .reading = "with the soft clamp the occlusion within the full-effect range stays ground truth, only the band "
               "from 0.75 D to D being softened",
    .stronger_reading = "that softening GTAO's samples from 0.75 D to D (instead of cutting them off at D) changes its "
                        "AO as the same fade of the occluders changes the truth's, within one 8-bit code value on "
                        "average: the talk does not say how its band compares with the truth's",
    .form = CLAIM_RANGE,
    .low = -CLAIM_ONE_CODE_VALUE_8BIT,
    .high = CLAIM_ONE_CODE_VALUE_8BIT,
    .tolerance_source = CLAIM_TOLERANCE_VISIBILITY,
    .tolerance = "one code value of an 8-bit AO target either way (CLAIM_ONE_CODE_VALUE_8BIT)"};

static void add_claim(report_context *ctx, const gtao_distance_fade_result *r)
{
    claims_table_add(ctx->claims, &fade_claim, r->pooled_change_vs_truth.mean, r->pooled_change_vs_truth.se,
                     "mean of (GTAO with the fade - the same GTAO cut off hard at the fade's end) - (3-D reference "
                     "with the same fade - one cut off hard there), pooled over %d scenes (8x8-block s.e.); GTAO's "
                     "own change %+.4f, the reference's %+.4f",
                     r->scene_count, r->pooled_gtao_change.mean, r->pooled_reference_change.mean);
}

void gtao_distance_fade_section(report_context *ctx, const gtao_distance_fade_result *r, cJSON *summary)
{
    cJSON *o = cJSON_AddObjectToObject(summary, "distance_fade");
    report_heading(ctx->doc, 3, "The conservative distance fade, scored like for like");
    report_paragraph(
        ctx->doc,
        "The talk's fade (full effect to 150 in, to none at 200 in) with its end D a quarter of the camera's "
        "distance to its target and its start 0.75 D. The like-for-like reference is the 3-D AO with each "
        "occluder at distance t counting with weight clamp((D - t) / (D - 0.75 D), 0, 1) (%d samples per "
        "pixel; each ray draws its own cutoff uniformly in the fade, an unbiased estimate tested against a "
        "closed form). GTAO (%d regular slices x %d samples per side, radius D, falloff 0.25) fades its horizon "
        "samples instead. Pooled over the scenes: GTAO minus the faded reference %+.4f ± %.4f; the faded "
        "reference minus the unbounded one %+.4f ± %.4f (the far occlusion the fade leaves to baked lighting); "
        "scoring the faded GTAO against the unbounded reference overstates its MSE by %+.2e ± %.1e. GTAO's "
        "signed error against the faded reference includes its error without any fade (on the empty plane too). "
        "The soft clamp's own change (the claims table's figure) is GTAO with the fade minus the same GTAO cut off "
        "hard at D (the same samples, falloff 0), %+.4f ± %.4f, against the reference's same change (faded minus "
        "cut off hard at D), %+.4f ± %.4f: they differ by %+.4f ± %.4f (%+.2f code values of an 8-bit target). "
        "Against GTAO with no radius limit the change would also hold that GTAO's error from spreading its %d "
        "samples per side over the whole screen.",
        r->spp, r->slices, r->steps, r->pooled_signed_vs_faded.mean, r->pooled_signed_vs_faded.se,
        r->pooled_reference_gap.mean, r->pooled_reference_gap.se, r->pooled_scoring_bias.mean,
        r->pooled_scoring_bias.se, r->pooled_gtao_change.mean, r->pooled_gtao_change.se,
        r->pooled_reference_change.mean, r->pooled_reference_change.se, r->pooled_change_vs_truth.mean,
        r->pooled_change_vs_truth.se, r->pooled_change_vs_truth.mean / CLAIM_ONE_CODE_VALUE_8BIT, r->steps);
    report_rows(ctx->doc, cJSON_AddArrayToObject(o, "rows"), columns, COLUMNS(columns), r->rows, sizeof r->rows[0],
                r->scene_count);
    add_claim(ctx, r);
}
