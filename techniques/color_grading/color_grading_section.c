/* The colour-grading LUT section (color_grading_section.h). */
#include "color_grading/color_grading_section.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "report/claim_thresholds.h"
#include "report/report_table.h"

#define ROW grading_row
static const report_column columns[] = {
    REPORT_STRING("grade", "grade", ROW, grade),
    REPORT_INT("N", "size", ROW, size),
    REPORT_STRING("indexed", "space", ROW, space),
    REPORT_STRING("lookup", "interpolation", ROW, interpolation),
    REPORT_STRING("stored", "storage", ROW, storage),
    REPORT_REAL("chart max dE00", "chart_max_de", "%.2f", ROW, image[0].max_de),
    REPORT_REAL("chart p99 dE00", "chart_p99_de", "%.2f", ROW, image[0].p99_de),
    REPORT_REAL("chart max LSB", "chart_max_lsb", "%.1f", ROW, image[0].max_lsb),
    REPORT_REAL("chart p99 LSB", "chart_p99_lsb", "%.1f", ROW, image[0].p99_lsb),
    REPORT_REAL("cube max dE00", "cube_max_de", "%.2f", ROW, image[1].max_de),
    REPORT_REAL("cube p99 dE00", "cube_p99_de", "%.2f", ROW, image[1].p99_de),
    REPORT_REAL("render max dE00", "render_max_de", "%.2f", ROW, image[2].max_de),
    REPORT_REAL("render p99 dE00", "render_p99_de", "%.2f", ROW, image[2].p99_de),
    REPORT_INT("max dE00 < 1", "perceptual", ROW, perceptual),
    REPORT_INT("p99 <= 1 LSB", "within_1lsb", ROW, within_1lsb),
    REPORT_REAL(NULL, "cube_max_lsb", NULL, ROW, image[1].max_lsb),
    REPORT_REAL(NULL, "cube_p99_lsb", NULL, ROW, image[1].p99_lsb),
    REPORT_REAL(NULL, "render_max_lsb", NULL, ROW, image[2].max_lsb),
    REPORT_REAL(NULL, "render_p99_lsb", NULL, ROW, image[2].p99_lsb),
};
#undef ROW
#define COLUMN_COUNT ((int)(sizeof columns / sizeof columns[0]))

/* The rows of one variant (space, lookup, storage), in grade and size order. */
static int select_rows(const grading_result *r, const char *space, const char *lookup, const char *storage,
                       grading_row *out)
{
    int n = 0;
    for (int i = 0; i < r->row_count; ++i) {
        const grading_row *row = &r->rows[i];
        if (!strcmp(row->space, space) && !strcmp(row->interpolation, lookup) && !strcmp(row->storage, storage))
            out[n++] = *row;
    }
    return n;
}

/* "a, b, c" of the looks (identity excluded) whose row of size N does / does
 * not suffice perceptually. */
static int list_grades(const grading_row *rows, int n, int size_n, int perceptual, char *text, size_t size)
{
    int count = 0;
    text[0] = 0;
    for (int i = 0; i < n; ++i)
        if (rows[i].size == size_n && strcmp(rows[i].grade, "identity") != 0 && rows[i].perceptual == perceptual) {
            size_t len = strlen(text);
            snprintf(text + len, size - len, "%s%s", count ? ", " : "", rows[i].grade);
            ++count;
        }
    if (!count)
        snprintf(text, size, "none");
    return count;
}

/* The largest chart dE00 of a grade at size N among the rows. */
static double chart_max_de(const grading_row *rows, int n, const char *grade, int size_n)
{
    for (int i = 0; i < n; ++i)
        if (rows[i].size == size_n && !strcmp(rows[i].grade, grade))
            return rows[i].image[0].max_de;
    return 0.0;
}

static const claim_record kSixteenCubed = {
    .talk = "Kaplanyan 2010 (CryENGINE 3)", .seed = "004", .section = "Color grading",
    .quote = "After doing some experiments, we figured out that the size of **16x16x16** is more than enough for "
             "the majority of color transformations.",
    .setting = "all global colour transformations of a game screenshot (colour correction, contrast, brightness, "
               "levels, selective colours, authored in Photoshop) baked into one 3-D LUT indexed by display "
               "(gamma) values, applied on consoles by one hardware 3-D texture lookup",
    .setting_match = CLAIM_SETTING_GTLAB,
    .setting_note = "the talk's transformations are its artists' and unknown; gtlab grades five looks of its own "
                    "(warm contrast, teal and orange, bleach bypass, cross-process curves, a clipped +1.5-stop "
                    "exposure), baked at 16^3 into an sRGB-indexed RGBA8 LUT read trilinearly (the hardware path), "
                    "on a photo-like chart and a Cornell-box render instead of game screenshots",
    .reading = "for more than half of the colour transformations a grader applies, a 16^3 LUT reproduces the "
               "exact grade with no visible colour error; the figure is the fraction of gtlab's looks whose "
               "16^3 LUT keeps every pixel of the chart and the render within one CIEDE2000 unit, its s.e. that "
               "of a fraction of so few looks (a claim about the majority of transformations is not decided by "
               "one hard look).",
    .form = CLAIM_RANGE, .low = 0.5 + 1e-9, .high = INFINITY, .tolerance_source = CLAIM_TOLERANCE_VISIBILITY,
    .tolerance = "a look counts as enough when its largest dE00 is below one CIEDE2000 unit (CLAIM_VISIBLE_DE00); "
                 "the claim holds when more than half of the looks are"};

void color_grading_add_claim(claims_table *t, const grading_row *rows, int n)
{
    int looks = 0, enough = 0;
    for (int i = 0; i < n; ++i)
        if (rows[i].size == 16 && strcmp(rows[i].grade, "identity") != 0) {
            ++looks;
            enough += rows[i].image[0].max_de < CLAIM_VISIBLE_DE00 && rows[i].image[2].max_de < CLAIM_VISIBLE_DE00;
        }
    if (!looks)
        return;
    /* The s.e. of a binomial fraction, with Laplace's (k + 1)/(n + 2) so that
     * 0 of n or n of n looks is never exact. */
    double p = (double)enough / looks, laplace = (enough + 1.0) / (looks + 2.0);
    claims_table_add(t, &kSixteenCubed, p, sqrt(laplace * (1.0 - laplace) / looks),
                     "fraction of %d looks (%d enough) whose 16^3 sRGB-indexed RGBA8 trilinear LUT keeps max dE00 "
                     "< %.0f on the chart and the render; s.e. binomial over the looks",
                     looks, enough, CLAIM_VISIBLE_DE00);
}

static void render_findings(report_context *ctx, const grading_row *gpu, int n, const grading_row *tet, int n_tet)
{
    char yes[512], no[512], yes32[512], no32[512];
    int looks = 0, bits = 0;
    for (int i = 0; i < n; ++i)
        if (gpu[i].size == 16 && strcmp(gpu[i].grade, "identity") != 0)
            ++looks, bits += gpu[i].within_1lsb;
    int count = list_grades(gpu, n, 16, 1, yes, sizeof yes), count32 = list_grades(gpu, n, 32, 1, yes32, sizeof yes32);
    list_grades(gpu, n, 16, 0, no, sizeof no);
    list_grades(gpu, n, 32, 0, no32, sizeof no32);
    report_finding(ctx->doc, "colour grading",
                   "An sRGB-indexed 16^3 RGBA8 LUT with hardware trilinear filtering keeps %d of %d looks below "
                   "dE00 1 everywhere on the chart and the render (%s; not: %s), and %d within 1 LSB at the 99th percentile; at "
                   "32^3 %d (not: %s).",
                   count, looks, yes, no, bits, count32, no32);
    report_finding(ctx->doc, "colour grading",
                   "Where a grade clips (the +1.5 stop exposure; saturation boosts pushing colours out of gamut) "
                   "the LUT converges to first order: the clip's max dE00 (float, tetrahedral) goes %.2f, %.2f, "
                   "%.2f from 16^3 to 64^3, against %.2f, %.2f, %.2f for the unclipped bleach bypass.",
                   chart_max_de(tet, n_tet, "clipped exposure +1.5", 16),
                   chart_max_de(tet, n_tet, "clipped exposure +1.5", 32),
                   chart_max_de(tet, n_tet, "clipped exposure +1.5", 64), chart_max_de(tet, n_tet, "bleach bypass", 16),
                   chart_max_de(tet, n_tet, "bleach bypass", 32), chart_max_de(tet, n_tet, "bleach bypass", 64));
}

/* The worst chart dE00 over the five looks of one variant at size N. */
static double worst_look(const grading_result *r, const char *space, const char *lookup, int size_n)
{
    double worst = 0.0;
    for (int i = 0; i < r->row_count; ++i) {
        const grading_row *row = &r->rows[i];
        if (row->size == size_n && !strcmp(row->space, space) && !strcmp(row->interpolation, lookup) &&
            !strcmp(row->storage, "float") && strcmp(row->grade, "identity") != 0)
            worst = row->image[0].max_de > worst ? row->image[0].max_de : worst;
    }
    return worst;
}

static void render_space_finding(report_context *ctx, const grading_result *r)
{
    report_finding(ctx->doc, "colour grading",
                   "At 32^3 (float, tetrahedral) the worst look's chart dE00 is %.2f indexed by sRGB values, %.2f "
                   "by linear values and %.2f by log2 values (12 stops): linear indexing leaves few lattice points "
                   "in the shadows, where display values change fastest.",
                   worst_look(r, "sRGB", "tetrahedral", 32), worst_look(r, "linear", "tetrahedral", 32),
                   worst_look(r, "log2", "tetrahedral", 32));
}

int color_grading_section(report_context *ctx, const grading_result *r, gt_error *e)
{
    (void)e;
    report_heading(ctx->doc, 2, "Colour-grading LUTs (CryENGINE 3)");
    report_paragraph(ctx->doc,
                     "Kaplanyan 2010 bakes all global colour transformations into a 3-D LUT and finds 16^3 enough. "
                     "Six grades as grading tools apply them (levels, monotone curves, saturation, hue rotation, "
                     "ASC CDL, a clipped exposure; color_grading/color_grade.h) are baked at 16^3, 32^3 and 64^3, "
                     "indexed by sRGB, linear or log2 values (12 stops), stored as float or RGBA8, looked up trilinearly or "
                     "tetrahedrally, and scored against the exact grade: on a photo-like HDR chart tone-mapped "
                     "to display values (hue, saturation and exposure sweeps, skin tones, a twelve-stop grey "
                     "ramp), on %d random colours (the cube) and on a gtlab render of the Cornell box (the frames of the "
                     "anti-aliasing study, 2x2 samples). Errors: CIEDE2000 (Little CMS) and the largest "
                     "channel difference in 8-bit steps, max and 99th percentile. The "
                     "table shows the GPU path (sRGB-indexed, RGBA8, trilinear) and the float LUTs with each "
                     "lookup; summary.json holds every variant, the linear- and log-indexed ones too.",
                     r->cube_samples);
    static grading_row gpu[sizeof r->rows / sizeof r->rows[0]], tet[sizeof r->rows / sizeof r->rows[0]];
    int n = select_rows(r, "sRGB", "trilinear", "8-bit", gpu), n_tet = select_rows(r, "sRGB", "tetrahedral", "float", tet);
    report_rows(ctx->doc, NULL, columns, COLUMN_COUNT, gpu, sizeof gpu[0], n);
    report_rows(ctx->doc, NULL, columns, COLUMN_COUNT, tet, sizeof tet[0], n_tet);
    render_findings(ctx, gpu, n, tet, n_tet);
    color_grading_add_claim(ctx->claims, gpu, n);
    render_space_finding(ctx, r);
    report_rows(NULL, cJSON_AddArrayToObject(ctx->summary, "color_grading"), columns, COLUMN_COUNT, r->rows,
                sizeof r->rows[0], r->row_count);
    const char *p[5] = {GRADING_DIR "/chart.png", GRADING_DIR "/chart_grade1.png", GRADING_DIR "/chart_grade3.png",
                        GRADING_DIR "/chart_grade5.png", GRADING_DIR "/render.png"};
    const char *c[5] = {"the chart (display values)", "warm contrast", "bleach bypass", "clipped exposure +1.5",
                        "the render (display values)"};
    report_figures(ctx->doc, 5, p, c);
    return 0;
}
