/* The GTAO section's part on the talk's conservative distance fade (issue
 * 25, item 12; studies/gtao_distance_fade.h): GTAO with the fade against a
 * reference with the same fade and against the unbounded one, and the
 * claims row. */
#include <math.h>
#include <stdio.h>

#include "report/gtao_checks_section.h"
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
    REPORT_REAL("scoring bias (MSE unbounded - MSE faded)", "scoring_bias", "%+.2e", fade_row, scoring_bias.mean),
    REPORT_REAL("s.e. ", "scoring_bias_se", "%.1e", fade_row, scoring_bias.se),
};

/* Claim: the conservative attenuation keeps the near occlusion ground
 * truth, i.e. GTAO with the fade is unbiased against a reference with the
 * same fade, to one 8-bit step. */
static void add_claim(report_context *ctx, const gtao_distance_fade_result *r)
{
    unreviewed_claim row = {.source = "Jimenez et al. 2016, Minimizing Artifacts",
                 .statement = "Conservative attenuation (full effect to 150 in, fading to 0 at 200 in): ensure "
                              "ground truth near occlusion",
                 .figure = r->pooled_signed_vs_faded.mean,
                 .standard_error = r->pooled_signed_vs_faded.se,
                 .low = -1.0 / 255.0,
                 .high = 1.0 / 255.0};
    snprintf(row.quantity, sizeof row.quantity,
             "mean signed error of GTAO with the fade against a 3-D reference whose occluders fade the same way "
             "with distance, pooled over %d scenes (8x8-block s.e.); the claim allows one 8-bit step either way",
             r->scene_count);
    claims_table_add_unreviewed(ctx->claims, &row);
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
        "scoring the faded GTAO against the unbounded reference overstates its MSE by %+.2e ± %.1e.",
        r->spp, r->slices, r->steps, r->pooled_signed_vs_faded.mean, r->pooled_signed_vs_faded.se,
        r->pooled_reference_gap.mean, r->pooled_reference_gap.se, r->pooled_scoring_bias.mean,
        r->pooled_scoring_bias.se);
    report_rows(ctx->doc, cJSON_AddArrayToObject(o, "rows"), columns, COLUMNS(columns), r->rows, sizeof r->rows[0],
                r->scene_count);
    add_claim(ctx, r);
}
