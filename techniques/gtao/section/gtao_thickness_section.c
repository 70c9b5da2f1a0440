/* The GTAO section's part on the thickness heuristic (issue 25, item 11;
 * gtao_thickness.h): per scene and thickness, the error against
 * the 3-D reference and the share of the height field's error removed, and
 * the claims row on the talk's 90 degree corners. */
#include <math.h>
#include <stdio.h>

#include "gtao/gtao_checks_section.h"
#include "report/claim_thresholds.h"
#include "report/report_table.h"

#define COLUMNS(c) (int)(sizeof(c) / sizeof((c)[0]))

static const report_column columns[] = {
    REPORT_TEXT("scene", "scene", thickness_row, scene),
    REPORT_REAL("thickness", "thickness", "%.2f", thickness_row, thickness),
    REPORT_REAL("MSE vs 3-D", "mse_3d", "%.2e", thickness_row, mse_3d),
    REPORT_REAL("MSE vs height field", "mse_hf", "%.2e", thickness_row, mse_hf),
    REPORT_REAL("minus MSE without (vs 3-D)", "paired_mse", "%+.2e", thickness_row, vs_none_3d.mean),
    REPORT_REAL("s.e. (8x8 blocks)", "paired_mse_se", "%.1e", thickness_row, vs_none_3d.se),
    REPORT_REAL("height-field error removed (%)", "removed_percent", "%+.1f", thickness_row, removed_percent),
    REPORT_REAL("mean AO minus AO without", "change", "%+.4f", thickness_row, change.mean),
    REPORT_REAL("8-bit codes changed", "codes_changed", "%.3f", thickness_row, codes.mean),
};

/* Claim: conservative on 90 degree corners. Scored as the heuristic's own
 * change on the corner scene (issue 42): it only lowers horizons, so it can
 * only brighten; conservative means it leaves the corners' occlusion, whose
 * truth the height field already is. */
static const claim_record corner_claim = {
    .talk = "Jimenez et al. 2016 (GTAO)",
    .seed = "001",
    .section = "Thickness Heuristic",
    .quote = "We developed a thickness heuristic: - Assume object thickness similar to screen space width - "
             "Conservative with architectural features such as 90\u00b0 corners",
    .setting = "architectural game levels at 1080p (half resolution), where thin features are the problem "
               "(\"Horizon-based AO leads to thin features to cast too much occlusion\") and 90 degree corners "
               "must keep their occlusion",
    .setting_match = CLAIM_SETTING_INDEPENDENT,
    .setting_note = "gtlab's 256x256 corner scene (three planes meeting at 90 degrees), GTAO with regular slices "
                    "and no denoiser, at the sweep's best thickness: the heuristic compares a sample's distance "
                    "with a thickness in the world, so the resolution only sets how many pixels see the corner",
    .reading = "the heuristic should leave a 90 degree corner's AO as it was without it, brightening the corner "
               "scene by less than one 8-bit code value on average",
    .form = CLAIM_RANGE,
    .low = -INFINITY,
    .high = CLAIM_ONE_CODE_VALUE_8BIT,
    .tolerance_source = CLAIM_TOLERANCE_VISIBILITY,
    .tolerance = "one code value of an 8-bit AO target (CLAIM_ONE_CODE_VALUE_8BIT) of mean brightening"};

static void add_claim(report_context *ctx, const gtao_thickness_result *r)
{
    if (r->corner_scene < 0)
        return;
    const thickness_row *x = &r->rows[r->corner_scene][r->best];
    claims_table_add(ctx->claims, &corner_claim, x->change.mean, x->change.se,
                     "corner scene: mean AO with thickness %.2f (the sweep's lowest pooled MSE) minus AO without "
                     "(8x8-block s.e.); %.1f%% of pixels change 8-bit code; MSE with minus without against the "
                     "3-D reference %+.2e",
                     x->thickness, 100.0 * x->codes.mean, x->vs_none_3d.mean);
}

void gtao_thickness_section(report_context *ctx, const gtao_thickness_result *r, cJSON *summary)
{
    cJSON *o = cJSON_AddObjectToObject(summary, "thickness");
    report_heading(ctx->doc, 3, "Thickness heuristic");
    report_paragraph(
        ctx->doc,
        "GTAO with %d regular slices x %d samples per side (no pattern, no denoiser, no radius limit) with the "
        "thickness heuristic off (the height field of infinite thickness, which GTAO reproduces) and at %d "
        "values. 'Height-field error removed' is the fall in MSE against the 3-D reference as a share of the "
        "heuristic-off MSE less the reference's noise variance; negative where the heuristic hurts. Pooled over "
        "the scenes, MSE minus MSE without: %.2f: %+.2e ± %.1e; %.2f: %+.2e ± %.1e; %.2f: %+.2e ± %.1e; %.2f: "
        "%+.2e ± %.1e (lowest: %.2f).",
        r->slices, r->steps, THICKNESS_VALUES, gtao_thickness_values[0], r->pooled_vs_none_3d[0].mean,
        r->pooled_vs_none_3d[0].se, gtao_thickness_values[1], r->pooled_vs_none_3d[1].mean,
        r->pooled_vs_none_3d[1].se, gtao_thickness_values[2], r->pooled_vs_none_3d[2].mean,
        r->pooled_vs_none_3d[2].se, gtao_thickness_values[3], r->pooled_vs_none_3d[3].mean,
        r->pooled_vs_none_3d[3].se, gtao_thickness_values[r->best]);
    report_rows(ctx->doc, cJSON_AddArrayToObject(o, "rows"), columns, COLUMNS(columns), r->rows, sizeof r->rows[0][0],
                r->scene_count * THICKNESS_VALUES);
    cJSON_AddNumberToObject(o, "best_thickness", gtao_thickness_values[r->best]);
    add_claim(ctx, r);
}
