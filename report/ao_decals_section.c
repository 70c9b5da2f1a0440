/* The AO decals section of `gtlab all` (studies/ao_decals.h). */
#include "report/ao_decals_section.h"

#include "report/report_table.h"

#define ROW ao_decal_row
static const report_column columns[] = {
    REPORT_STRING("decal", "variant", ROW, variant),
    REPORT_REAL("RMSE V_d, view A", "rmse_a", "%.4f", ROW, rmse[0]),
    REPORT_REAL("worst, A", "worst_a", "%.4f", ROW, worst[0]),
    REPORT_REAL("DSSIM, A", "dssim_a", "%.2e", ROW, dssim[0]),
    REPORT_REAL("beyond 4 s.e., A", "outlier_share_a", "%.3f", ROW, outlier_share[0]),
    REPORT_REAL("RMSE, view B (held out)", "rmse_b", "%.4f", ROW, rmse[1]),
    REPORT_REAL("worst, B", "worst_b", "%.4f", ROW, worst[1]),
    REPORT_REAL("DSSIM, B", "dssim_b", "%.2e", ROW, dssim[1]),
    REPORT_REAL("beyond 4 s.e., B", "outlier_share_b", "%.3f", ROW, outlier_share[1]),
};
#undef ROW

int ao_decals_section(report_context *ctx, const ao_decals_result *r, gt_error *e)
{
    (void)e;
    const ao_decal_fit_result *f = &r->fit;
    report_heading(ctx->doc, 2, "AO decals (INSIDE)");
    report_paragraph(ctx->doc,
                     "INSIDE's multiplicative AO decals against gtlab's cosine AO reference (%dx%d, %d spp) of "
                     "builtin:sphere-on-plane, floor pixels only (%zu in view A, %zu in view B). The point decal "
                     "is drawn at radius 3 around the sphere's centre with the talk's sign (pos = p - centre) and "
                     "with a light's (pos = centre - p); the refit (Ceres, view A) gives radius %.3f, falloff "
                     "exponent %.3f, wrap %.3f, intensity %.3f (RMSE %.4f, %d on a bound, %d within 1%% of one: the "
                     "falloff runs along the ridge k, R -> infinity at fixed k/R = %.3f, i.e. towards exp(-k d/R), "
                     "so the exponent is not identified); view B holds other floor points of the same configuration. Boxes, pills, corners and overlaps are not rendered yet: "
                     "tests/realtime/test_ao_decals.c checks the exact box and the horizon-clipped sphere against "
                     "Monte Carlo, and that multiplied decals over-occlude overlapping spheres.",
                     r->request.size, r->request.size, r->request.spp, r->floor_pixels[0], r->floor_pixels[1],
                     f->params[0], f->params[1], f->params[2], f->params[3], f->rmse, f->at_bound, f->near_bound,
                     f->params[1] / f->params[0]);
    cJSON *json = cJSON_AddObjectToObject(ctx->summary, "ao_decals");
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "rows"), columns, (int)(sizeof columns / sizeof columns[0]),
                r->rows, sizeof r->rows[0], AO_DECAL_VARIANTS);
    claims_table_add_figure(ctx->claims, "Gjoel 2016, INSIDE, AO Decals - Spheres",
                            "Quilez's sphere occlusion gives the covered sum accurately (occluder not intersecting "
                            "the surface)",
                            "share of floor pixels (view A) where 1 - Quilez differs from the AO reference by more "
                            "than 4 of its standard errors; holds at or below 0.01",
                            r->rows[1].outlier_share[0], 0.0, -INFINITY, 0.01);
    report_finding(ctx->doc, "AO decals",
                   "Under a sphere above the floor, Quilez's sphere AO matches the reference (RMSE %.4f, %.1f%% of "
                   "pixels beyond 4 s.e.). The published point decal at radius 3 misses by RMSE %.3f with the talk's "
                   "sign and %.3f with a light's; refitted, %.3f on held-out pixels.",
                   r->rows[1].rmse[0], 100.0 * r->rows[1].outlier_share[0], r->rows[2].rmse[0], r->rows[3].rmse[0],
                   r->rows[4].rmse[1]);
    return 0;
}
