/* The split-sum DFG LUT's section of `gtlab all` (dfg/dfg_study.h): the
 * table's accuracy, and its bilinear lookup's error against the size beside
 * Filament's 128^2. */
#include "dfg/dfg_section.h"

#include <stdio.h>

#include "report/gnuplot_plot.h"
#include "report/report_table.h"

#define ROW dfg_interpolation_result
static const report_column columns[] = {
    REPORT_INT("size N", "size", ROW, size),
    REPORT_REAL("max E, whole square", "max_error_e", "%.2e", ROW, max_error[DFG_ALBEDO]),
    REPORT_REAL("RMS E, whole square", "rms_error_e", "%.2e", ROW, rms_error[DFG_ALBEDO]),
    REPORT_REAL("max A, between centres", "interior_max_error_a", "%.2e", ROW, interior_max_error[DFG_SCALE]),
    REPORT_REAL("max B, between centres", "interior_max_error_b", "%.2e", ROW, interior_max_error[DFG_BIAS]),
    REPORT_REAL("max E, between centres", "interior_max_error_e", "%.2e", ROW, interior_max_error[DFG_ALBEDO]),
    REPORT_REAL("RMS E, between centres", "interior_rms_error_e", "%.2e", ROW, interior_rms_error[DFG_ALBEDO]),
    REPORT_REAL(NULL, "max_error_a", NULL, ROW, max_error[DFG_SCALE]),
    REPORT_REAL(NULL, "max_error_b", NULL, ROW, max_error[DFG_BIAS]),
    REPORT_REAL(NULL, "interior_rms_error_a", NULL, ROW, interior_rms_error[DFG_SCALE]),
    REPORT_REAL(NULL, "interior_rms_error_b", NULL, ROW, interior_rms_error[DFG_BIAS]),
    REPORT_INT(NULL, "interior_points", ROW, interior_points),
    REPORT_REAL("build s", "build_seconds", "%.1f", ROW, build_seconds),
};
static const report_column table_columns[] = {
    REPORT_INT(NULL, "size", dfg_result, request.size),
    REPORT_INT(NULL, "interpolation_points", dfg_result, request.points),
    REPORT_REAL(NULL, "max_quadrature_error_estimate", NULL, dfg_result, max_error_estimate),
    REPORT_REAL(NULL, "smallest_albedo_e", NULL, dfg_result, e_min),
    REPORT_REAL(NULL, "build_seconds", NULL, dfg_result, build_seconds),
};
#undef ROW

/* Interior RMS error of A, B and E against the size, log-log. */
static int plot(const report_context *ctx, gt_error *e)
{
    char data[4096], png[4096], script[8192];
    snprintf(data, sizeof data, "%s/%s/dfg_interpolation.dat", ctx->study.output_dir, DFG_LUTS_DIR);
    snprintf(png, sizeof png, "%s/figures/dfg_interpolation.png", ctx->study.output_dir);
    snprintf(script, sizeof script,
             "set logscale xy\nset xrange [10:400]\nset xlabel 'table size N (N x N)'\nset ylabel 'RMS error between texel centres'\n"
             "set title 'DFG LUT: bilinear lookup against the quadrature'\nset key top right\n"
             "set arrow from %d, graph 0 to %d, graph 1 nohead dashtype 2\n"
             "set label 'Filament' at %d, graph 0.95 right offset -0.5,0\n"
             "plot '%s' using 1:5 with linespoints title 'A', '' using 1:9 with linespoints title 'B', "
             "'' using 1:13 with linespoints title 'E = A + B'\n",
             DFG_FILAMENT_SIZE, DFG_FILAMENT_SIZE, DFG_FILAMENT_SIZE, data);
    return gnuplot_render(script, png, 900, 520, e);
}

static void render_findings(report_context *ctx, const dfg_result *r)
{
    if (r->filament_row < 1)
        return;
    const dfg_interpolation_result *f = &r->by_size[r->filament_row], *half = &r->by_size[r->filament_row - 1];
    report_finding(ctx->doc, "DFG LUT",
                   "At Filament's %dx%d, bilinear lookup of the split-sum DFG table is within %.1e of the exact "
                   "albedo E between texel centres (RMS %.1e); %dx%d has %.1fx the RMS error. Near the borders, "
                   "where a texture clamps, the error reaches %.1e.",
                   f->size, f->size, f->interior_max_error[DFG_ALBEDO], f->interior_rms_error[DFG_ALBEDO], half->size,
                   half->size, half->interior_rms_error[DFG_ALBEDO] / f->interior_rms_error[DFG_ALBEDO],
                   f->max_error[DFG_ALBEDO]);
}

int dfg_section(report_context *ctx, const dfg_result *r, gt_error *e)
{
    char figures[2048];
    if (study_make_dir(&ctx->study, "figures", figures, sizeof figures, e) != 0 || plot(ctx, e) != 0)
        return -1;
    const dfg_request *rq = &r->request;
    report_heading(ctx->doc, 2, "Split-sum DFG LUT (environment BRDF)");
    report_paragraph(ctx->doc,
                     "Karis 2013's split sum tabulates the GGX directional albedo as F0 A(n.v, r) + B(n.v, r) "
                     "(height-correlated Smith masking, Schlick Fresnel), and E = A + B, the single-scattering "
                     "albedo that multiple-scattering energy compensation divides by (Kulla-Conty 2017). The %dx%d "
                     "table is computed by adaptive Gauss-Kronrod quadrature with an error bound of %.1e per texel "
                     "(tested against Monte Carlo and the mirror limit), and written as luts/dfg_%d.exr, .png, .h "
                     "and .hlsl, .glsl. Its smallest E is %.3f: single scattering loses up to %.0f%% of the energy. The "
                     "table below scores the bilinear lookup a GPU performs against the quadrature at %d random "
                     "(n.v, r), for each size; Filament ships %dx%d. 'Between centres' excludes the half-texel "
                     "borders, where clamp-to-edge makes the error first order in 1/N.",
                     rq->size, rq->size, r->max_error_estimate, rq->size, r->e_min, 100.0 * (1.0 - r->e_min),
                     rq->points, DFG_FILAMENT_SIZE, DFG_FILAMENT_SIZE);
    cJSON *json = cJSON_AddObjectToObject(ctx->summary, "dfg");
    report_object(json, "table", table_columns, (int)(sizeof table_columns / sizeof table_columns[0]), r);
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "interpolation"), columns,
                (int)(sizeof columns / sizeof columns[0]), r->by_size, sizeof r->by_size[0], rq->size_count);
    const char *p[1] = {"figures/dfg_interpolation.png"}, *c[1] = {"DFG LUT: RMS interpolation error against size"};
    report_figures(ctx->doc, 1, p, c);
    render_findings(ctx, r);
    return 0;
}
