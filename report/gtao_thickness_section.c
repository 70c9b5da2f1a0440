/* The GTAO section's part on the thickness heuristic (issue 25, item 11;
 * studies/gtao_thickness.h): per scene and thickness, the error against
 * the 3-D reference and the share of the height field's error removed, and
 * the claims row on the talk's 90 degree corners. */
#include <math.h>
#include <stdio.h>

#include "report/gtao_checks_section.h"
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
};

/* Claim: conservative on 90 degree corners, i.e. on the corner scene the
 * heuristic (at the sweep's best value) makes no visible error. */
static void add_claim(report_context *ctx, const gtao_thickness_result *r)
{
    if (r->corner_scene < 0)
        return;
    const thickness_row *x = &r->rows[r->corner_scene][r->best];
    unreviewed_claim row = {.source = "Jimenez et al. 2016, Thickness Heuristic",
                 .statement = "The thickness heuristic is conservative with architectural features such as 90 "
                              "degree corners",
                 .figure = x->vs_none_3d.mean,
                 .standard_error = x->vs_none_3d.se,
                 .low = -INFINITY,
                 .high = GTAO_SHORTCUT_VISIBLE_MSE};
    snprintf(row.quantity, sizeof row.quantity,
             "corner scene: MSE with thickness %.2f (the sweep's lowest pooled MSE) minus MSE without, against the 3-D "
             "reference (8x8-block s.e.); the claim allows up to (1/255)^2",
             x->thickness);
    claims_table_add_unreviewed(ctx->claims, &row);
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
