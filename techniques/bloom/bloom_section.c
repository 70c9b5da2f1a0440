/* The bloom 13 -> 9 tap section of `gtlab all` (bloom_study.h). */
#include "bloom/bloom_section.h"

#include <math.h>

#include "report/report_table.h"

#define ROW bloom_target_result
static const report_column target_columns[] = {
    REPORT_STRING("target", "target", ROW, target),
    REPORT_REAL("worst texel weight error", "worst_error", "%.5f", ROW, fit.worst_error),
    REPORT_REAL("RMS", "rms_error", "%.5f", ROW, fit.rms_error),
    REPORT_REAL("largest target weight", "max_target_weight", "%.4f", ROW, max_target_weight),
    REPORT_REAL("worst error in a tap's normalised weights (talk's 0.08)", "worst_normalised_error", "%.4f", ROW,
                worst_normalised_error),
    REPORT_REAL("max response error", "response_max_error", "%.4f", ROW, response_max_error),
    REPORT_REAL("H target at pi/2", "response_target_nyquist", "%.4f", ROW, response_target_nyquist),
    REPORT_REAL("H fit at pi/2", "response_fit_nyquist", "%.4f", ROW, response_fit_nyquist),
    REPORT_REAL("worst, any phase", "worst_any_phase", "%.4f", ROW, worst_any_phase),
    REPORT_REAL("worst, 135 -> 67 rows", "worst_odd_mip", "%.4f", ROW, worst_odd_mip),
    REPORT_REAL("RMS, 135 -> 67 rows", "rms_odd_mip", "%.5f", ROW, rms_odd_mip),
    REPORT_INT("params on bounds", "at_bound", ROW, fit.at_bound),
    REPORT_INT(NULL, "iterations", ROW, fit.iterations),
};
#undef ROW
#define ROW bloom_level_result
static const report_column level_columns[] = {
    REPORT_INT("width", "width", ROW, width),
    REPORT_INT("height", "height", ROW, height),
    REPORT_INT("exact half", "exact_half", ROW, exact_half),
    REPORT_REAL("DSSIM 9 (LSQ) vs 13 taps", "dssim_jimenez", "%.2e", ROW, dssim[0]),
    REPORT_REAL("policy vs 13", "dssim_policy_jimenez", "%.2e", ROW, dssim_policy[0]),
    REPORT_REAL("9 (held) vs 13", "dssim_jimenez_held", "%.2e", ROW, dssim[1]),
    REPORT_REAL("policy (held) vs 13", "dssim_policy_jimenez_held", "%.2e", ROW, dssim_policy[1]),
    REPORT_REAL("9 vs Gaussian", "dssim_gaussian", "%.2e", ROW, dssim[2]),
    REPORT_REAL("policy vs Gaussian", "dssim_policy_gaussian", "%.2e", ROW, dssim_policy[2]),
};
#undef ROW

static void taps_paragraph(report_context *ctx, const bloom_target_result *t)
{
    const bloom_tap *p = t->fit.taps;
    report_paragraph(ctx->doc,
                     "%s fit (offsets in source texels, weight): centre (%.4f, %.4f) %.5f; top (%.4f, %.4f) %.5f; "
                     "top-left corner (%.4f, %.4f) %.5f; the others by symmetry (bloom/bloom_9tap.hlsl, .glsl).",
                     t->target, p[4].x, p[4].y, p[4].w, p[1].x, p[1].y, p[1].w, p[0].x, p[0].y, p[0].w);
}

static double total_weight(const bloom_target_result *t)
{
    double sum = 0.0;
    for (int k = 0; k < BLOOM_FIT_TAPS; ++k)
        sum += t->fit.taps[k].w;
    return sum;
}

#define INSIDE_TALK "Gjøl & Svendsen 2016 (INSIDE)"
#define FIT_SETTING                                                                                                   \
    "Jimenez 2014's 13-tap bloom downsample (weights /128, the talk's table) refitted to 9 bilinear taps that read "  \
    "each texel once, by a Python minimiser (objective not given), for HDR glow at 1080p with a mip pyramid"

static const claim_record kWorstWeightError = {
    .talk = INSIDE_TALK, .seed = "002", .section = "Sample Fitting: utilising bilinear filtering",
    .quote = "worst weight-error of approximation is 0.08", .setting = FIT_SETTING ", at exact half resolution",
    .setting_match = CLAIM_SETTING_TALK,
    .reading = "the 9 taps' worst error in a tap's own bilinear weights (the talk's note: 'Corner sample has 8% error "
               "on bilinear weights, top sample is exact') is 0.08 at its stated precision",
    .form = CLAIM_RANGE, .low = 0.075, .high = 0.085, .tolerance_source = CLAIM_TOLERANCE_CLAIM_NUMBER,
    .tolerance = "0.08 at two decimals: [0.075, 0.085]"};

static const claim_record kExactHalf = {
    .talk = INSIDE_TALK, .seed = "002", .section = "Sample Fitting: utilising bilinear filtering",
    .quote = "Valid only if **exactly ½ resolution**", .setting = FIT_SETTING ", 1920x1080's pyramid",
    .setting_match = CLAIM_SETTING_TALK,
    .reading = "off exact half resolution (1920x1080's first odd step, 240x135 -> 120x67) the 9 taps miss the 13 by "
               "more than the error the talk accepts at half resolution ('Visually good enough')",
    .form = CLAIM_RANGE, .low = 1.0, .high = INFINITY, .tolerance_source = CLAIM_TOLERANCE_CLAIM_NUMBER,
    .tolerance = "the talk's own accepted error: the fit's worst texel-weight error at exact half resolution "
                 "(ratio above 1)"};

static const claim_record kExactMips = {
    .talk = INSIDE_TALK, .seed = "002", .section = "Sample Fitting: utilising bilinear filtering",
    .quote = "1920x1080 => only first 3 mips :( (hint: 1920x1088 => 6 mips)", .setting = FIT_SETTING,
    .setting_match = CLAIM_SETTING_TALK,
    .reading = "halving 1920x1080 gives exact half sizes for 3 levels before the first odd size, 1920x1088 for 6",
    .form = CLAIM_RANGE, .low = 63, .high = 63, .tolerance_source = CLAIM_TOLERANCE_CLAIM_NUMBER,
    .tolerance = "the talk's counts, exactly (3 + 10 x 6 = 63)"};

static void bloom_claims(report_context *ctx, const bloom_result *r)
{
    const bloom_target_result *a = &r->targets[0], *h = &r->targets[1];
    claims_table_add(ctx->claims, &kWorstWeightError, h->worst_normalised_error, 0.0,
                     "worst error of a tap's four bilinear weights, normalised to sum 1, against its 2x2 block's "
                     "(the corner tap), 9 taps fitted to the 13 with each tap's weight held at its block's sum; "
                     "exact (%.4f with free weights)",
                     a->worst_normalised_error);
    claims_table_add(ctx->claims, &kExactHalf, a->worst_odd_mip / a->fit.worst_error, 0.0,
                     "worst texel weight error of the 9 taps (least squares) against the 13 over the rows of 240x135 "
                     "-> 120x67 (%.4f), over the same at exact half resolution (%.4f); exact",
                     a->worst_odd_mip, a->fit.worst_error);
    claims_table_add(ctx->claims, &kExactMips, r->exact_levels_1080 + 10.0 * r->exact_levels_1088, 0.0,
                     "exact halvings before the first odd size from 1920x1080 (%d), plus 10 x those from 1920x1088 "
                     "(%d); exact",
                     r->exact_levels_1080, r->exact_levels_1088);
}

static void bloom_finding(report_context *ctx, const bloom_result *r)
{
    const bloom_target_result *a = &r->targets[0], *h = &r->targets[1], *g = &r->targets[2];
    report_finding(ctx->doc, "Bloom 13 -> 9 taps",
                   "The talk's 0.08 is the corner tap's error in its own normalised bilinear weights: %.4f with the "
                   "taps' weights held at their blocks' sums, %.4f with free weights (whose kernel then sums to %.4f, "
                   "losing light each level). In texel weights the 9 taps miss the 13 by at most %.4f (RMS %.4f): the "
                   "corner block [[1,1],[1,5]]/128 has rank two. Fitted to a Gaussian of the same variance the 9 taps "
                   "are exact (%.1e; the Gaussian is separable). Off half resolution the 9 taps err by up to %.4f on "
                   "the rows of 135 -> 67, %.0fx their half-resolution error.",
                   h->worst_normalised_error, a->worst_normalised_error, total_weight(a), a->fit.worst_error,
                   a->fit.rms_error, g->fit.worst_error, a->worst_odd_mip, a->worst_odd_mip / a->fit.worst_error);
}

int bloom_section(report_context *ctx, const bloom_result *r, gt_error *e)
{
    (void)e;
    const bloom_request *rq = &r->request;
    report_heading(ctx->doc, 2, "Bloom: 13 bilinear taps refitted to 9 (INSIDE)");
    report_paragraph(ctx->doc,
                     "Jimenez 2014's 13-tap downsample covers 6x6 texels at half resolution (weights /128 as in the "
                     "talk's table; variance %.3f texel^2 per axis). Nine bilinear taps, each held inside its 2x2 "
                     "block so every texel is read once, are fitted by Ceres (least squares on the 36 texel weights) "
                     "to it (weights free, or held at each block's sum) and to a Gaussian of the same variance (sigma "
                     "%.4f texels sampled at the texel centres; %.2f%% of the continuous Gaussian lies outside the "
                     "footprint; off half resolution, in the response and in the pyramids the Gaussian reference is "
                     "sampled over 9x9 texels). Phases: the output pixel's offset from a texel corner, 0 at exact half "
                     "resolution; 1920x1080's first odd step is 240x135 -> 120x67. Pyramids: gtlab's sphere-light "
                     "reference at %dx%d (%d spp), tone-mapped x/(1+x).",
                     r->jimenez_variance, r->gaussian_sigma, 100.0 * r->gaussian_outside_mass, rq->width, rq->height,
                     rq->spp);
    cJSON *json = cJSON_AddObjectToObject(ctx->summary, "bloom");
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "fits"), target_columns,
                (int)(sizeof target_columns / sizeof target_columns[0]), r->targets, sizeof r->targets[0], BLOOM_FITS);
    for (int f = 0; f < BLOOM_FITS; ++f)
        taps_paragraph(ctx, &r->targets[f]);
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "pyramid"), level_columns,
                (int)(sizeof level_columns / sizeof level_columns[0]), r->levels, sizeof r->levels[0], r->level_count);
    bloom_claims(ctx, r);
    bloom_finding(ctx, r);
    return 0;
}
