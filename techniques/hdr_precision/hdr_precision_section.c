/* The section of Kaplanyan 2010's precision figures (hdr_precision_section.h). */
#include "hdr_precision/hdr_precision_section.h"

#include <math.h>
#include <stdio.h>

#include "report/gnuplot_plot.h"
#include "report/report_table.h"

typedef struct {
    const char *quantity, *talk;
    double computed, check;
    const char *how;
} figure_row;

static const report_column columns[] = {
    REPORT_STRING("quantity", "quantity", figure_row, quantity),
    REPORT_STRING("the talk", "talk", figure_row, talk),
    REPORT_REAL("gtlab (closed form)", "computed", "%.8g", figure_row, computed),
    REPORT_REAL("check (bisection / other)", "check", "%.8g", figure_row, check),
    REPORT_STRING("how", "how", figure_row, how),
};

static int plot(const report_context *ctx, const hdr_precision_result *r, gt_error *e)
{
    char data[4096], png[4096], script[8192];
    snprintf(data, sizeof data, "%s/%s/code_steps.dat", ctx->study.output_dir, HDR_PRECISION_DIR);
    snprintf(png, sizeof png, "%s/figures/hdr_code_steps.png", ctx->study.output_dir);
    snprintf(script, sizeof script,
             "set logscale xy\nset xlabel 'linear value x'\nset ylabel 'step of one 8-bit code (linear units)'\n"
             "set title '8-bit storage: gamma vs linear precision'\nset key top left\n"
             "set arrow from %.6f, graph 0 to %.6f, graph 1 nohead dashtype 2\n"
             "set label 'equal (gamma 2.2)' at %.6f, graph 0.1 left offset 0.5,0\n"
             "set arrow from %.6f, graph 0 to %.6f, graph 1 nohead dashtype 3\n"
             "set label 'the talk: 116/255' at %.6f, graph 0.05 left offset 0.5,0\n"
             "plot '%s' using 1:2 with lines title 'linear', '' using 1:3 with lines title 'gamma 2.2', "
             "'' using 1:4 with lines title 'sRGB'\n",
             r->gamma22_point, r->gamma22_point, r->gamma22_point, r->talk_median, r->talk_median, r->talk_median,
             data);
    return gnuplot_render(script, png, 900, 520, e);
}

static const claim_record kEqualPrecision = {
    .talk = "Kaplanyan 2010 (CryENGINE 3)", .seed = "004", .section = "Gamma vs linear space for color textures",
    .quote = "This point is in the **linear space**. This means that the linear space has better precision above "
             "the value 116/255. And the gamma space is more precise below it.",
    .setting = "8-bit colour textures stored either linearly or in gamma space (a power function; the talk names "
               "no exponent here, gamma 2.2 is the usual one), "
               "the two compared by the derivatives of their transformations in linear space; the point chooses "
               "a texture's storage from its histogram",
    .setting_match = CLAIM_SETTING_INDEPENDENT,
    .setting_note = "a point of two functions, computed in closed form: nothing of gtlab's setting enters",
    .reading = "one 8-bit code step of linear storage is smaller than one of gamma-2.2 storage exactly above "
               "linear x = 5/11 = 0.45 ~ 116/255; the figure is that point (2.2 g^1.2 = 1 at g = x^(1/2.2)), "
               "which lies at 0.236 in linear and 0.518 = 132/255 in gamma space, so neither space gives 116/255 "
               "(5/11 solves 2.2 x = 1, the derivative without its power). No other exponent gives it either: "
               "for a power g the point is g^(-g/(g-1)), below its limit 1/e = 0.368 (g -> 1) for every g > 1. "
               "Of the sentence's two halves the "
               "first holds (linear is the finer storage above 116/255, as everywhere above 0.236) and the second "
               "fails from 0.236 to 116/255, where linear is the finer too: the point that the rule of thumb "
               "counts texels above is about twice too high in linear terms.",
    .form = CLAIM_RANGE, .low = 0.445, .high = 116.5 / 255.0, .tolerance_source = CLAIM_TOLERANCE_CLAIM_NUMBER,
    .tolerance = "the talk's 0.45 ~ 116/255 at its printed precision: 0.445 to 116.5/255"};

static const claim_record kExponentialBound = {
    .talk = "Kaplanyan 2010 (CryENGINE 3)", .seed = "004", .section = "HDR on consoles: lower bound estimator",
    .quote = "Exponential tone mapping $T(c) = 1 - e^{-\\frac{c}{l}}$ - Estimator $c_{min} = -l "
             "\\ln\\left(\\frac{510}{509}\\right) \\approx 0.00196271l$",
    .setting = "the HDR buffer's lower bound from the inverse tone mapper at the display's threshold 0.5/255 "
               "(l: the frame's average luminance)",
    .setting_match = CLAIM_SETTING_INDEPENDENT,
    .setting_note = "an exact derivation: nothing of gtlab's setting enters",
    .reading = "T(c_min) = 0.5/255 gives c_min = -l ln(1 - 1/510) = +l ln(510/509) ~ 0.00196271 l (the slide's "
               "minus sign is a typo: its number is the positive root).",
    .form = CLAIM_RANGE, .low = 0.001962705, .high = 0.001962715, .tolerance_source = CLAIM_TOLERANCE_CLAIM_NUMBER,
    .tolerance = "the talk's 0.00196271 at its printed precision (+-5e-9)"};

static const claim_record kFilmicBound = {
    .talk = "Kaplanyan 2010 (CryENGINE 3)", .seed = "004", .section = "HDR on consoles: lower bound estimator",
    .quote = "Estimator $c_{min} \\approx 0.0119052l$",
    .setting = "the HDR buffer's lower bound from the inverse of the filmic tone mapper (the slide's T(c'), c' = "
               "c/l - 0.004, with its ^2.2) at the display's threshold 0.5/255",
    .setting_match = CLAIM_SETTING_INDEPENDENT,
    .setting_note = "an exact derivation: nothing of gtlab's setting enters",
    .reading = "T(c_min) = 0.5/255 with Hejl and Burgess-Dawson's curve c'(6.2c' + 0.5)/(c'(6.2c' + 1.7) + 0.06) "
               "raised to 2.2 gives c_min ~ 0.0119052 l (the slide prints the denominator as 6.2(c' + 1.7), a "
               "typo: read as printed the bound is another number, shown in the section).",
    .form = CLAIM_RANGE, .low = 0.01190515, .high = 0.01190525, .tolerance_source = CLAIM_TOLERANCE_CLAIM_NUMBER,
    .tolerance = "the talk's 0.0119052 at its printed precision (+-5e-8)"};

void hdr_precision_add_claims(claims_table *t, const hdr_precision_result *r)
{
    claims_table_add(t, &kEqualPrecision, r->gamma22_point, 0.0,
                     "linear x where one 8-bit code step of gamma 2.2 equals one of linear storage, closed form "
                     "(gamma-space value %.4f = %.1f/255)",
                     pow(r->gamma22_point, 1.0 / 2.2), 255.0 * pow(r->gamma22_point, 1.0 / 2.2));
    claims_table_add(t, &kExponentialBound, r->exponential_c_min, 0.0,
                     "c_min / l = ln(510/509), closed form (bisection %.10f)", r->exponential_bisection);
    claims_table_add(t, &kFilmicBound, r->filmic_c_min, 0.0,
                     "c_min / l, root of the filmic curve^2.2 = 0.5/255, closed form (bisection %.9f)",
                     r->filmic_bisection);
}

int hdr_precision_section(report_context *ctx, const hdr_precision_result *r, gt_error *e)
{
    char figures[2048];
    if (study_make_dir(&ctx->study, "figures", figures, sizeof figures, e) != 0 || plot(ctx, r, e) != 0)
        return -1;
    report_heading(ctx->doc, 2, "Colour precision and the HDR range (CryENGINE 3)");
    report_paragraph(ctx->doc,
                     "Kaplanyan 2010 chooses gamma or linear 8-bit storage per texture by the point where the two "
                     "are equally precise, and bounds an HDR buffer's range from below by inverting the tone "
                     "mapper at the display's threshold 0.5/255 (l: the frame's average luminance). Each figure is "
                     "derived in closed form (hdr_precision/hdr_precision.h) and checked independently.");
    figure_row rows[6] = {
        {"equal-precision point, gamma 2.2 (linear x)", "5/11 = 0.4545 ~ 116/255", r->gamma22_point,
         r->talk_median, "gamma g^1.2 = 1; check column: the talk's 5/11"},
        {"equal-precision point, sRGB (linear x)", "-", r->srgb_point, r->gamma22_point,
         "d sRGB/dx = 1; check column: gamma 2.2"},
        {"exponential c_min / l", "-ln(510/509) ~ 0.00196271", r->exponential_c_min, r->exponential_bisection,
         "-ln(1 - 1/510) = +ln(510/509): the slide's minus sign is a typo"},
        {"filmic c_min / l", "0.0119052", r->filmic_c_min, r->filmic_bisection,
         "quadratic root, threshold on the linear (^2.2) output"},
        {"filmic c_min / l, slide's denominator 6.2(c'+1.7)", "-", r->filmic_transcribed_c_min, r->filmic_c_min,
         "bisection; check column: 6.2c'+1.7 (Hejl-Burgess-Dawson)"},
        {"filmic c_min / l, threshold on display value", "-", r->filmic_display_threshold_c_min, r->filmic_c_min,
         "bisection; check column: on the linear output"},
    };
    report_rows(ctx->doc, cJSON_AddArrayToObject(ctx->summary, "hdr_precision"), columns,
                (int)(sizeof columns / sizeof columns[0]), rows, sizeof rows[0], 6);
    const char *p[1] = {"figures/hdr_code_steps.png"}, *c[1] = {"One 8-bit code's step: gamma vs linear"};
    report_figures(ctx->doc, 1, p, c);
    report_finding(ctx->doc, "colour precision",
                   "8-bit linear storage is finer than gamma 2.2 above linear x = %.4f (%.0f/255; sRGB %.4f), "
                   "which is %.0f/255 in gamma space: in neither space the talk's 5/11 = 116/255, which solves "
                   "2.2 x = 1 instead of 2.2 g^1.2 = 1.",
                   r->gamma22_point, r->gamma22_point * 255.0, r->srgb_point,
                   255.0 * pow(r->gamma22_point, 1.0 / 2.2));
    report_finding(ctx->doc, "HDR range",
                   "Both lower bounds reproduce (exponential %.8f l, filmic %.7f l) once two slide typos are "
                   "read right: the exponential bound is +l ln(510/509), and the filmic denominator is "
                   "c'(6.2c' + 1.7) + 0.06 (as printed, 6.2(c' + 1.7), the bound would be %.4f l).",
                   r->exponential_c_min, r->filmic_c_min, r->filmic_transcribed_c_min);
    hdr_precision_add_claims(ctx->claims, r);
    return 0;
}
