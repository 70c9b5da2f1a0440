/* The height fog's section of `gtlab all` (studies/height_fog.h). */
#include "report/height_fog_section.h"

#include <math.h>
#include <stdio.h>

#include "core/reference_schema.h"
#include "report/aerial_perspective_section.h"
#include "report/report_table.h"

#define ROW height_fog_case
static const report_column case_columns[] = {
    REPORT_TEXT("weather", "weather", ROW, weather),
    REPORT_REAL("sun elevation", "sun_elevation_deg", "%.0f", ROW, sun_elevation_deg),
    REPORT_REAL("reference L (G)", "reference_mean_l", "%.4f", ROW, reference_mean_l),
    REPORT_REAL("its stderr", "reference_mean_stderr", "%.1e", ROW, reference_mean_stderr),
    REPORT_REAL("single scattering L", "single_mean_l", "%.4f", ROW, single_mean_l),
    REPORT_REAL("published vs single, max rel.", "published_max_rel_single", "%.1e", ROW, published_max_rel_single),
    REPORT_REAL("noise floor (RMS stderr)", "reference_noise_rms", "%.4f", ROW, reference_noise_rms),
    REPORT_REAL("RMSE published", "rmse_l_published", "%.4f", ROW, rmse_l[FOG_MODEL_PUBLISHED]),
    REPORT_REAL("RMSE clamp fixed", "rmse_l_clamp_fixed", "%.4f", ROW, rmse_l[FOG_MODEL_CLAMP_FIXED]),
    REPORT_REAL("RMSE sun attenuated", "rmse_l_sun_attenuated", "%.4f", ROW, rmse_l[FOG_MODEL_SUN_ATTENUATED]),
    REPORT_REAL("RMSE sky attenuated", "rmse_l_sky_attenuated", "%.4f", ROW, rmse_l[FOG_MODEL_SKY_ATTENUATED]),
    REPORT_REAL("DSSIM published", "dssim_l_published", "%.4f", ROW, dssim_l[FOG_MODEL_PUBLISHED]),
    REPORT_REAL("DSSIM sun attenuated", "dssim_l_sun_attenuated", "%.4f", ROW, dssim_l[FOG_MODEL_SUN_ATTENUATED]),
    REPORT_REAL("DSSIM sky attenuated", "dssim_l_sky_attenuated", "%.4f", ROW, dssim_l[FOG_MODEL_SKY_ATTENUATED]),
    REPORT_REAL(NULL, "dssim_l_clamp_fixed", NULL, ROW, dssim_l[FOG_MODEL_CLAMP_FIXED]),
    REPORT_REAL(NULL, "rmse_t_published", NULL, ROW, rmse_t[FOG_MODEL_PUBLISHED]),
    REPORT_REAL(NULL, "rmse_t_corrected", NULL, ROW, rmse_t[FOG_MODEL_SUN_ATTENUATED]),
    REPORT_INT(NULL, "pixels", ROW, pixels),
    REPORT_REAL(NULL, "reference_rays_per_second", NULL, ROW, reference_rays_per_second),
};
#undef ROW
#define ROW height_fog_regime
static const report_column regime_columns[] = {
    REPORT_TEXT("rays", "regime", ROW, regime),
    REPORT_REAL("published: depth", "published_depth_error", "%.2e", ROW, published_depth_error),
    REPORT_REAL("published: L", "published_l_error", "%.2e", ROW, published_l_error),
    REPORT_REAL("corrected: depth", "corrected_depth_error", "%.2e", ROW, corrected_depth_error),
    REPORT_REAL("corrected: L", "corrected_l_error", "%.2e", ROW, corrected_l_error),
};
#undef ROW

/* The largest departure of the published model from single scattering on
 * the terrain (its assumptions held), and in the regime table. */
static void add_claims(report_context *ctx, const height_fog_result *r)
{
    double terrain = 0.0, regimes = 0.0;
    for (int i = 0; i < HEIGHT_FOG_CASES; ++i)
        terrain = fmax(terrain, r->cases[i].published_max_rel_single);
    for (int g = 0; g < HEIGHT_FOG_REGIMES; ++g)
        regimes = fmax(regimes, r->regimes[g].published_depth_error);
    claims_table_add_unreviewed_figure(ctx->claims, "Decima 2017, Height fog: Analytic model",
                            "HeightFog() is an analytic solution of the volume rendering equation under single "
                            "scattering (and single scale height): exact, on the terrain's downward rays",
                            "max relative error of its L against single-scattering quadrature (sun unattenuated, "
                            "no shadows), terrain pixels",
                            terrain, 0.0, 0.0, 1e-3);
    claims_table_add_unreviewed_figure(ctx->claims, "Decima 2017, Height fog: Analytic model",
                            "the same, for every ray direction (its max(1e-2, ...) clamp included)",
                            "max relative error of its optical depth against quadrature over the regime table",
                            regimes, 0.0, 0.0, 1e-3);
}

int height_fog_section(report_context *ctx, const height_fog_result *r, gt_error *e)
{
    (void)e;
    const height_fog_request *rq = &r->request;
    report_heading(ctx->doc, 2, "Height fog (Decima 2017)");
    report_paragraph(ctx->doc,
                     "The talk's HeightFog() as published (its max(1e-2, ...) clamp, float), with the clamp fixed, "
                     "with the sun attenuated by the fog above each point (closed form), and with the ambient too "
                     "(the upper hemisphere's sky through the fog above, 6-point rule; docs/decisions.md "
                     "\"Height fog\"), against `gtlab render fog` on builtin:terrain (%dx%d, %d samples per pixel "
                     "of volumetric path tracing: the truth, with the sun attenuated and shadowed and the sky "
                     "blocked by the terrain) and against single-scattering quadrature under the model's own "
                     "assumptions. fog.L is the light the fog scatters towards the camera; surfaces absorb. "
                     "Each case's reference is %s/<weather>_sunNN.exr, with the error maps %s and %s (model minus "
                     "reference).",
                     rq->width, rq->height, rq->spp, HEIGHT_FOG_DIR, CH_FOG_PUBLISHED_ERROR, CH_FOG_CORRECTED_ERROR);
    cJSON *section = cJSON_AddObjectToObject(ctx->summary, "height_fog");
    report_rows(ctx->doc, section ? cJSON_AddArrayToObject(section, "cases") : NULL, case_columns,
                (int)(sizeof case_columns / sizeof case_columns[0]), r->cases, sizeof r->cases[0], HEIGHT_FOG_CASES);
    report_paragraph(ctx->doc,
                     "Single rays against the quadrature, largest relative error over H in {10, 100, 1000, 1e5} m, "
                     "beta from clear air to dense fog (x1, x30, x1000), 300 m and 3 km: the published model with "
                     "the sun unattenuated, the corrected one with the sun attenuated.");
    report_rows(ctx->doc, section ? cJSON_AddArrayToObject(section, "regimes") : NULL, regime_columns,
                (int)(sizeof regime_columns / sizeof regime_columns[0]), r->regimes, sizeof r->regimes[0],
                HEIGHT_FOG_REGIMES);
    const height_fog_timing *cost = &r->analytic_cost;
    report_paragraph(ctx->doc, "Analytic model cost in C, one thread: %.1f ns per pixel published, %.1f clamp fixed, "
                               "%.1f sun attenuated, %.1f sky attenuated, one pixel at a time; the published model "
                               "over rows of pixels, vectorised (realtime/height_fog_batch.c): %.1f ns (goal < 20 ns).",
                     cost->ns_per_pixel[0], cost->ns_per_pixel[1], cost->ns_per_pixel[2], cost->ns_per_pixel[3],
                     cost->published_batch_ns_per_pixel);
    const height_fog_case *dense = &r->cases[HEIGHT_FOG_SUNS];
    report_finding(ctx->doc, "Height fog",
                   "HeightFog() is exact single scattering (within %.1e) only where its assumptions hold: rays that "
                   "descend by at least H/100, the sun unattenuated by the fog. Its clamp loses %.0f%% of an upward "
                   "ray's optical depth; in dense fog with the sun %.0f degrees up its fog.L is off by RMSE %.3f "
                   "against the full reference (%.3f with the sun attenuated, %.3f with the sky attenuated too).",
                   r->cases[0].published_max_rel_single, 100.0 * r->regimes[4].published_depth_error,
                   dense->sun_elevation_deg, dense->rmse_l[FOG_MODEL_PUBLISHED],
                   dense->rmse_l[FOG_MODEL_SUN_ATTENUATED], dense->rmse_l[FOG_MODEL_SKY_ATTENUATED]);
    add_claims(ctx, r);
    aerial_perspective_section(ctx, section, HEIGHT_FOG_DIR, &r->aerial);
    return 0;
}
