/* The Decima atmosphere LUTs' section of `gtlab all` (studies/atmosphere_luts.h). */
#include "report/atmosphere_section.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "report/claims_table.h"
#include "report/gnuplot_plot.h"
#include "report/report_table.h"

static const char *const TABLE_NAMES[ATMOSPHERE_TABLES] = {"L_inscatter", "L_sun", "L_sky"};

static void table_cell(const void *row, char *text, size_t size)
{
    snprintf(text, size, "%s", TABLE_NAMES[((const atmosphere_luts_row *)row)->table]);
}

static void sizes_cell(const void *row, char *text, size_t size)
{
    const atmosphere_luts_row *x = row;
    if (x->table == ATMOSPHERE_TABLE_INSCATTER)
        snprintf(text, size, "(%d, %d, %d, %d)", x->sizes[0], x->sizes[1], x->sizes[2], x->sizes[3]);
    else
        snprintf(text, size, "(%d, %d, %d)", x->sizes[0], x->sizes[2], x->sizes[3]);
}

static void verdict_cell(const void *row, char *text, size_t size)
{
    snprintf(text, size, "%s", atmosphere_luts_row_suffices(row) ? "yes" : "no");
}

#define ROW atmosphere_luts_row
static const report_column columns[] = {
    REPORT_CELL("table", table_cell),
    REPORT_TEXT("departs from the talk", "label", ROW, label),
    REPORT_CELL("sizes", sizes_cell),
    REPORT_INT(NULL, "table", ROW, table),
    REPORT_REAL("bytes", "bytes", "%.0f", ROW, bytes),
    REPORT_REAL("interpolation p95", "interpolation_p95", "%.3g", ROW, error.interpolation.p95),
    REPORT_REAL("interpolation max", "interpolation_max", "%.3g", ROW, error.interpolation.max),
    REPORT_REAL(NULL, "interpolation_rms", NULL, ROW, error.interpolation.rms),
    REPORT_REAL("quadrature p95", "quadrature_p95", "%.2e", ROW, error.quadrature.p95),
    REPORT_REAL(NULL, "quadrature_max", NULL, ROW, error.quadrature.max),
    REPORT_REAL("total p95", "total_p95", "%.3g", ROW, error.total.p95),
    REPORT_REAL("its s.e.", "total_p95_se", "%.2g", ROW, error.total.p95_se),
    REPORT_REAL("total p95, sun >= 10 deg", "day_total_p95", "%.3g", ROW, error.day_total.p95),
    REPORT_REAL("its s.e.", "day_total_p95_se", "%.2g", ROW, error.day_total.p95_se),
    REPORT_CELL("within 2%", verdict_cell),
};
static const report_column summary_columns[] = {
    REPORT_INT(NULL, "points", atmosphere_luts_result, request.points),
    REPORT_INT(NULL, "blends", atmosphere_luts_result, request.blend_count),
    REPORT_REAL(NULL, "build_seconds", NULL, atmosphere_luts_result, build_seconds),
    REPORT_REAL(NULL, "reference_error_estimate", NULL, atmosphere_luts_result, quadrature_estimate),
};
#undef ROW

/* Total p95 error against bytes, one series per table, log-log. */
static int plot(const report_context *ctx, gt_error *e)
{
    char data[4096], png[4096], script[8192];
    snprintf(data, sizeof data, "%s/%s/atmosphere_sizes.dat", ctx->study.output_dir, ATMOSPHERE_LUTS_DIR);
    snprintf(png, sizeof png, "%s/figures/atmosphere_sizes.png", ctx->study.output_dir);
    snprintf(script, sizeof script,
             "set logscale xy\nset xrange [500:2e6]\nset xlabel 'table size [bytes]'\nset ylabel '95th percentile of the relative error'\n"
             "set title 'Decima atmosphere LUTs: error against memory (one axis at a time from the talk size)'\n"
             "set key outside right\nset arrow from graph 0, first %g to graph 1, first %g nohead dashtype 2\n"
             "plot '%s' using ($1 == 0 ? $2 : 1/0):6 with points pt 7 title 'in-scatter', "
             "'' using ($1 == 1 ? $2 : 1/0):6 with points pt 5 title 'sun', "
             "'' using ($1 == 2 ? $2 : 1/0):6 with points pt 9 title 'sky', "
             "'' using ($1 == 0 ? $2 : 1/0):4 with points pt 6 title 'in-scatter, interpolation max'\n",
             ATMOSPHERE_TOLERANCE, ATMOSPHERE_TOLERANCE, data);
    return gnuplot_render(script, png, 1000, 560, e);
}

/* Claims rows for the in-scatter table only: the talk's sun and sky tables
 * hold one altitude, the light at a "representative position", so scoring
 * them over 0-2 km is not the talk's setting (docs/decisions.md); their
 * errors stay in the table and the findings, without a verdict. */
static void add_claims(report_context *ctx, const atmosphere_luts_result *r)
{
    for (int table = 0; table < 1; ++table) {
        int k = r->talk_row[table];
        if (k < 0)
            continue;
        const atmosphere_luts_row *x = &r->rows[k];
        char statement[CLAIM_TEXT], quantity[CLAIM_TEXT];
        snprintf(statement, sizeof statement, "%s at (%s) suffices (%s)", TABLE_NAMES[table],
                 table == 0 ? "8, 64, 8, 4" : "64, 1, 4", table == 0 ? "128 KB" : "4 KB");
        snprintf(quantity, sizeof quantity,
                 "95th percentile of the lookup's relative error against direct integration (tolerance 2%% or the "
                 "quadrature's %.1e)", x->error.quadrature.p95);
        double high = fmax(ATMOSPHERE_TOLERANCE, x->error.quadrature.p95);
        claims_table_add_unreviewed_figure(ctx->claims, "Kojima 2017, Height fog: Precomputation", statement, quantity,
                                x->error.total.p95, x->error.total.p95_se, 0.0, high);
        strncat(statement, ", sun 10 deg or more above the horizon", sizeof statement - strlen(statement) - 1);
        claims_table_add_unreviewed_figure(ctx->claims, "Kojima 2017, Height fog: Precomputation", statement, quantity,
                                x->error.day_total.p95, x->error.day_total.p95_se, 0.0, high);
    }
}

static void render_findings(report_context *ctx, const atmosphere_luts_result *r)
{
    for (int table = 0; table < ATMOSPHERE_TABLES; ++table) {
        int k = r->talk_row[table], s = r->smallest_within[table];
        if (k < 0)
            continue;
        const atmosphere_luts_row *x = &r->rows[k];
        char smallest[160];
        if (s >= 0)
            snprintf(smallest, sizeof smallest, "the smallest evaluated table within 2%% is %s (%.0f bytes)",
                     r->rows[s].label, r->rows[s].bytes);
        else
            snprintf(smallest, sizeof smallest, "no evaluated size (one axis at a time) is within 2%%");
        report_finding(ctx->doc, "Atmosphere LUTs",
                       "%s at the talk's size (%.0f bytes): 95%% of lookups within %.1f%% +- %.1f%% of direct integration "
                       "(interpolation %.1f%%, quadrature %.2f%%), worst %.0f%%; with the sun 10 degrees or more "
                       "above the horizon, within %.1f%%; %s.",
                       TABLE_NAMES[table], x->bytes, 100.0 * x->error.total.p95, 100.0 * x->error.total.p95_se,
                       100.0 * x->error.interpolation.p95, 100.0 * x->error.quadrature.p95,
                       100.0 * x->error.interpolation.max, 100.0 * x->error.day_total.p95, smallest);
    }
}

int atmosphere_section(report_context *ctx, const atmosphere_luts_result *r, gt_error *e)
{
    char figures[2048];
    if (study_make_dir(&ctx->study, "figures", figures, sizeof figures, e) != 0 || plot(ctx, e) != 0)
        return -1;
    report_heading(ctx->doc, 2, "Atmosphere LUTs of the Decima height fog (Kojima 2017)");
    report_paragraph(
        ctx->doc,
        "The talk feeds its analytic height fog from three precomputed tables: L_inscatter(theta_s, theta_v, y, t) "
        "per species without phase (the runtime applies p_i(theta_sv)), L_sun(theta_s, y, t) and L_sky(theta_s, y, t), "
        "for a blend t between two weathers, at (8, 64, 8, 4) = 128 KB and (64, 1, 4) = 4 KB. gtlab computes them for "
        "Bruneton 2017's atmosphere (clear) and a dense-fog weather (Mie x50, scale height 0.6 km), with multiple "
        "scattering to order 5 (docs/decisions.md: the definitions), y over [0, %.0f m], and writes them as "
        "luts/atmosphere/ (EXR, C header, HLSL, GLSL: one lookup source). The full set for two weathers at the talk's "
        "sizes builds in %.1f s. Each table is scored at %d random points (theta_v over the sky, t off the grid) "
        "against direct integration (every optical depth by quadrature; its own error estimate %.1e), as the 95th "
        "percentile and the maximum of the relative error (floor 1e-3 of the table's brightest value), split into "
        "the lookup's interpolation and the build's quadrature; each percentile's standard error is a bootstrap over "
        "the points (2000 resamples).",
        ATMOSPHERE_LUT_MAX_ALTITUDE, r->build_seconds, r->request.points, r->quadrature_estimate);
    cJSON *json = cJSON_AddObjectToObject(ctx->summary, "atmosphere_luts");
    report_object(json, "study", summary_columns, (int)(sizeof summary_columns / sizeof summary_columns[0]), r);
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "sizes"), columns, (int)(sizeof columns / sizeof columns[0]),
                r->rows, sizeof r->rows[0], r->row_count);
    const char *p[1] = {"figures/atmosphere_sizes.png"}, *c[1] = {"Atmosphere LUTs: error against memory"};
    report_figures(ctx->doc, 1, p, c);
    render_findings(ctx, r);
    add_claims(ctx, r);
    return 0;
}
