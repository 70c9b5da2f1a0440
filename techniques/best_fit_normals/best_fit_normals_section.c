/* The best-fit normals section of `gtlab all` (best_fit_normals_section.h). */
#include "best_fit_normals/best_fit_normals_section.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "best_fit_normals/best_fit_normals_cells.h"
#include "report/gnuplot_plot.h"
#include "report/report_table.h"

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
    REPORT_RANKED("mean error, deg", "mean_deg", "%.4f", ROW, mean_deg, REPORT_LOWEST_BEST),
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

/* The talk's setting for all four rows: its slides "Normals precision for
 * shading" and "Storage techniques breakdown". */
#define NORMALS_SETTING                                                                                          \
    "unit normals stored in an RGB8 (24-bit) G-buffer, the 256^3 cube of codes; counts of the codes each "       \
    "storage can produce, the best fit baked into a cubemap (face > 256^2) of the best cell per direction; "     \
    "the talk does not say how it counted"
#define NORMALS_SECTION_TITLE "Storage techniques breakdown"

static const claim_record kNormalisedCells = {
    .talk = "Kaplanyan 2010 (CryENGINE 3)", .seed = "004", .section = NORMALS_SECTION_TITLE,
    .quote = "1. Normalized normals: - ~289880 cells out of 16777216, which is ~ 1.73 %",
    .setting = NORMALS_SETTING, .setting_match = CLAIM_SETTING_GTLAB,
    .setting_note = "gtlab counts exactly every cell whose box the unit sphere crosses (each reachable by rounding "
                    "a unit normal); the talk's way of counting is not stated: counted as the talk bakes (the "
                    "distinct cells written for the texel centres of a cubemap) the count grows with the face "
                    "and passes 1.73% between faces of 1024^2 and 2048^2 (the section's sampled table)",
    .reading = "normalised normals can be stored in about 1.73% of the 256^3 codes (~289880).",
    .form = CLAIM_RANGE, .low = 1.725, .high = 1.735, .tolerance_source = CLAIM_TOLERANCE_CLAIM_NUMBER,
    .tolerance = "the talk's 1.73% at its printed precision (+-0.005%)"};

static const claim_record kMaxComponentCells = {
    .talk = "Kaplanyan 2010 (CryENGINE 3)", .seed = "004", .section = NORMALS_SECTION_TITLE,
    .quote = "2. Divided by maximum component: - ~390152 cells out of 16777216, which is ~ 2.33 %",
    .setting = NORMALS_SETTING, .setting_match = CLAIM_SETTING_TALK,
    .reading = "normals divided by their largest component land on the cube's surface, 256^3 - 254^3 = 390152 "
               "cells (2.33%), however they are counted (a cubemap of 512^2 already writes them all).",
    .form = CLAIM_RANGE, .low = 2.325, .high = 2.335, .tolerance_source = CLAIM_TOLERANCE_CLAIM_NUMBER,
    .tolerance = "the talk's 2.33% at its printed precision (+-0.005%)"};

static const claim_record kBestFitCells = {
    .talk = "Kaplanyan 2010 (CryENGINE 3)", .seed = "004", .section = NORMALS_SECTION_TITLE,
    .quote = "3. Proposed method (best fit): - ~16482364 cells out of 16777216, which is ~ 98.2 %",
    .setting = NORMALS_SETTING, .setting_match = CLAIM_SETTING_GTLAB,
    .setting_note = "gtlab counts exactly the cells that encode distinct directions (a cell that is a multiple of "
                    "another decodes to the same normal), the most any one-cell-per-direction encoding can use; "
                    "the talk's way of counting is not stated: the cells its search writes for a cubemap's texels, "
                    "repeats of a direction included, grow with the face (the quantity gives them at the largest "
                    "face) and may reach 98.2% on a larger bake",
    .reading = "the best fit stores normals in about 98.2% of the 256^3 codes (~16482364).",
    .stronger_reading = "the 98.2% are distinct directions (the talk: \"uses almost the whole range of 24 bits\"), "
                        "so no more than the cells of distinct directions",
    .form = CLAIM_RANGE, .low = 98.15, .high = 98.25, .tolerance_source = CLAIM_TOLERANCE_CLAIM_NUMBER,
    .tolerance = "the talk's 98.2% at its printed precision (+-0.05%)"};

static const claim_record kOldTechniqueBits = {
    .talk = "Kaplanyan 2010 (CryENGINE 3)", .seed = "004", .section = NORMALS_SECTION_TITLE,
    .quote = "It shows how many bits it uses out of **total number of 24 bits**. Both old techniques uses ~**17 "
             "bits**",
    .setting = NORMALS_SETTING, .setting_match = CLAIM_SETTING_TALK,
    .reading = "the old techniques use about 17 bits of the 24; the figure is log2 of the smaller of the talk's "
               "own counts, 289880 (its 390152 gives 18.57, gtlab's exact counts 18.23 and 18.57), so it does not "
               "depend on how the cells were counted.",
    .stronger_reading = "the bits are log2 of the cells over the whole sphere, as the talk counts them (289880 of "
                        "16777216); the talk does not say over which directions it counts bits, and over the "
                        "hemisphere a view-space G-buffer stores (half the cells) log2 289880/2 = 17.15 is ~17",
    .form = CLAIM_RANGE, .low = 16.5, .high = 17.5, .tolerance_source = CLAIM_TOLERANCE_CLAIM_NUMBER,
    .tolerance = "the talk's ~17 bits at its printed precision (a whole bit: 16.5 to 17.5)"};

/* The talk's own count of the normalised normals' cells (its slide). */
#define TALK_NORMALISED_CELLS 289880.0

void normals_add_claims(claims_table *t, const normals_result *r)
{
    const normals_cells_row *last = &r->sampled[r->request.face_count - 1];
    claims_table_add(t, &kNormalisedCells, 100.0 * r->cells_sphere / BFN_CELL_COUNT, 0.0,
                     "%% of the 256^3 cells the unit sphere crosses, counted exactly (sampled on a %d^2 cubemap: "
                     "%.3f%%)",
                     last->face, 100.0 * last->naive / BFN_CELL_COUNT);
    claims_table_add(t, &kMaxComponentCells, 100.0 * r->cells_surface / BFN_CELL_COUNT, 0.0,
                     "%% of the 256^3 cells on the cube's surface, counted exactly");
    claims_table_add(t, &kBestFitCells, 100.0 * r->cells_distinct / BFN_CELL_COUNT, 0.0,
                     "%% of the 256^3 cells that encode distinct directions, counted exactly (the talk's search on a "
                     "%d^2 cubemap writes %.2f%%, repeats included)",
                     last->face, 100.0 * last->best_fit / BFN_CELL_COUNT);
    claims_table_add(t, &kOldTechniqueBits, log2(TALK_NORMALISED_CELLS), 0.0,
                     "log2 of the talk's 289880 cells, exact");
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
                   "The talk's 2.33%% (the cube's surface, 256^3 - 254^3) is exact however it is counted. The "
                   "talk does not say how it counted the other two: counted exactly, normalised normals reach "
                   "%.2f%% of the cells, not 1.73%%, while the cells a %d^2 cubemap writes (%.2f%%) pass 1.73%% "
                   "between faces of 1024^2 and 2048^2; and 98.2%% exceeds the %.2f%% of cells that encode "
                   "distinct directions, while the talk's search on a %d^2 cubemap writes %.2f%% of the cells, "
                   "repeats of a direction included, and grows with the face. Either count fails only under "
                   "gtlab's way of counting. The talk's ~17 bits does not follow from its own counts over the "
                   "whole sphere (log2 289880 = %.2f, log2 390152 = %.2f bits); over the hemisphere a view-space "
                   "G-buffer stores it does (%.2f): the row fails that stronger reading only.",
                   100.0 * r->cells_sphere / BFN_CELL_COUNT, last->face, 100.0 * last->naive / BFN_CELL_COUNT,
                   100.0 * r->cells_distinct / BFN_CELL_COUNT, last->face, 100.0 * last->best_fit / BFN_CELL_COUNT,
                   log2(TALK_NORMALISED_CELLS), log2(390152.0), log2(TALK_NORMALISED_CELLS / 2.0));
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
                     "and lookup, transcribed; best_fit_normals/best_fit_normals.h), written here as "
                     NORMALS_DIR "/best_fit_normals_%d."
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
    const char *hp[4] = {NORMALS_DIR "/highlight_exact.png", NORMALS_DIR "/highlight_naive.png", NORMALS_DIR "/highlight_best_fit.png",
                         NORMALS_DIR "/highlight_octahedral10p.png"};
    const char *hc[4] = {"exact normals, roughness 0.2", "RGB8 normalised", "RGB8 best fit (point)",
                         "octahedral 2x10 precise"};
    report_figures(ctx->doc, 4, hp, hc);
    render_findings(ctx, r);
    normals_add_claims(ctx->claims, r);
    return 0;
}
