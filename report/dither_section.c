/* The dithering and blue-noise section of `gtlab all` (studies/dither.h). */
#include "report/dither_section.h"

#include <math.h>
#include <string.h>

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

static void dither_claims(report_context *ctx, const dither_result *r)
{
    static const char *const source = "Gjoel 2016, INSIDE, Dithering";
    const dither_row *tpdf = find_row(r, 0, "blue tpdf-remap"), *rpdf = find_row(r, 0, "white rpdf");
    const dither_row *average = find_row(r, 0, "white tpdf-average (as written)");
    const dither_row *blue = find_row(r, 1, "blue tpdf-remap"), *white = find_row(r, 1, "white tpdf-remap");
    if (!tpdf || !rpdf || !average || !blue || !white)
        return;
    claims_table_add_unreviewed_figure(ctx->claims, source, "the error of triangularly distributed noise is independent of the signal",
                            "noise modulation a of blue noise remapped to TPDF on the 8-bit gradient: Var(f) = c + a "
                            "(f(1-f) - 1/6) over 32 bins of the signal's fraction f (RPDF has a = 1); holds for "
                            "|a| <= 0.1", tpdf->modulation_amplitude, tpdf->modulation_amplitude_se, -0.1, 0.1);
    claims_table_add_unreviewed_figure(ctx->claims, source, "with uniform (RPDF) noise the amount of noise varies across the signal",
                            "the same a for white RPDF; holds above 0.5", rpdf->modulation_amplitude,
                            rpdf->modulation_amplitude_se, 0.5, INFINITY);
    claims_table_add_unreviewed_figure(ctx->claims, source, "a TPDF is made by (rand(seed0) + rand(seed1)) / 2",
                            "the same a for that formula as written (a 1-LSB triangle); holds for |a| <= 0.1, as a "
                            "TPDF's", average->modulation_amplitude, average->modulation_amplitude_se, -0.1, 0.1);
    claims_table_add_unreviewed_figure(ctx->claims, source, "blue noise: perceptually less noise than white",
                            "DSSIM after a 1-pixel display blur of the 8-bit tone-mapped sphere-light render, blue "
                            "over white (both TPDF); holds below 1",
                            blue->dssim_blurred / white->dssim_blurred, 0.0, -INFINITY, 1.0);
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
                   "error variance is %.3f LSB^2 at every signal (modulation a = %+.3f +- %.3f; RPDF's is 1). As written in "
                   "the talk, (rand + rand) / 2 is a 1-LSB triangle: a = %+.2f, not a TPDF; and tex / 255 into a "
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
