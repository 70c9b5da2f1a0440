/* The AO decals section of `gtlab all` (ao_decals_study.h). */
#include "ao_decals/ao_decals_section.h"

#include "report/claim_thresholds.h"
#include "report/report_table.h"

#include <math.h>
#include <string.h>

#define ROW ao_decal_row
static const report_column columns[] = {
    REPORT_STRING("decal", "variant", ROW, variant),
    REPORT_REAL("RMSE V_d, view A", "rmse_a", "%.4f", ROW, rmse[0]),
    REPORT_REAL("worst, A", "worst_a", "%.4f", ROW, worst[0]),
    REPORT_REAL("DSSIM, A", "dssim_a", "%.2e", ROW, dssim[0]),
    REPORT_REAL("beyond 4 s.e., A", "outlier_share_a", "%.3f", ROW, outlier_share[0]),
    REPORT_RANKED("RMSE, view B (held out)", "rmse_b", "%.4f", ROW, rmse[1], REPORT_LOWEST_BEST),
    REPORT_REAL("worst, B", "worst_b", "%.4f", ROW, worst[1]),
    REPORT_REAL("DSSIM, B", "dssim_b", "%.2e", ROW, dssim[1]),
    REPORT_REAL("beyond 4 s.e., B", "outlier_share_b", "%.3f", ROW, outlier_share[1]),
};
#undef ROW

#define ROW ao_decal_scene_row
static const report_column scene_columns[] = {
    REPORT_STRING("scene", "scene", ROW, scene),
    REPORT_STRING("decal", "decal", ROW, decal),
    REPORT_COUNT("pixels", "pixels", ROW, pixels),
    REPORT_REAL("RMSE V_d", "rmse", "%.4f", ROW, rmse),
    REPORT_REAL("mean error", "bias", "%+.4f", ROW, bias),
    REPORT_REAL("worst", "worst", "%.4f", ROW, worst),
    REPORT_REAL("DSSIM", "dssim", "%.2e", ROW, dssim),
    REPORT_REAL("beyond 4 s.e.", "outlier_share", "%.3f", ROW, outlier_share),
    REPORT_COUNT("single px", "single_pixels", ROW, region_pixels[AO_REGION_SINGLE]),
    REPORT_REAL("RMSE single", "rmse_single", "%.4f", ROW, region_rmse[AO_REGION_SINGLE]),
    REPORT_COUNT("overlap px", "overlap_pixels", ROW, region_pixels[AO_REGION_OVERLAP]),
    REPORT_REAL("RMSE overlap", "rmse_overlap", "%.4f", ROW, region_rmse[AO_REGION_OVERLAP]),
    REPORT_COUNT("clipped px", "clipped_pixels", ROW, region_pixels[AO_REGION_CLIPPED]),
    REPORT_REAL("RMSE clipped", "rmse_clipped", "%.4f", ROW, region_rmse[AO_REGION_CLIPPED]),
};
#undef ROW

static const ao_decal_scene_row *scene_row(const ao_decals_result *r, const char *scene, const char *decal_prefix)
{
    static const ao_decal_scene_row empty = {"", "", 0, NAN, NAN, NAN, NAN, NAN, {0}, {NAN, NAN, NAN}};
    for (int k = 0; k < r->scenes.row_count; ++k)
        if (strcmp(r->scenes.rows[k].scene, scene) == 0 &&
            strncmp(r->scenes.rows[k].decal, decal_prefix, strlen(decal_prefix)) == 0)
            return &r->scenes.rows[k];
    return &empty;
}

static void scene_findings(report_context *ctx, const ao_decals_result *r)
{
    const ao_decal_scene_row *box = scene_row(r, "box-on-plane", "exact"), *over = scene_row(r, "overlap-on-plane", "exact");
    const ao_decal_scene_row *corner = scene_row(r, "box-in-corner", "exact"), *walls = scene_row(r, "box-in-corner", "walls");
    const ao_decal_scene_row *engine = scene_row(r, "overlap-on-plane", "engine");
    const ao_decal_scene_row *pill_t = scene_row(r, "pill-on-plane", "point decal, talk"),
                             *pill_l = scene_row(r, "pill-on-plane", "point decal, light");
    report_finding(ctx->doc, "AO decals",
                   "The exact box (Lambert's polygon formula) is the crate's AO: RMSE %.4f on the floor of "
                   "box-on-plane, %.1f%% of pixels beyond 4 s.e. Multiplying exact forms is not the union: on "
                   "overlap-on-plane RMSE %.4f where two or more occluders act against %.4f elsewhere, mean error "
                   "%+.4f (over-occlusion); in the corner the walls times the exact crate (RMSE %.4f, mean %+.4f) "
                   "are worse than no crate decal at all (%.4f): the crate blocks directions the walls already block. "
                   "Below the horizon (the sphere sunk into the floor, alone): the exact clipped sphere %.4f, Quilez's "
                   "%.4f (it assumes the occluder clear of the surface, as the talk says). "
                   "The pill's point decal (its ellipsoid x %.0f, the talk's full transform): RMSE %.4f with the "
                   "talk's sign, %.4f with a light's.",
                   box->rmse, 100.0 * box->outlier_share, over->region_rmse[AO_REGION_OVERLAP],
                   over->region_rmse[AO_REGION_SINGLE], over->bias, corner->rmse, corner->bias, walls->rmse,
                   over->region_rmse[AO_REGION_CLIPPED], engine->region_rmse[AO_REGION_CLIPPED],
                   AO_DECAL_POINT_RADIUS, pill_t->rmse, pill_l->rmse);
}

/* The summary table's row: the point decal as published and its two
 * refits, by RMSE on the held-out scenes, the gap's interval from each
 * held-out scene's own RMSE (paired over those scenes). */
static void add_headline(report *doc, const ao_decals_result *r)
{
    const char *labels[AO_DECAL_COMPARED] = {"point decal as published", "refit, k held at 2", "refit, k free"};
    report_headline h = {.topic = "AO decals", .measure = "held-out RMSE (box, corner, overlap)",
                         .significance = HEADLINE_NOT_COMPUTED,
                         .margin = CLAIM_ONE_CODE_VALUE_8BIT}; /* RMSE of V_d in an 8-bit AO target */
    if (headline_rank(&h, AO_DECAL_COMPARED, labels, r->held_out_rmse) != 0)
        return;
    char over[64];
    snprintf(over, sizeof over, "per-scene RMSE paired over %d held-out scenes", r->held_out_scenes);
    headline_pair_cases(&h, AO_DECAL_COMPARED, labels, &r->held_out_scene_rmse[0][0],
                        (int)(sizeof r->held_out_scene_rmse[0] / sizeof(double)), r->held_out_scenes, over);
    headline_state_reference_noise(&h, r->held_out_noise_rmse);
    report_add_headline(doc, &h);
}

#define INSIDE_TALK "Gjøl & Svendsen 2016 (INSIDE)"

static const claim_record kQuilezSphere = {
    .talk = INSIDE_TALK, .seed = "002", .section = "AO Decals - Spheres",
    .quote = "This, which actually gives you that result accurately, the covered sum. Assuming the occluder doesn't "
             "intersect the surface, which we do assume.",
    .setting = "a multiplicative AO decal for large round occluders (a submarine) over receivers, the sphere clear of "
               "the receiver's tangent plane; the decal's result multiplies the light buffer",
    .setting_match = CLAIM_SETTING_TALK,
    .setting_note = NULL,
    .reading = "Quilez's sphere occlusion equals the cosine-weighted solid angle the sphere covers (its exact form "
               "factor) when the sphere lies above the receiver's plane",
    .form = CLAIM_RANGE, .low = 0.0, .high = CLAIM_ONE_CODE_VALUE_8BIT, .tolerance_source = CLAIM_TOLERANCE_VISIBILITY,
    .tolerance = "one 8-bit code value of the AO it multiplies in (CLAIM_ONE_CODE_VALUE_8BIT)"};

static const claim_record kPointFalloff = {
    .talk = INSIDE_TALK, .seed = "002", .section = "AO Decals - Points",
    .quote = "float falloff = 1.0 - length(pos); float ao = falloff * falloff * nDotL; ... This entity has no wrap "
             "parameter, we fixed it to half lambert, and gave it a fixed falloff.",
    .setting = "character AO: one point decal per bone, stretched over the limb (full transform), hundreds on screen; "
               "'it's important to have controls be easy', so only the transform and an intensity slider",
    .setting_match = CLAIM_SETTING_TALK,
    .reading = "a design choice, not a claim of fit: the falloff is fixed at (1 - d)^2 (exponent k = 2) and the wrap at "
               "half Lambert for easy controls; gtlab measures how far a free refit's tail moves from it",
    .form = CLAIM_ASSUMPTION, .tolerance_source = CLAIM_TOLERANCE_NONE};

static void add_claims(report_context *ctx, const ao_decals_result *r)
{
    const ao_decal_fit_result *f = &r->fit;
    claims_table_add(ctx->claims, &kQuilezSphere, fmax(r->quilez_exact_worst[0], r->quilez_exact_worst[1]), 0.0,
                     "largest |V(Quilez) - V(exact sphere form factor)| over the floor pixels of both views of "
                     "builtin:sphere-on-plane (%zu + %zu); closed forms, exact (against the Monte Carlo reference both "
                     "have RMSE %.4f, its noise)",
                     r->floor_pixels[0], r->floor_pixels[1], r->rows[1].rmse[0]);
    claims_table_add(ctx->claims, &kPointFalloff, f->params[AO_DECAL_SHAPE], f->standard_errors[AO_DECAL_SHAPE],
                     "tail shape xi of the point decal's free refit on sphere-on-plane and pill-on-plane (a compact "
                     "(1 - d)^k for xi < 0, k = -1 / xi: the talk's k = 2 is xi = -1/2; xi > 0 a power-law tail, the "
                     "exact sphere's (r/d)^2 xi = +1/2); held-out RMSE free %.4f, k held at 2 %.4f, as published %.4f",
                     r->held_out_rmse[AO_DECAL_REFIT_FREE], r->held_out_rmse[AO_DECAL_REFIT_K2],
                     r->held_out_rmse[AO_DECAL_PUBLISHED]);
}

int ao_decals_section(report_context *ctx, const ao_decals_result *r, gt_error *e)
{
    (void)e;
    const ao_decal_fit_result *f = &r->fit, *k2 = &r->fit_k2;
    report_heading(ctx->doc, 2, "AO decals (INSIDE)");
    report_paragraph(ctx->doc,
                     "INSIDE's multiplicative AO decals against gtlab's cosine AO reference (%dx%d, at most %d spp, a "
                     "pixel stopping at a standard error of %g, its noise budget) of "
                     "builtin:sphere-on-plane, floor pixels only (%zu in view A, %zu in view B). The point decal "
                     "is drawn at radius 3 around the sphere's centre with the talk's sign (pos = p - centre) and "
                     "with a light's (pos = centre - p). View B holds other floor points of the same configuration.",
                     r->request.size, r->request.size, r->request.spp, r->request.noise_budget, r->floor_pixels[0],
                     r->floor_pixels[1]);
    report_paragraph(ctx->doc,
                     "Refit (Ceres, ao_decals/ao_decals_fit.h) on view A and builtin:pill-on-plane (the talk's setting: "
                     "a decal stretched over a pill) together, %zu samples; held out: box-on-plane, box-in-corner and "
                     "overlap-on-plane (%zu receivers; other occluder shapes, sizes, walls and several decals "
                     "multiplying). Falloff a = A (1 + xi (d - 2) / L)^(-1 / xi) wrap, d in occluder radii: A the "
                     "occlusion at d = 2, L the decay length there, xi < 0 compact with exponent k = -1 / xi (the "
                     "published decal at radius 3: xi = -1/2, L = 1/2, A = 1/9), xi = 0 exponential, xi > 0 a "
                     "power-law tail (xi = 1/2, L = 1: the exact sphere's (r / d)^2). Free: xi %.3f +- %.3f, L %.3f "
                     "+- %.3f, wrap %.3f +- %.3f, A %.4f +- %.4f (RMSE %.4f, %d on a bound; s.e. from the covariance "
                     "scaled by the residual variance, lower bounds as the misfit is spatially correlated); k = "
                     "-1 / xi = %.2f +- %.2f. With k held at 2 (xi = -1/2): L %.3f +- %.3f, wrap %.3f +- %.3f, A %.4f "
                     "+- %.4f (RMSE %.4f, %d on a bound).",
                     r->fitted_count, r->held_out_count, f->params[0], f->standard_errors[0], f->params[1],
                     f->standard_errors[1], f->params[2], f->standard_errors[2], f->params[3], f->standard_errors[3],
                     f->rmse, f->at_bound, f->exponent, f->exponent_se, k2->params[1], k2->standard_errors[1],
                     k2->params[2], k2->standard_errors[2], k2->params[3], k2->standard_errors[3], k2->rmse,
                     k2->at_bound);
    report_paragraph(ctx->doc,
                     "RMSE of V_d, fitted samples / held-out receivers: published decal (light's sign) %.4f / %.4f; "
                     "refit with k = 2 %.4f / %.4f; free refit %.4f / %.4f.",
                     r->fitted_rmse[AO_DECAL_PUBLISHED], r->held_out_rmse[AO_DECAL_PUBLISHED],
                     r->fitted_rmse[AO_DECAL_REFIT_K2], r->held_out_rmse[AO_DECAL_REFIT_K2],
                     r->fitted_rmse[AO_DECAL_REFIT_FREE], r->held_out_rmse[AO_DECAL_REFIT_FREE]);
    report_paragraph(ctx->doc,
                     "Each configuration alone (k free): sphere view A xi %.3f +- %.3f, wrap %.3f (%d on a bound); "
                     "pill xi %.3f +- %.3f, wrap %.3f (%d on a bound).",
                     r->fit_sphere.params[AO_DECAL_SHAPE], r->fit_sphere.standard_errors[AO_DECAL_SHAPE],
                     r->fit_sphere.params[AO_DECAL_WRAP], r->fit_sphere.at_bound, r->fit_pill.params[AO_DECAL_SHAPE],
                     r->fit_pill.standard_errors[AO_DECAL_SHAPE], r->fit_pill.params[AO_DECAL_WRAP], r->fit_pill.at_bound);
    cJSON *json = cJSON_AddObjectToObject(ctx->summary, "ao_decals");
    cJSON_AddNumberToObject(json, "held_out_noise_rmse", r->held_out_noise_rmse);
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "rows"), columns, (int)(sizeof columns / sizeof columns[0]),
                r->rows, sizeof r->rows[0], AO_DECAL_VARIANTS);
    report_paragraph(ctx->doc,
                     "The decal scenes (builtin:pill-on-plane, box-on-plane, box-in-corner, overlap-on-plane: the "
                     "occluders as real geometry, so the reference counts their union), receivers only (floor, and "
                     "the corner's walls), at each scene's camera. Decals multiply, V = V_walls prod (1 - a_i), "
                     "V_walls the corner walls' exact form factor (1 elsewhere); the point decal sits in each "
                     "occluder's unit space scaled by %.0f (the pill's decal is its stretched ellipsoid). Regions: "
                     "overlap (two or more occluders, walls included, each occlude > %.2f), clipped (otherwise, the "
                     "one that does, > %.2f, is a sphere straddling the tangent plane), single (the rest). DSSIM maps: figures "
                     "ao_decals/dssim_<scene>_<decal>.png (0 to %.2f).",
                     AO_DECAL_POINT_RADIUS, AO_DECAL_SIGNIFICANT, AO_DECAL_SIGNIFICANT, AO_DECAL_DSSIM_MAP_MAX);
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "scene_rows"), scene_columns,
                (int)(sizeof scene_columns / sizeof scene_columns[0]), r->scenes.rows, sizeof r->scenes.rows[0],
                r->scenes.row_count);
    add_claims(ctx, r);
    add_headline(ctx->doc, r);
    report_finding(ctx->doc, "AO decals",
                   "The point decal's refit (sphere and pill fitted, box, corner and overlap held out) wants a "
                   "power-law tail, not the talk's (1 - d)^2: shape xi = %.3f +- %.3f (k = 2 is xi = -0.5; the exact "
                   "sphere's (r/d)^2 is xi = 0.5), wrap %.3f +- %.3f (plain Lambert, not half-Lambert). Held-out "
                   "RMSE: free %.4f, k held at 2 %.4f, published %.4f.",
                   f->params[AO_DECAL_SHAPE], f->standard_errors[AO_DECAL_SHAPE], f->params[AO_DECAL_WRAP],
                   f->standard_errors[AO_DECAL_WRAP], r->held_out_rmse[AO_DECAL_REFIT_FREE],
                   r->held_out_rmse[AO_DECAL_REFIT_K2], r->held_out_rmse[AO_DECAL_PUBLISHED]);
    report_finding(ctx->doc, "AO decals",
                   "Under a sphere above the floor, Quilez's sphere AO matches the reference (RMSE %.4f, %.1f%% of "
                   "pixels beyond 4 s.e.). The published point decal at radius 3 misses by RMSE %.3f with the talk's "
                   "sign and %.3f with a light's; refitted, %.3f on view B.",
                   r->rows[1].rmse[0], 100.0 * r->rows[1].outlier_share[0], r->rows[2].rmse[0], r->rows[3].rmse[0],
                   r->rows[4].rmse[1]);
    scene_findings(ctx, r);
    return 0;
}
