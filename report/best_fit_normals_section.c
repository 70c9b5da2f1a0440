/* The best-fit normals section of `gtlab all` (best_fit_normals_section.h). */
#include "report/best_fit_normals_section.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "luts/best_fit_normals_cells.h"
#include "report/gnuplot_plot.h"
#include "report/report_table.h"

#define SOURCE "Kaplanyan 2010, CryENGINE 3, storage techniques breakdown"

/* One row of the cell-count audit, built from the result. */
typedef struct {
    const char *encoding, *definition, *talk;
    uint64_t cells;
    double percent, bits;
} cells_row;

static const report_column cells_columns[] = {
    REPORT_STRING("encoding", "encoding", cells_row, encoding),
    REPORT_STRING("what is counted (exactly, over the 256^3 cells)", "definition", cells_row, definition),
    REPORT_COUNT("cells", "cells", cells_row, cells),
    REPORT_REAL("% of 256^3", "percent", "%.3f", cells_row, percent),
    REPORT_REAL("bits (log2 cells)", "bits", "%.2f", cells_row, bits),
    REPORT_STRING("the talk", "talk", cells_row, talk),
};

static cells_row make_row(const char *encoding, const char *definition, const char *talk, long cells)
{
    return (cells_row){encoding, definition, talk, (uint64_t)cells, 100.0 * cells / BFN_CELL_COUNT, log2((double)cells)};
}

/* The sampled counts as percentages. */
typedef struct {
    int face;
    double naive, max, best_fit;
} sampled_row;

static const report_column sampled_columns[] = {
    REPORT_INT("cubemap face", "face", sampled_row, face),
    REPORT_REAL("normalised, %", "naive_percent", "%.3f", sampled_row, naive),
    REPORT_REAL("/ max component, %", "max_percent", "%.3f", sampled_row, max),
    REPORT_REAL("best fit (talk's search), %", "best_fit_percent", "%.2f", sampled_row, best_fit),
};

#define ROW normals_encoding_result
static const report_column error_columns[] = {
    REPORT_STRING("encoding", "encoding", ROW, name),
    REPORT_INT("bits", "bits", ROW, bits),
    REPORT_REAL("mean error, deg", "mean_deg", "%.4f", ROW, mean_deg),
    REPORT_REAL("99th pct, deg", "p99_deg", "%.4f", ROW, p99_deg),
    REPORT_REAL("max, deg", "max_deg", "%.4f", ROW, max_deg),
    REPORT_REAL("DSSIM r=0.1", "highlight_dssim_r01", "%.2e", ROW, highlight_dssim[0]),
    REPORT_REAL("DSSIM r=0.2", "highlight_dssim_r02", "%.2e", ROW, highlight_dssim[1]),
    REPORT_REAL("DSSIM r=0.3", "highlight_dssim_r03", "%.2e", ROW, highlight_dssim[2]),
    REPORT_REAL("DSSIM r=0.5", "highlight_dssim_r05", "%.2e", ROW, highlight_dssim[3]),
    REPORT_INT(NULL, "directions", ROW, directions),
};
#undef ROW

static void render_cells(report_context *ctx, const normals_result *r, cJSON *json)
{
    cells_row rows[3] = {
        make_row("normalised", "cells whose box the unit sphere crosses (each reachable)", "289880, 1.73%",
                 r->cells_sphere),
        make_row("/ max component", "cells on the cube's surface, 256^3 - 254^3", "390152, 2.33%", r->cells_surface),
        make_row("best fit", "cells of distinct directions (not a multiple of another cell)", "16482364, 98.2%",
                 r->cells_distinct),
    };
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "cells"), cells_columns,
                (int)(sizeof cells_columns / sizeof cells_columns[0]), rows, sizeof rows[0], 3);
    sampled_row sampled[NORMALS_MAX_FACES];
    for (int i = 0; i < r->request.face_count; ++i) {
        const normals_cells_row *s = &r->sampled[i];
        sampled[i] = (sampled_row){s->face, 100.0 * s->naive / BFN_CELL_COUNT, 100.0 * s->max / BFN_CELL_COUNT,
                                   100.0 * s->best_fit / BFN_CELL_COUNT};
    }
    report_paragraph(ctx->doc,
                     "Counted instead as the talk bakes directions, the distinct cells written for the texel centres "
                     "of a cubemap of the given face size (6 faces): these grow with the face towards the exact "
                     "counts, so a sampled count is a lower bound that depends on the sampling.");
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "sampled_cells"), sampled_columns,
                (int)(sizeof sampled_columns / sizeof sampled_columns[0]), sampled, sizeof sampled[0],
                r->request.face_count);
}

static int plot(const report_context *ctx, const normals_result *r, gt_error *e)
{
    char data[4096], png[4096], script[8192];
    snprintf(data, sizeof data, "%s/%s/cells.dat", ctx->study.output_dir, NORMALS_DIR);
    snprintf(png, sizeof png, "%s/figures/normals_cells.png", ctx->study.output_dir);
    snprintf(script, sizeof script,
             "set logscale x 2\nset xlabel 'cubemap face size (texels)'\nset ylabel '%% of the 256^3 cells used'\n"
             "set title 'RGB8 normals: cells used, sampled on a cubemap vs exact'\nset key at graph 0.98, graph 0.62\n"
             "set logscale y\nset yrange [1:120]\n"
             "plot '%s' using 1:4 with linespoints title 'best fit (talk''s search)', "
             "%.6f title 'exact: distinct directions' dashtype 2, 98.2 title 'the talk: 98.2%%' dashtype 3, "
             "'' using 1:2 with linespoints title 'normalised', %.6f title 'exact: sphere cells' dashtype 2, "
             "1.73 title 'the talk: 1.73%%' dashtype 3\n",
             data, 100.0 * r->cells_distinct / BFN_CELL_COUNT, 100.0 * r->cells_sphere / BFN_CELL_COUNT);
    return gnuplot_render(script, png, 900, 520, e);
}

/* The error distributions: percentile against angular error. */
static int plot_cdf(const report_context *ctx, gt_error *e)
{
    char data[4096], png[4096], script[8192];
    snprintf(data, sizeof data, "%s/%s/error_cdf.dat", ctx->study.output_dir, NORMALS_DIR);
    snprintf(png, sizeof png, "%s/figures/normals_error_cdf.png", ctx->study.output_dir);
    snprintf(script, sizeof script,
             "set xlabel 'angular error (degrees)'\nset ylabel 'percentile'\nset logscale x\nset xrange [0.003:1]\n"
             "set title 'G-buffer normals: error distribution over random directions'\nset key bottom right\n"
             "plot '%s' using 2:1 with lines title 'RGB8 normalised', '' using 3:1 with lines title 'RGB8 / max', "
             "'' using 4:1 with lines title 'RGB8 best fit (table)', '' using 5:1 with lines title 'best fit, "
             "bilinear', '' using 6:1 with lines title 'RGB8 best cell', '' using 10:1 with lines title "
             "'octahedral 2x10 precise', '' using 12:1 with lines title 'octahedral 2x12 precise'\n",
             data);
    return gnuplot_render(script, png, 900, 520, e);
}

static void add_claims(report_context *ctx, const normals_result *r)
{
    claims_table_add_unreviewed_figure(ctx->claims, SOURCE, "normalised normals use ~1.73% of the 256^3 cells (~289880)",
                            "% of cells the unit sphere crosses, exact", 100.0 * r->cells_sphere / BFN_CELL_COUNT, 0.0,
                            1.725, 1.735);
    claims_table_add_unreviewed_figure(ctx->claims, SOURCE, "divided by the maximum component: ~2.33% (~390152)",
                            "% of cells on the cube's surface, exact", 100.0 * r->cells_surface / BFN_CELL_COUNT, 0.0,
                            2.325, 2.335);
    claims_table_add_unreviewed_figure(ctx->claims, SOURCE, "best fit uses ~98.2% of the cells (~16482364)",
                            "% of cells that encode distinct directions, exact",
                            100.0 * r->cells_distinct / BFN_CELL_COUNT, 0.0, 98.15, 98.25);
    claims_table_add_unreviewed_figure(ctx->claims, SOURCE, "both old techniques use ~17 bits",
                            "log2 of the cells normalised normals reach, exact", log2((double)r->cells_sphere), 0.0,
                            16.5, 17.5);
}

static void render_findings(report_context *ctx, const normals_result *r)
{
    const normals_encoding_result *naive = &r->encodings[0], *fit = &r->encodings[2], *bilinear = &r->encodings[3];
    const normals_encoding_result *ideal = &r->encodings[4], *oct12 = &r->encodings[10];
    report_finding(ctx->doc, "best-fit normals",
                   "The %dx%d best-fit table cuts the mean angular error of RGB8 normals from %.3f to %.3f degrees "
                   "(99th percentile %.3f to %.3f), and a glossy highlight's DSSIM at roughness 0.1 from %.1e to "
                   "%.1e; the best cell 24 bits allow is %.4f degrees on average, octahedral 2x12 precise %.4f.",
                   r->request.table_size, r->request.table_size, naive->mean_deg, fit->mean_deg, naive->p99_deg,
                   fit->p99_deg, naive->highlight_dssim[0], fit->highlight_dssim[0], ideal->mean_deg, oct12->mean_deg);
    report_finding(ctx->doc, "best-fit normals",
                   "Read with bilinear filtering (the talk asks for mip-maps), the table's mean error is %.3f "
                   "degrees instead of %.3f: the best scale jumps between neighbouring directions, so averaging "
                   "texels picks a scale that fits neither; sample it with a point filter.",
                   bilinear->mean_deg, fit->mean_deg);
    const normals_cells_row *last = &r->sampled[r->request.face_count - 1];
    report_finding(ctx->doc, "best-fit normals",
                   "Of the talk's cell counts only 2.33%% (the cube's surface, 256^3 - 254^3) is exact; normalised "
                   "normals reach %.2f%% of the cells, not 1.73%% (%.1f bits, not 17), and 98.2%% exceeds the "
                   "%.2f%% of cells that encode distinct directions: sampled on a %d^2 cubemap the talk's search "
                   "writes %.2f%% of the cells, counting cells that repeat a direction.",
                   100.0 * r->cells_sphere / BFN_CELL_COUNT, log2((double)r->cells_sphere),
                   100.0 * r->cells_distinct / BFN_CELL_COUNT, last->face, 100.0 * last->best_fit / BFN_CELL_COUNT);
}

int normals_section(report_context *ctx, const normals_result *r, gt_error *e)
{
    char figures[2048];
    if (study_make_dir(&ctx->study, "figures", figures, sizeof figures, e) != 0 || plot(ctx, r, e) != 0 ||
        plot_cdf(ctx, e) != 0)
        return -1;
    report_heading(ctx->doc, 2, "Best-fit normals in an RGB8 G-buffer (CryENGINE 3)");
    report_paragraph(ctx->doc,
                     "Kaplanyan 2010 stores a unit normal in RGB8 scaled along its ray to the cell whose centre "
                     "deviates least from it, the scale baked per direction into a %dx%d table (Appendix A's search "
                     "and lookup, transcribed; luts/best_fit_normals.h), written here as normals/best_fit_normals_%d."
                     "{exr,png,h,hlsl} (built in %.2f s). First the talk's cell counts, each counted exactly by "
                     "enumerating the 256^3 cells under the stated definition:",
                     r->request.table_size, r->request.table_size, r->request.table_size, r->table_seconds);
    cJSON *json = cJSON_AddObjectToObject(ctx->summary, "best_fit_normals");
    cJSON_AddNumberToObject(json, "table_size", r->request.table_size);
    cJSON_AddNumberToObject(json, "table_seconds", r->table_seconds);
    render_cells(ctx, r, json);
    const char *p[1] = {"figures/normals_cells.png"}, *c[1] = {"Cells used: sampled on a cubemap against exact"};
    report_figures(ctx->doc, 1, p, c);
    report_paragraph(ctx->doc,
                     "Accuracy over %d uniformly random directions (the exhaustive best cell over the first %d): the "
                     "angle between a normal and its decoded value, and DSSIM of a GGX highlight on a gently curved "
                     "surface (normals within 6 degrees, in a generic orientation) rendered with the decoded normals "
                     "against the exact ones, tone-mapped x/(1+x) with the peak at 4. Octahedral: Cigolle et al. "
                     "2014, precise = the best of the four codes around the point.",
                     r->request.directions, r->request.exhaustive_directions);
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "encodings"), error_columns,
                (int)(sizeof error_columns / sizeof error_columns[0]), r->encodings, sizeof r->encodings[0],
                NORMALS_ENCODINGS);
    const char *cp[1] = {"figures/normals_error_cdf.png"}, *cc[1] = {"Angular error distributions"};
    report_figures(ctx->doc, 1, cp, cc);
    const char *hp[4] = {"normals/highlight_exact.png", "normals/highlight_naive.png", "normals/highlight_best_fit.png",
                         "normals/highlight_octahedral10p.png"};
    const char *hc[4] = {"exact normals, roughness 0.2", "RGB8 normalised", "RGB8 best fit (point)",
                         "octahedral 2x10 precise"};
    report_figures(ctx->doc, 4, hp, hc);
    render_findings(ctx, r);
    add_claims(ctx, r);
    return 0;
}
