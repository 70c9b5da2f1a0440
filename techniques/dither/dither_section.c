/* The dithering and blue-noise section of `gtlab all` (dither_study.h). */
#include "dither/dither_section.h"

#include <math.h>
#include <string.h>

#include "report/claim_thresholds.h"
#include "report/report_table.h"

#define ROW dither_row
static const report_column columns[] = {
    REPORT_TEXT("dither", "dither", ROW, label),
    REPORT_REAL("bias (LSB)", "bias", "%+.3f", ROW, bias),
    REPORT_REAL("worst bias over f", "worst_bin_bias", "%.3f", ROW, worst_bin_bias),
    REPORT_REAL("error variance (LSB^2)", "variance", "%.3f", ROW, variance),
    REPORT_REAL("variance spread over f (LSB^2)", "modulation", "%.3f", ROW, modulation),
    REPORT_REAL("modulation a (RPDF 1, TPDF 0)", "modulation_amplitude", "%+.3f", ROW, modulation_amplitude),
    REPORT_REAL("s.e. of a", "modulation_amplitude_se", "%.3f", ROW, modulation_amplitude_se),
    REPORT_INT("longest run", "longest_run", ROW, longest_run),
    REPORT_REAL("error power below Nyquist/4", "low_power_share", "%.3f", ROW, low_power_share),
    REPORT_REAL("DSSIM", "dssim", "%.2e", ROW, dssim),
    REPORT_REAL("DSSIM, blurred", "dssim_blurred", "%.2e", ROW, dssim_blurred),
};
#undef ROW
#define ROW dither_small_float_row
static const report_column float_columns[] = {
    REPORT_STRING("dither", "dither", ROW, kind),
    REPORT_REAL("worst |bias| (spacings)", "worst_bias", "%.3f", ROW, worst_bias),
    REPORT_REAL("largest variance", "worst_variance", "%.3f", ROW, worst_variance),
    REPORT_REAL("smallest variance", "best_variance", "%.3f", ROW, best_variance),
};
#undef ROW

/* The row of the given label in image i, or NULL. */
static const dither_row *find_row(const dither_result *r, int i, const char *label)
{
    for (int k = 0; k < r->images[i].row_count; ++k)
        if (strcmp(r->images[i].rows[k].label, label) == 0)
            return &r->images[i].rows[k];
    return NULL;
}

#define INSIDE_TALK "Gjøl & Svendsen 2016 (INSIDE)"
#define DITHER_SETTING                                                                                                \
    "dither added before quantisation to 8-bit UNORM targets (back buffer, light buffer, G-buffer normals) of a "    \
    "1080p game, noise from ALU RPDF/TPDF random or a tiled 256^2 blue-noise texture"
#define DITHER_SETTING_NOTE                                                                                           \
    "an 8-bit gradient (0.20 .. 0.30) instead of game frames, gtlab's own void-and-cluster texture: the error's "    \
    "distribution at each signal level depends on the noise's distribution, not on the image or the texture's size"
/* Modulation a: the error variance Var(f) = c + a (f (1 - f) - 1/6) over the
 * signal's fraction f; RPDF's a = 1 is what the talk shows as visible bands. */
#define MODULATION_TOLERANCE                                                                                          \
    "the talk's own comparison: RPDF's modulation (a = 1) 'causing bands with visibly less noise', TPDF 'Can't see "  \
    "any \"bands\" of no noise'; holds while at most half of RPDF's modulation remains, |a| <= 0.5"

static const claim_record kTriangularIndependent = {
    .talk = INSIDE_TALK, .seed = "002", .section = "Dithering - no noise modulation",
    .quote = "The error resulting from a triangularly distributed noise is independent of the signal.",
    .setting = DITHER_SETTING ", TPDF 2 LSB wide [-0.5, 1.5[", .setting_match = CLAIM_SETTING_INDEPENDENT,
    .setting_note = DITHER_SETTING_NOTE,
    .reading = "with a 2-LSB TPDF dither (the talk's blue noise through remap_tri) the error's variance does not change "
               "with the signal's fraction between code values",
    .form = CLAIM_RANGE, .low = -0.5, .high = 0.5, .tolerance_source = CLAIM_TOLERANCE_TALK_COMPARISON,
    .tolerance = MODULATION_TOLERANCE};

static const claim_record kUniformModulates = {
    .talk = INSIDE_TALK, .seed = "002", .section = "Dithering: white noise, uniform PDF, 1bit [0.0; 1.0[",
    .quote = "almost no noise near “correct” values ... the amount of noise varies across the signal, causing bands "
             "with visibly less noise to appear",
    .setting = DITHER_SETTING ", RPDF 1 LSB wide [0, 1[", .setting_match = CLAIM_SETTING_INDEPENDENT,
    .setting_note = DITHER_SETTING_NOTE,
    .reading = "with a 1-LSB uniform dither the error's variance falls to almost nothing where the signal sits on a "
               "code value",
    .form = CLAIM_RANGE, .low = 0.5, .high = INFINITY, .tolerance_source = CLAIM_TOLERANCE_CLAIM_NUMBER,
    .tolerance = "'almost no noise near correct values': the variance at a whole code value at most half its mean, "
                 "(1 - a) / 6 <= 1/12, so a >= 0.5"};

static const claim_record kTwoUniforms = {
    .talk = INSIDE_TALK, .seed = "002", .section = "Dithering - no noise modulation",
    .quote = "Two easy ways to generate a TPDF: 1. Add to uniform distributions (literally just "
             "$(\\text{rand}(\\text{seed0})+\\text{rand}(\\text{seed1}))/2$)",
    .setting = DITHER_SETTING ", TPDF 2 LSB wide [-0.5, 1.5[ ('Also now **2bit** wide')",
    .setting_match = CLAIM_SETTING_INDEPENDENT, .setting_note = DITHER_SETTING_NOTE,
    .reading = "adding two uniform random numbers gives a triangular PDF (true: their sum's density is a triangle); "
               "the talk's 2-LSB TPDF is the sum minus 1/2, and the /2 of the transcribed formula halves its width",
    .stronger_reading = "the formula as transcribed, (rand + rand) / 2 (a 1-LSB triangle on [0, 1[), used as the "
                        "dither removes noise modulation as the talk's 2-LSB TPDF does",
    .form = CLAIM_RANGE, .low = -0.5, .high = 0.5, .tolerance_source = CLAIM_TOLERANCE_TALK_COMPARISON,
    .tolerance = MODULATION_TOLERANCE};

static const claim_record kBlueLessNoise = {
    .talk = INSIDE_TALK, .seed = "002", .section = "Dithering using Blue Noise (high pass)",
    .quote = "triangular PDF blue noise, 2bit [-0.5;1.5[ ... Perceptually less noise",
    .setting = DITHER_SETTING ", blue against white noise, both remapped to a 2-LSB TPDF; of its own TPDF-dithered "
               "image the talk says 'this image has a lot of noise though – not really visible'",
    .setting_match = CLAIM_SETTING_INDEPENDENT,
    .setting_note = "a tone-mapped sphere-light render quantised to 8 bits at gtlab's size instead of game frames; "
                    "seen through a 1-pixel display blur (a viewer's low-pass); a per-pixel noise's visibility at a "
                    "given display density does not depend on the frame's size",
    .reading = "blue TPDF dither leaves an 8-bit image perceptually closer to the unquantised one than white TPDF "
               "dither, by a margin a viewer could see",
    .form = CLAIM_BETTER, .margin = CLAIM_DSSIM_JUST_NOTICEABLE, .tolerance_source = CLAIM_TOLERANCE_TALK_COMPARISON,
    .tolerance = "the talk's comparison, blue against white, past a just noticeable DSSIM "
                 "(CLAIM_DSSIM_JUST_NOTICEABLE)"};

static void dither_claims(report_context *ctx, const dither_result *r)
{
    const dither_row *tpdf = find_row(r, 0, "blue tpdf-remap"), *rpdf = find_row(r, 0, "white rpdf");
    const dither_row *average = find_row(r, 0, "white tpdf-average (as written)");
    const dither_row *blue = find_row(r, 1, "blue tpdf-remap"), *white = find_row(r, 1, "white tpdf-remap");
    if (!tpdf || !rpdf || !average || !blue || !white)
        return;
    static const char *const modulation =
        "on the 8-bit gradient: Var(f) = c + a (f(1-f) - 1/6) fitted over 32 bins of the signal's fraction f (RPDF "
        "a = 1, TPDF a = 0), s.e. from the fit";
    claims_table_add(ctx->claims, &kTriangularIndependent, tpdf->modulation_amplitude, tpdf->modulation_amplitude_se,
                     "noise modulation a of blue noise remapped to TPDF (remap_tri) %s", modulation);
    claims_table_add(ctx->claims, &kUniformModulates, rpdf->modulation_amplitude, rpdf->modulation_amplitude_se,
                     "noise modulation a of white RPDF %s", modulation);
    claims_table_add(ctx->claims, &kTwoUniforms, average->modulation_amplitude, average->modulation_amplitude_se,
                     "noise modulation a of (rand + rand) / 2 as transcribed %s", modulation);
    claims_table_add(ctx->claims, &kBlueLessNoise, blue->dssim_blurred - white->dssim_blurred, 0.0,
                     "DSSIM after a 1-pixel display blur of the 8-bit tone-mapped sphere-light render against the "
                     "unquantised one, blue TPDF (%.2e) minus white TPDF (%.2e); one deterministic image each",
                     blue->dssim_blurred, white->dssim_blurred);
}

static void dither_findings(report_context *ctx, const dither_result *r)
{
    const dither_row *none = find_row(r, 0, "none"), *tpdf = find_row(r, 0, "blue tpdf-remap");
    const dither_row *written = find_row(r, 0, "blue rpdf (as written)");
    const dither_row *average = find_row(r, 0, "white tpdf-average (as written)");
    if (!none || !tpdf || !written || !average)
        return;
    report_finding(ctx->doc, "Dithering",
                   "On an 8-bit gradient, undithered runs of %d equal pixels fall to %d with blue TPDF dither, whose "
                   "error variance is %.3f LSB^2 at every signal (modulation a = %+.3f +- %.3f; RPDF's is 1). As transcribed, "
                   "(rand + rand) / 2 is a triangle 1 LSB wide, not the talk's 2-LSB TPDF: a = %+.2f (the sum minus 1/2 "
                   "is the talk's); and tex / 255 into a "
                   "rounding 8-bit target is biased by %+.3f LSB (subtract 1/2).",
                   none->longest_run, tpdf->longest_run, tpdf->variance, tpdf->modulation_amplitude,
                   tpdf->modulation_amplitude_se, average->modulation_amplitude, written->bias);
}

int dither_section(report_context *ctx, const dither_result *r, gt_error *e)
{
    (void)e;
    const dither_request *rq = &r->request;
    report_heading(ctx->doc, 2, "Dithering and blue noise (INSIDE)");
    report_paragraph(ctx->doc,
                     "Quantisation to 8-bit UNORM (round to nearest) of a %dx%d gradient (0.20 .. 0.30) and of a "
                     "%dx%d tone-mapped sphere-light render (%d spp), with no dither, each pattern as RPDF and as "
                     "TPDF (the talk's remap_tri), and the talk's two formulas as written; then to 10-bit UNORM with no, "
                     "blue RPDF and blue TPDF dither (rows \"..., 10-bit\", errors in 10-bit LSB). Every pattern has a flat "
                     "histogram, so the dither's power is equal. Blue noise: void-and-cluster %d^2, 4 channels, "
                     "built in %.2f s (dither/blue_noise_%d.exr, .png); its radially averaged power below n/16 is "
                     "%.3f of white noise's and %.2f above n/4; after remap_tri (not monotone) %.3f and %.2f of "
                     "white TPDF's.",
                     rq->gradient_width, rq->gradient_height, rq->render_width, rq->render_height, rq->render_spp,
                     rq->blue_noise_size, r->blue_noise_seconds, rq->blue_noise_size, r->blue_low_ring_power,
                     r->blue_high_ring_power, r->remapped_low_ring_power, r->remapped_high_ring_power);
    cJSON *json = cJSON_AddObjectToObject(ctx->summary, "dither");
    for (int i = 0; i < DITHER_IMAGES; ++i) {
        report_paragraph(ctx->doc, "%s:", r->images[i].image_name);
        report_rows(ctx->doc, cJSON_AddArrayToObject(json, r->images[i].image_name), columns,
                    (int)(sizeof columns / sizeof columns[0]), r->images[i].rows, sizeof r->images[i].rows[0],
                    r->images[i].row_count);
    }
    report_paragraph(ctx->doc, "R11G11B10 (6-bit mantissa, round to nearest even) of a linear ramp over [0.5, 4[, "
                               "dither scaled by the local spacing of representable values:");
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "r11g11b10"), float_columns,
                (int)(sizeof float_columns / sizeof float_columns[0]), r->small_float, sizeof r->small_float[0],
                DITHER_SMALL_FLOAT_ROWS);
    dither_claims(ctx, r);
    dither_findings(ctx, r);
    return 0;
}
