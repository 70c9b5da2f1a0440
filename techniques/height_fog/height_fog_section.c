/* The height fog's section of `gtlab all` (height_fog/height_fog_study.h). */
#include "height_fog/height_fog_section.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/reference_schema.h"
#include "height_fog/aerial_perspective_section.h"
#include "report/claim_thresholds.h"
#include "report/claims_table.h"
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
    REPORT_REAL("RMSE published", "rmse_l_published", "%.4f", ROW, rmse_l[HEIGHT_FOG_MODEL_PUBLISHED]),
    REPORT_REAL("RMSE clamp fixed", "rmse_l_clamp_fixed", "%.4f", ROW, rmse_l[HEIGHT_FOG_MODEL_CLAMP_FIXED]),
    REPORT_REAL("RMSE sun attenuated", "rmse_l_sun_attenuated", "%.4f", ROW, rmse_l[HEIGHT_FOG_MODEL_SUN_ATTENUATED]),
    REPORT_REAL("RMSE sky attenuated", "rmse_l_sky_attenuated", "%.4f", ROW, rmse_l[HEIGHT_FOG_MODEL_SKY_ATTENUATED]),
    REPORT_REAL("DSSIM published", "dssim_l_published", "%.4f", ROW, dssim_l[HEIGHT_FOG_MODEL_PUBLISHED]),
    REPORT_REAL("DSSIM sun attenuated", "dssim_l_sun_attenuated", "%.4f", ROW, dssim_l[HEIGHT_FOG_MODEL_SUN_ATTENUATED]),
    REPORT_REAL("DSSIM sky attenuated", "dssim_l_sky_attenuated", "%.4f", ROW, dssim_l[HEIGHT_FOG_MODEL_SKY_ATTENUATED]),
    REPORT_REAL(NULL, "dssim_l_clamp_fixed", NULL, ROW, dssim_l[HEIGHT_FOG_MODEL_CLAMP_FIXED]),
    REPORT_REAL(NULL, "rmse_t_published", NULL, ROW, rmse_t[HEIGHT_FOG_MODEL_PUBLISHED]),
    REPORT_REAL(NULL, "rmse_t_corrected", NULL, ROW, rmse_t[HEIGHT_FOG_MODEL_SUN_ATTENUATED]),
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

#define HEIGHT_FOG_TALK "de Carpentier & Ishiyama 2017 (Decima)"
#define HEIGHT_FOG_SETTING                                                                                                  \
    "Death Stranding's height fog: a camera on or near the ground (the LUTs are \"optimized for games on the "      \
    "ground or near the ground\"), terrain, mountains and sky seen through fog from sunny to dense; single "       \
    "scattering and a single scale height assumed, the sun and sky light given by the LUTs"

/* The model against its own assumptions on terrain pixels. */
static const claim_record kAnalytic = {
    .talk = HEIGHT_FOG_TALK, .seed = "000", .section = "Height fog: Combination",
    .quote = "This calculation is an analytic solution of the volume rendering equation with assuming the single "
             "scattering.",
    .setting = HEIGHT_FOG_SETTING, .setting_match = CLAIM_SETTING_INDEPENDENT,
    .setting_note = "builtin:terrain's pixels (rays from a camera above the terrain going down to it) against "
                    "single-scattering quadrature under the model's own assumptions (one scale height, the sun "
                    "unattenuated, no shadows): a claim about the formula's values, which do not depend on the "
                    "image's resolution",
    .reading = "on the terrain's rays the published HeightFog() gives single scattering's in-scattered light L "
               "within what could be seen (largest relative error below 1%)",
    .form = CLAIM_RANGE, .low = 0.0, .high = CLAIM_WEBER_FRACTION,
    .tolerance_source = CLAIM_TOLERANCE_VISIBILITY,
    .tolerance = "a 1% change of luminance (CLAIM_WEBER_FRACTION), as the largest relative error of L"};

/* The same for the published code on every ray a camera near the ground sees. */
static const claim_record kEveryRay = {
    .talk = HEIGHT_FOG_TALK, .seed = "000", .section = "Height fog: Combination",
    .quote = "This calculation is an analytic solution of the volume rendering equation with assuming the single "
             "scattering.",
    .setting = HEIGHT_FOG_SETTING, .setting_match = CLAIM_SETTING_INDEPENDENT,
    .setting_note = "single rays from a camera 20 m up, inside the fog (down, less than H/100 down, horizontal, "
                    "up, shallow up), H from 10 m to 100 km, clear air to dense fog, 300 m and 3 km: the regime a "
                    "ground camera sees; a claim about values, independent of resolution",
    .reading = "the talk's words are about the model (its slide's formula); this row tests its published code",
    .stronger_reading = "the published HeightFog() code, with its max(1e-2, ...) clamp, gives that solution on every "
                        "ray a camera near the ground sees, upward rays (mountains, sky) included",
    .form = CLAIM_RANGE, .low = 0.0, .high = CLAIM_WEBER_FRACTION,
    .tolerance_source = CLAIM_TOLERANCE_VISIBILITY,
    .tolerance = "a 1% change of luminance (CLAIM_WEBER_FRACTION), as the largest relative error of L"};

/* The regimes of the table whose camera is near the ground (20 m). */
static int near_ground(const char *regime)
{
    return strstr(regime, "camera inside") || strstr(regime, "H/100") || strstr(regime, "horizontal") ||
           strstr(regime, "shallow");
}

static void add_claims(report_context *ctx, const height_fog_result *r)
{
    double terrain = 0.0, regimes = 0.0;
    int n = 0;
    for (int i = 0; i < HEIGHT_FOG_CASES; ++i)
        terrain = fmax(terrain, r->cases[i].published_max_rel_single);
    for (int g = 0; g < HEIGHT_FOG_REGIMES; ++g)
        if (near_ground(r->regimes[g].regime))
            regimes = fmax(regimes, r->regimes[g].published_l_error), ++n;
    claims_table_add(ctx->claims, &kAnalytic, terrain, 0.0,
                     "largest |published - single scattering| / single scattering of L (green) over the terrain "
                     "pixels of %d cases (exact: a maximum over every pixel)", HEIGHT_FOG_CASES);
    claims_table_add(ctx->claims, &kEveryRay, regimes, 0.0,
                     "largest relative error of the published L against single-scattering quadrature (sun "
                     "unattenuated) over %d near-ground regimes of the regime table (exact: a maximum)", n);
}

int height_fog_section(report_context *ctx, const height_fog_result *r, gt_error *e)
{
    (void)e;
    const height_fog_request *rq = &r->request;
    report_heading(ctx->doc, 2, "Height fog (Decima 2017)");
    report_paragraph(ctx->doc,
                     "The talk's HeightFog() as published (its max(1e-2, ...) clamp, float), with the clamp fixed, "
                     "with the sun attenuated by the fog above each point (closed form), and with the ambient too "
                     "(the upper hemisphere's sky through the fog above, 6-point rule; "
                     "techniques/height_fog/README.md, \"The sky attenuated\"), against `gtlab render fog` on "
                     "builtin:terrain (%dx%d, %d samples per pixel "
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
                               "over rows of pixels, vectorised (techniques/height_fog/height_fog_batch.c): %.1f ns (goal < 20 ns).",
                     cost->ns_per_pixel[0], cost->ns_per_pixel[1], cost->ns_per_pixel[2], cost->ns_per_pixel[3],
                     cost->published_batch_ns_per_pixel);
    const height_fog_case *dense = &r->cases[HEIGHT_FOG_SUNS];
    report_finding(ctx->doc, "Height fog",
                   "HeightFog() is exact single scattering (within %.1e) only where its assumptions hold: rays that "
                   "descend by at least H/100, the sun unattenuated by the fog. Its clamp loses %.0f%% of an upward "
                   "ray's optical depth; in dense fog with the sun %.0f degrees up its fog.L is off by RMSE %.3f "
                   "against the full reference (%.3f with the sun attenuated, %.3f with the sky attenuated too).",
                   r->cases[0].published_max_rel_single, 100.0 * r->regimes[4].published_depth_error,
                   dense->sun_elevation_deg, dense->rmse_l[HEIGHT_FOG_MODEL_PUBLISHED],
                   dense->rmse_l[HEIGHT_FOG_MODEL_SUN_ATTENUATED], dense->rmse_l[HEIGHT_FOG_MODEL_SKY_ATTENUATED]);
    add_claims(ctx, r);
    aerial_perspective_section(ctx, section, HEIGHT_FOG_DIR, &r->aerial);
    return 0;
}
