/* The section of Kaplanyan 2010's precision figures (hdr_precision_section.h). */
#include "report/hdr_precision_section.h"

#include <stdio.h>

#include "report/gnuplot_plot.h"
#include "report/report_table.h"

#define SOURCE "Kaplanyan 2010, CryENGINE 3"

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

static void add_claims(report_context *ctx, const hdr_precision_result *r)
{
    claims_table_add_unreviewed_figure(ctx->claims, SOURCE ", gamma vs linear",
                            "linear storage is finer above x = 5/11 ~ 116/255 (linear space)",
                            "x where one 8-bit code step is equal, gamma 2.2", r->gamma22_point, 0.0, 115.5 / 255.0,
                            116.5 / 255.0);
    claims_table_add_unreviewed_figure(ctx->claims, SOURCE ", HDR lower bound", "exponential tone mapping: c_min ~ 0.00196271 l",
                            "l ln(510/509), per unit l", r->exponential_c_min, 0.0, 0.001962705,
                            0.001962715);
    claims_table_add_unreviewed_figure(ctx->claims, SOURCE ", HDR lower bound", "filmic tone mapping: c_min ~ 0.0119052 l",
                            "root of filmic^2.2 = 1/510 (Hejl-Burgess-Dawson), per unit l", r->filmic_c_min, 0.0,
                            0.01190515, 0.01190525);
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
                     "derived in closed form (realtime/hdr_precision.h) and checked independently.");
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
                   "8-bit linear storage is finer than gamma 2.2 above x = %.4f (%.0f/255; sRGB %.4f), not above "
                   "the talk's 5/11 = 116/255, which solves 2.2 x = 1 instead of 2.2 g^1.2 = 1.",
                   r->gamma22_point, r->gamma22_point * 255.0, r->srgb_point);
    report_finding(ctx->doc, "HDR range",
                   "Both lower bounds reproduce (exponential %.8f l, filmic %.7f l) once two slide typos are "
                   "read right: the exponential bound is +l ln(510/509), and the filmic denominator is "
                   "c'(6.2c' + 1.7) + 0.06 (as printed, 6.2(c' + 1.7), the bound would be %.4f l).",
                   r->exponential_c_min, r->filmic_c_min, r->filmic_transcribed_c_min);
    add_claims(ctx, r);
    return 0;
}
