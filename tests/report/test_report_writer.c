/* report/report_writer.c: the report's Markdown and HTML say the same thing;
 * findings gathered while stages run land in one "At a glance" section right
 * after the introduction, before every stage's section, after the summary
 * table of the sections' headline rows (report/report_headline.c: best and
 * runner-up ranked from the figures, the verdict from a paired difference or
 * a noise floor); each section opens with its own findings and its first
 * row of figures; a long table is folded in HTML; a long paragraph
 * is folded in HTML, whole; in HTML a plot is shown as its SVG twin, a
 * heatmap with its colour bar and range, and a comparison view holds its
 * images (report/figure_resolve.c, report/compare_viewer.c); HTML special
 * characters are escaped; a report without findings has no such section. */
#include "report/report_table.h"
#include "report/report_writer.h"
#include "core/files/image_io.h"
#include "tests/check.h"
#include "core/statistics/paired_power.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static char *read_all(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *text = malloc((size_t)n + 1);
    if (text && fread(text, 1, (size_t)n, f) != (size_t)n) {
        free(text);
        text = NULL;
    }
    if (text)
        text[n] = '\0';
    fclose(f);
    return text;
}

/* Whether `first` occurs in `text`, and before `second`. */
static int occurs_before(const char *text, const char *first, const char *second)
{
    const char *a = text ? strstr(text, first) : NULL, *b = text ? strstr(text, second) : NULL;
    return a && b && a < b;
}

static void write_and_read(report *r, char **md, char **html)
{
    char path[2048];
    gt_error e;
    CHECK(report_write(r, check_tmp_dir(), &e) == 0);
    snprintf(path, sizeof path, "%s/report.md", check_tmp_dir());
    *md = read_all(path);
    snprintf(path, sizeof path, "%s/report.html", check_tmp_dir());
    *html = read_all(path);
    CHECK(*md && *html);
}

static void test_findings_after_introduction(void)
{
    report r;
    report_init(&r, "title");
    report_paragraph(&r, "introduction");
    report_findings_here(&r);
    report_heading(&r, 2, "Stage one");
    report_finding(&r, "AO", "error %.2f < 1", 0.25);
    report_heading(&r, 2, "Stage two");
    report_finding(&r, "GTAO", "second");
    char *md, *html;
    write_and_read(&r, &md, &html);
    CHECK(occurs_before(md, "introduction", "## At a glance"));
    CHECK(occurs_before(md, "## At a glance", "- **[AO](#stage-one)**: error 0.25 < 1"));
    CHECK(occurs_before(md, "- **[AO](#stage-one)**: error 0.25 < 1", "- **[GTAO](#stage-two)**: second"));
    CHECK(occurs_before(md, "- **[GTAO](#stage-two)**: second", "## Contents"));
    CHECK(occurs_before(md, "## Contents", "- [Stage one](#stage-one)\n- [Stage two](#stage-two)\n"));
    CHECK(occurs_before(md, "- [Stage two](#stage-two)", "## Stage one"));
    CHECK(occurs_before(html, "<p>introduction</p>", "<h2 id=\"at-a-glance\">At a glance</h2>"));
    CHECK(occurs_before(html, "<li><b><a href=\"#stage-one\">AO</a></b>: error 0.25 &lt; 1</li>",
                        "<h2 id=\"contents\">Contents</h2>"));
    CHECK(occurs_before(html, "<li><a href=\"#stage-two\">Stage two</a></li>", "<h2 id=\"stage-one\">Stage one</h2>"));
    CHECK(html && strstr(html, "</ul>") && strstr(html, "</body></html>"));
    free(md);
    free(html);
    report_free(&r);
}

static void test_no_findings_no_section(void)
{
    report r;
    report_init(&r, "title");
    report_findings_here(&r);
    report_heading(&r, 2, "Stage");
    char *md, *html;
    write_and_read(&r, &md, &html);
    CHECK(md && !strstr(md, "At a glance") && strstr(md, "## Stage"));
    CHECK(html && !strstr(html, "At a glance"));
    free(md);
    free(html);
    report_free(&r);
}

/* Anchors follow GitHub's rule for Markdown headings: lowercase, spaces to
 * '-', punctuation dropped, repeats numbered; the names the report inserts
 * itself ("At a glance", "Contents") are taken; every HTML id is unique. */
static void test_anchors(void)
{
    report r;
    report_init(&r, "title");
    report_findings_here(&r);
    report_heading(&r, 2, "Height fog (Decima 2017): 1.5x <faster>");
    report_heading(&r, 3, "Item 9: fast_acos");
    report_heading(&r, 2, "Contents");
    report_heading(&r, 3, "Item 9: fast_acos");
    char *md, *html;
    write_and_read(&r, &md, &html);
    CHECK(html && strstr(html, "<h2 id=\"height-fog-decima-2017-15x-faster\">Height fog (Decima 2017): 1.5x &lt;faster&gt;</h2>"));
    CHECK(html && strstr(html, "<h3 id=\"item-9-fast_acos\">") && strstr(html, "<h3 id=\"item-9-fast_acos-1\">"));
    CHECK(html && strstr(html, "<h2 id=\"contents-1\">Contents</h2>"));
    CHECK(md && strstr(md, "- [Height fog (Decima 2017): 1.5x <faster>](#height-fog-decima-2017-15x-faster)\n"));
    CHECK(md && strstr(md, "- [Contents](#contents-1)\n"));
    free(md);
    free(html);
    report_free(&r);
}

/* A '|' inside a table cell is escaped in Markdown (it would split the
 * cell) and left as it is in HTML; a column of figures is right-aligned, one
 * of prose left, and its HTML header with it (issue 41: the claims table
 * right-aligned its verdicts and the headers of its prose); a
 * cell that is exactly a verdict's name takes its tone's class, and only
 * then (issue 41: the claims table did not colour its verdicts). */
static void test_pipe_in_cell(void)
{
    report r;
    report_init(&r, "title");
    const char *headers[4] = {"what", "mean |x|", "error", "verdict"};
    const char *cells[4] = {"a", "|e| = 1", "-0.25 (2%)", "reproduced"};
    report_table_begin(&r, 4, headers);
    report_table_row(&r, cells);
    report_table_row(&r, (const char *const[]){"b", "2", "prose now", "0.5"}); /* the first row decides */
    report_table_row(&r, (const char *const[]){"c", "refuted", "not significant", "reproduced here"});
    report_table_end(&r);
    char *md, *html;
    write_and_read(&r, &md, &html);
    CHECK(md && strstr(md, "| a | \\|e\\| = 1 | -0.25 (2%) | reproduced |") && strstr(md, "mean \\|x\\|"));
    CHECK(md && strstr(md, "| verdict |\n| :--- | :--- | ---: | :--- |\n| a |"));
    CHECK(html && strstr(html, "<td class=\"prose\">|e| = 1</td><td>-0.25 (2%)</td><td class=\"prose v-holds\">reproduced</td>"));
    CHECK(html && strstr(html, "<td class=\"prose v-fails\">refuted</td><td class=\"prose v-open\">not significant</td>"
                               "<td class=\"prose\">reproduced here</td>"));
    CHECK(html && strstr(html, "<td>a</td>"));
    /* each header aligned as its column: prose left, figures right */
    CHECK_MSG(html && strstr(html, "<tr><th>what</th><th class=\"l\">mean |x|</th><th class=\"r\">error</th>"
                                   "<th class=\"l\">verdict</th></tr>"),
              "%s", html ? strstr(html, "<tr><th>") : "");
    free(md);
    free(html);
    report_free(&r);
}

typedef struct {
    const char *name;
    double error;
} ranked_row;

/* The rows of a ranked table through report_rows, into md and html. */
static void ranked_table(const ranked_row *rows, int count, report_rank rank, char **md, char **html)
{
    const report_column columns[] = {REPORT_STRING("variant", "name", ranked_row, name),
                                     REPORT_RANKED("error", "error", "%.2f", ranked_row, error, rank)};
    report r;
    report_init(&r, "title");
    report_rows(&r, NULL, columns, 2, rows, sizeof rows[0], count);
    write_and_read(&r, md, html);
    report_free(&r);
}

static int occurrences(const char *text, const char *what)
{
    int n = 0;
    for (const char *p = text; p && (p = strstr(p, what)) != NULL; p += strlen(what))
        ++n;
    return n;
}

/* A ranked table draws its best row bold, once (issue 41: "the best row is
 * bold"): the lowest or the highest by its ranked column, NaN left out; a
 * table of one row, or with no number, marks none. */
static void test_best_row(void)
{
    const ranked_row rows[4] = {{"a", 0.3}, {"b", NAN}, {"c", 0.1}, {"d", 0.2}};
    char *md, *html;
    ranked_table(rows, 4, REPORT_LOWEST_BEST, &md, &html);
    CHECK(md && strstr(md, "| **c** | **0.10** |\n") && occurrences(md, "**") == 4);
    CHECK(html && strstr(html, "<tr class=\"best\"><td>c</td>") && occurrences(html, "class=\"best\"") == 1);
    free(md);
    free(html);
    ranked_table(rows, 4, REPORT_HIGHEST_BEST, &md, &html);
    CHECK(md && strstr(md, "| **a** | **0.30** |\n") && occurrences(md, "**") == 4);
    free(md);
    free(html);
    ranked_table(rows, 1, REPORT_LOWEST_BEST, &md, &html);
    CHECK(md && occurrences(md, "**") == 0 && html && !strstr(html, "class=\"best\""));
    free(md);
    free(html);
    const ranked_row none[2] = {{"x", NAN}, {"y", NAN}};
    ranked_table(none, 2, REPORT_LOWEST_BEST, &md, &html);
    CHECK(md && occurrences(md, "**") == 0);
    free(md);
    free(html);
}

/* Ranking leaves NaNs out and keeps the two lowest; the verdicts follow
 * |d| > z s (strictly) and gap > floor. */
static void test_headline_verdicts(void)
{
    report_headline h = {.topic = "t"};
    const char *labels[4] = {"a", "b", "c", "d"};
    CHECK(headline_rank(&h, 4, labels, (const double[]){0.3, NAN, 0.1, 0.2}) == 0);
    CHECK(!strcmp(h.best, "c") && !strcmp(h.runner_up, "d") && h.best_error == 0.1 && h.runner_up_error == 0.2);
    CHECK(headline_rank(&h, 2, labels, (const double[]){NAN, 1.0}) == -1 && !strcmp(h.best, "c"));
    headline_from_difference(&h, 0.3, 0.1, "over 6 scenes");
    CHECK(h.significance == HEADLINE_SIGNIFICANT && strstr(h.basis, "over 6 scenes"));
    headline_from_difference(&h, -0.19, 0.1, "x");
    CHECK(h.significance == HEADLINE_NOT_SIGNIFICANT);
    headline_from_difference(&h, -0.2, 0.1, "x");
    CHECK(h.significance == HEADLINE_SIGNIFICANT);
    headline_from_difference(&h, 0.2, NAN, "x");
    CHECK(h.significance == HEADLINE_NOT_COMPUTED);
    headline_from_noise_floor(&h, 0.2); /* gap 0.1: (0.2 / 0.1)^2 = 4 times the samples */
    CHECK(h.significance == HEADLINE_NOT_SIGNIFICANT && strstr(h.basis, "below"));
    CHECK(fabs(h.samples_factor_to_decide - 4.0) < 1e-12 && strstr(h.basis, "about 4 times the references' samples"));
    headline_from_noise_floor(&h, 0.05);
    CHECK(h.significance == HEADLINE_ABOVE_NOISE_FLOOR && strstr(h.basis, "above"));
    CHECK(h.samples_factor_to_decide == 0.0 && !strstr(h.basis, "would decide"));
}

/* The summary's opening sentence counts each verdict and says, for each
 * undecided row in order, what would decide it; the report opens with it. */
static void test_headline_opening(void)
{
    report_headline rows[5] = {
        {.topic = "A", .significance = HEADLINE_SIGNIFICANT},
        {.topic = "B", .significance = HEADLINE_NOT_SIGNIFICANT, .cases_to_decide = 42, .cases = 6},
        {.topic = "C", .significance = HEADLINE_NOT_SIGNIFICANT, .samples_factor_to_decide = 4.0},
        {.topic = "D", .significance = HEADLINE_NO_VISIBLE_DIFFERENCE},
        {.topic = "E", .significance = HEADLINE_NOT_COMPUTED},
    };
    char s[2048];
    headlines_opening(rows, 5, s, sizeof s);
    CHECK(!strcmp(s, "Of 5 rankings, 1 is decided (a significant gap, past its visible margin where it states one), "
                     "1 shows no difference a viewer could see, 2 are undecided at this quality, and 1 has no "
                     "interval (above the noise floor, or not computed); what would decide them: B: about 42 paired "
                     "cases (it has 6); C: about 4 times the references' samples (if their noise floor falls as "
                     "1/sqrt(samples))."));
    headlines_opening(rows, 0, s, sizeof s);
    CHECK(s[0] == 0);
    rows[1].cases_to_decide = -1;
    headlines_opening(rows, 2, s, sizeof s);
    CHECK(strstr(s, "B: no number of cases") && strstr(s, "Of 2 rankings, 1 is decided") && !strstr(s, "no interval"));

    report r;
    report_init(&r, "title");
    report_findings_here(&r);
    report_heading(&r, 2, "Stage");
    rows[1].cases_to_decide = 42;
    report_add_headline(&r, &rows[1]);
    char *md, *html;
    write_and_read(&r, &md, &html);
    CHECK(occurs_before(md, "## At a glance\n\nOf 1 ranking, 0 are decided", "| technique |"));
    CHECK(md && occurs_before(md, "what would decide them: B: about 42 paired cases (it has 6).", "| technique |"));
    CHECK(html && strstr(html, "<p>Of 1 ranking, 0 are decided"));
    free(md);
    free(html);
    report_free(&r);
}

/* The references' noise against a row's budget (issue 46 item 1): the
 * budget is the closed form of metrics/noise_corrected.h at the best figure
 * with the noise taken out; a row that misses it says by how much its
 * figures read high, keeps its verdict, and the opening names it. */
static void test_headline_noise_budget(void)
{
    /* Best 0.13 measured against references of noise 0.05: truth
     * sqrt(0.0169 - 0.0025) = 0.12, budget sqrt(0.12 * 0.004 / 2 + 0.004^2 / 16) = 0.0155. */
    report_headline h = {.topic = "N", .best_error = 0.13, .margin = 0.004, .significance = HEADLINE_SIGNIFICANT};
    headline_state_reference_noise(&h, 0.05);
    double budget = sqrt(0.12 * 0.004 / 2 + 0.004 * 0.004 / 16);
    CHECK_NEAR(h.noise_budget, budget, 1e-12);
    CHECK(h.reference_noise == 0.05 && headline_missed_noise_budget(&h) && h.significance == HEADLINE_SIGNIFICANT);
    CHECK(strstr(h.basis, "references' noise RMSE 0.05, over its budget 0.016: figures near 0.13 read up to 0.01 high"));
    report_headline quiet = {.topic = "Q", .best_error = 0.13, .margin = 0.004};
    headline_state_reference_noise(&quiet, 0.01);
    CHECK(!headline_missed_noise_budget(&quiet) && strstr(quiet.basis, "noise RMSE 0.01, within its budget"));
    report_headline unstated = {.topic = "U", .best_error = 0.13};
    headline_state_reference_noise(&unstated, 0.05); /* no margin: no budget */
    CHECK(!headline_missed_noise_budget(&unstated) && unstated.basis[0] == 0);
    report_headline rows[3] = {h, quiet, unstated};
    char s[2048];
    headlines_opening(rows, 3, s, sizeof s);
    CHECK(strstr(s, " The references of N (noise RMSE 0.05, budget 0.016) missed their noise budget at this quality: "
                    "its figures read high and its gaps low"));
    CHECK(!strstr(s, "of Q") && !strstr(s, "of U"));
}

/* A visible margin m (issue 42): a significant gap whose interval lies in
 * [-m, m] is no visible difference; a significant gap below m is not
 * called significant; one past m stays significant; with Student's t the
 * interval is t s wide; against a noise floor only the gap counts. */
static void test_headline_margin(void)
{
    report_headline h = {.topic = "t", .margin = 0.01};
    headline_from_difference(&h, 0.003, 0.001, "x"); /* 0.003 + 1.96e-3 < 0.01 */
    CHECK(h.significance == HEADLINE_NO_VISIBLE_DIFFERENCE && strstr(h.basis, "visible from 0.01"));
    headline_from_difference(&h, 0.009, 0.002, "x"); /* significant, below m, interval past it */
    CHECK(h.significance == HEADLINE_NOT_SIGNIFICANT);
    headline_from_difference(&h, 0.02, 0.002, "x");
    CHECK(h.significance == HEADLINE_SIGNIFICANT);
    headline_from_paired_cases(&h, 0.005, 0.001, 3, "x"); /* 0.005 + 4.303e-3 < 0.01 */
    CHECK(h.significance == HEADLINE_NO_VISIBLE_DIFFERENCE);
    headline_from_paired_cases(&h, 0.005, 0.0013, 3, "x"); /* 0.005 + 5.59e-3 > 0.01 */
    CHECK(h.significance == HEADLINE_NOT_SIGNIFICANT && h.margin == 0.01);
    h.best_error = 0.1, h.runner_up_error = 0.105;
    headline_from_noise_floor(&h, 0.001);
    CHECK(h.significance == HEADLINE_NO_VISIBLE_DIFFERENCE);
    CHECK(!strcmp(headline_significance_name(HEADLINE_NO_VISIBLE_DIFFERENCE), "no visible difference"));
}

/* Paired ranking: means over the cases rank the candidates; the verdict is
 * the per-case difference runner-up - best, by hand: a (1, 2, 3, NaN),
 * b (2, 2.5, 3.5, 9), c (0.5, 2.6, 4.9, 0) rank a (mean 2) before b (4.25)
 * and c (2); ties keep the earlier, so a then c; c - a over the cases both
 * have = (-0.5, 0.6, 1.9): mean 2/3, s.e. sqrt(1.4433 / 3) = 0.6936 ->
 * not significant. With c far behind, b is the runner-up, and b - a =
 * (1, 0.5, 0.5) is 2/3 +- 1/6: 4.0 standard errors, significant by the
 * normal 1.96 but not by Student's t with 2 degrees of freedom (4.303),
 * which the paired verdict uses; b = (2, 2.6, 3.55, 9) makes it
 * (1, 0.6, 0.55), 0.7167 +- 0.1424, 5.03 standard errors: significant. */
static void test_headline_paired(void)
{
    report_headline h = {.topic = "t"};
    const char *labels[3] = {"a", "b", "c"};
    double e[12] = {1, 2, 3, NAN, 2, 2.5, 3.5, 9, 0.5, 2.6, 4.9, 0};
    CHECK(headline_rank_paired(&h, 3, labels, e, 4, "over 4 cases") == 0);
    CHECK(!strcmp(h.best, "a") && !strcmp(h.runner_up, "c") && h.best_error == 2.0 && h.runner_up_error == 2.0);
    CHECK(h.significance == HEADLINE_NOT_SIGNIFICANT && strstr(h.basis, "+0.6667 +- 0.69"));
    /* what would decide it: the spread of one case's difference is sqrt(1.4433) */
    CHECK_MSG(h.cases_to_decide == paired_cases_needed(2.0 / 3.0, sqrt(1.4433), 0.8, 1000000) &&
                  h.cases_to_decide > 4 && strstr(h.basis, "such cases would decide it"),
              "%d: %s", h.cases_to_decide, h.basis);
    double far[12] = {1, 2, 3, NAN, 2, 2.5, 3.5, 9, 10.5, 12.6, 14.9, 40};
    CHECK(headline_rank_paired(&h, 3, labels, far, 4, "x") == 0 && !strcmp(h.runner_up, "b"));
    CHECK(h.significance == HEADLINE_NOT_SIGNIFICANT && strstr(h.basis, "; critical t(2) = 4.3"));
    far[5] = 2.6, far[6] = 3.55;
    CHECK(headline_rank_paired(&h, 3, labels, far, 4, "x") == 0 && h.significance == HEADLINE_SIGNIFICANT);
    double one[4] = {1, NAN, NAN, NAN};
    CHECK(headline_rank_paired(&h, 1, labels, one, 4, "x") == -1);
}

/* Headline rows make the summary table at the top, in the order registered,
 * linked to their sections, with their verdicts; then the findings. */
static void test_headline_table(void)
{
    report r;
    report_init(&r, "title");
    report_findings_here(&r);
    report_heading(&r, 2, "Stage one");
    report_headline h = {.topic = "AO <x>", .measure = "RMSE", .best = "b1", .runner_up = "r1", .best_error = 0.125,
                         .runner_up_error = 0.25};
    report_add_headline(&r, &h);
    report_finding(&r, "AO", "first");
    report_heading(&r, 2, "Stage two");
    h = (report_headline){.topic = "GTAO", .measure = "DSSIM", .best = "b2", .runner_up = "r2", .best_error = 1,
                          .runner_up_error = 2};
    headline_from_difference(&h, 1.0, 0.25, "paired");
    report_add_headline(&r, &h);
    char *md, *html;
    write_and_read(&r, &md, &html);
    CHECK(occurs_before(md, "## At a glance\n\nOf 2 rankings, 1 is decided", "| technique |"));
    CHECK(occurs_before(md, "| technique |", "| [AO <x>](#stage-one) | RMSE | b1 | 0.125 | r1 | 0.25 | not computed |"));
    CHECK(occurs_before(md, "| [AO <x>](#stage-one) |", "| [GTAO](#stage-two) | DSSIM | b2 | 1 | r2 | 2 | significant at 95% (difference +1 +- 0.25 s.e., paired) |"));
    CHECK(occurs_before(md, "| [GTAO](#stage-two) |", "- **[AO](#stage-one)**: first"));
    CHECK(occurs_before(html, "<table class=\"glance\">", "<td><a href=\"#stage-one\">AO &lt;x&gt;</a></td><td>RMSE</td>"));
    CHECK(occurs_before(html, "<tr class=\"sig\"><td><a href=\"#stage-two\">GTAO</a>", "<ul>\n<li><b><a href=\"#stage-one\">AO</a>"));
    free(md);
    free(html);
    report_free(&r);
}

/* A section's findings open it (after its heading, before its body), in
 * both files; a paragraph over REPORT_FOLD_CHARACTERS is folded in HTML
 * under its first sentence, its whole text inside; Markdown keeps it. */
static void test_conclusions_first_and_folding(void)
{
    char long_text[REPORT_FOLD_CHARACTERS + 64];
    memset(long_text, 'w', sizeof long_text);
    memcpy(long_text, "Lead <one>. ", 12);
    long_text[sizeof long_text - 1] = '\0';
    report r;
    report_init(&r, "title");
    report_findings_here(&r);
    report_heading(&r, 2, "Stage one");
    report_paragraph(&r, "body");
    report_paragraph(&r, "%s", long_text);
    report_finding(&r, "AO", "error %.2f", 0.25);
    report_heading(&r, 2, "Stage two");
    report_paragraph(&r, "second body");
    report_finding(&r, "GTAO", "second");
    char *md, *html;
    write_and_read(&r, &md, &html);
    CHECK(occurs_before(md, "## Stage one\n\nConclusions:\n\n- **AO**: error 0.25\n\nbody", long_text));
    CHECK(md && strstr(md, "## Stage two\n\nConclusions:\n\n- **GTAO**: second\n\nsecond body"));
    CHECK(md && !strstr(md, "<details>"));
    CHECK(occurs_before(html, "<h2 id=\"stage-one\">Stage one</h2>\n<ul class=\"conclusions\">\n<li><b>AO</b>: error 0.25</li>\n</ul>\n<p>body</p>",
                        "<details><summary><span class=\"lead\">Lead &lt;one&gt;. &hellip;</span>"));
    CHECK(html && strstr(html, "<p>Lead &lt;one&gt;. www"));
    CHECK(occurs_before(html, "<ul class=\"conclusions\">\n<li><b>GTAO</b>: second</li>\n</ul>\n<p>second body</p>", "</body>"));
    free(md);
    free(html);
    report_free(&r);
}

/* A section opens with its conclusions and its lead figure, its first row
 * of figures, moved up from where the stage wrote it; its other rows stay;
 * a section without findings opens with its lead figure; a row before the
 * first section is no section's (issue 41: "every section opens with its
 * verdict and one figure"). */
static void test_lead_figure(void)
{
    report r;
    report_init(&r, "title");
    report_findings_here(&r);
    const char *first[2] = {"figures/a.png", "figures/b.png"}, *captions[2] = {"A", "B"};
    const char *second[1] = {"figures/c.png"}, *third[1] = {"figures/d.png"}, *before[1] = {"figures/e.png"};
    report_figures(&r, 1, before, captions);
    report_heading(&r, 2, "Stage one");
    report_paragraph(&r, "body");
    report_table_begin(&r, 1, (const char *const[]){"x"});
    report_table_row(&r, (const char *const[]){"1"});
    report_table_end(&r);
    report_figures(&r, 2, first, captions);
    report_paragraph(&r, "after");
    report_figures(&r, 1, second, captions);
    report_finding(&r, "AO", "error %.2f", 0.25);
    report_heading(&r, 2, "Stage two");
    report_paragraph(&r, "second body");
    report_figures(&r, 1, third, captions);
    char *md, *html;
    write_and_read(&r, &md, &html);
    CHECK_MSG(md && strstr(md, "## Stage one\n\nConclusions:\n\n- **AO**: error 0.25\n\n"
                               "![A](figures/a.png) ![B](figures/b.png) \n\nbody\n\n| x |"),
              "%s", md ? strstr(md, "## Stage one") : "");
    CHECK(occurs_before(md, "| 1 |", "after\n\n![A](figures/c.png)"));
    CHECK(md && strstr(md, "## Stage two\n\n![A](figures/d.png) \n\nsecond body"));
    CHECK(occurs_before(md, "![A](figures/e.png)", "## Stage one"));
    CHECK(occurs_before(html, "<li><b>AO</b>: error 0.25</li>\n</ul>\n<div>\n<figure><a href=\"figures/a.png\">",
                        "<p>body</p>"));
    CHECK(occurs_before(html, "<p>body</p>", "<p>after</p>\n<div>\n<figure><a href=\"figures/c.png\">"));
    CHECK(html && strstr(html, "<h2 id=\"stage-two\">Stage two</h2>\n<div>\n<figure><a href=\"figures/d.png\">"));
    free(md);
    free(html);
    report_free(&r);
}

/* A table of more than REPORT_FOLD_ROWS rows is folded in HTML (issue 41:
 * "the long tables fold below"), whole, its summary its row count; one of
 * REPORT_FOLD_ROWS is not; Markdown folds nothing. */
static void test_long_table_folded(void)
{
    report r;
    report_init(&r, "title");
    report_heading(&r, 2, "Stage");
    for (int rows = REPORT_FOLD_ROWS; rows <= REPORT_FOLD_ROWS + 1; ++rows) {
        report_table_begin(&r, 1, (const char *const[]){rows > REPORT_FOLD_ROWS ? "long" : "short"});
        for (int k = 0; k < rows; ++k)
            report_table_row(&r, (const char *const[]){"1"});
        report_table_end(&r);
    }
    char *md, *html, expected[256];
    write_and_read(&r, &md, &html);
    snprintf(expected, sizeof expected,
             "<details class=\"rows\"><summary>a table of %d rows <i>(show)</i></summary>\n<table>\n<tr><th>long</th>",
             REPORT_FOLD_ROWS + 1);
    CHECK_MSG(html && strstr(html, expected), "%s", html ? strstr(html, "<h2") : "");
    CHECK(occurs_before(html, "<th>long</th>", "</table>\n</details>\n"));
    CHECK(html && strstr(html, "</h2>\n<table>\n<tr><th>short</th>"));
    CHECK(md && !strstr(md, "<details"));
    free(md);
    free(html);
    report_free(&r);
}

static int count_of(const char *text, const char *what)
{
    int n = 0;
    for (const char *p = text; p && (p = strstr(p, what)) != NULL; p += strlen(what))
        ++n;
    return n;
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

/* Figures as written: the plot (a PNG with an SVG twin) as its SVG, the
 * heatmap with a colour bar carrying its map and range, a plain image as it
 * was; no mark left; report.md keeps the PNGs. A comparison view holds its
 * images and says how many take the exposure. */
static void test_figures_resolved(void)
{
    char dir[1024], path[1200];
    snprintf(dir, sizeof dir, "%s/figures", check_tmp_dir());
    mkdir(dir, 0777);
    const float values[4] = {0.0f, 0.1f, 0.2f, 0.5f};
    gt_error e;
    snprintf(path, sizeof path, "%s/heat.png", dir);
    CHECK_MSG(image_write_heatmap(path, values, NULL, 2, 2, 0.5f, "viridis", &e) == 0, "%s", e.message);
    snprintf(path, sizeof path, "%s/plot.png", dir);
    write_text(path, "not read");
    snprintf(path, sizeof path, "%s/plot.svg", dir);
    write_text(path, "<svg xmlns=\"http://www.w3.org/2000/svg\"/>");
    report r;
    report_init(&r, "title");
    const char *p[3] = {"figures/heat.png", "figures/plot.png", "figures/none.png"}, *c[3] = {"h", "p", "n"};
    report_figures(&r, 3, p, c);
    report_comparison(&r, 2, p, c, 1, "view");
    char *md, *html;
    write_and_read(&r, &md, &html);
    CHECK(html && count_of(html, "src=\"figures/plot.svg\"") == 2 && !strstr(html, "figures/plot.png"));
    CHECK(html && strstr(html, "<img src=\"figures/heat.png\" alt=\"h\"></a><div class=\"cbar\" title=\"viridis, "
                               "linear from 0 to 0.5, clamped\"><span>0</span>"));
    CHECK(html && strstr(html, "<span>0.5</span></div><figcaption>h</figcaption>"));
    CHECK(html && count_of(html, "class=\"cbar\"") == 2);
    CHECK(html && strstr(html, "<img src=\"figures/none.png\" alt=\"n\"></a><figcaption>n</figcaption>"));
    CHECK(html && !strchr(html, '\x1f') && !strchr(html, '\x1e'));
    CHECK(html && strstr(html, "<div class=\"cmp\" tabindex=\"0\" data-exposed=\"1\">"));
    CHECK(html && count_of(html, "<figure class=\"cmp-pane\">") == 2 && strstr(html, "function gtlabViewer("));
    CHECK(md && strstr(md, "![p](figures/plot.png)") && strstr(md, "view:\n\n![h](figures/heat.png) ![p](figures/plot.png)"));
    free(md);
    free(html);
    report_free(&r);
}

int main(void)
{
    test_figures_resolved();
    test_headline_verdicts();
    test_headline_opening();
    test_headline_margin();
    test_headline_noise_budget();
    test_headline_paired();
    test_headline_table();
    test_conclusions_first_and_folding();
    test_lead_figure();
    test_long_table_folded();
    test_pipe_in_cell();
    test_best_row();
    test_findings_after_introduction();
    test_no_findings_no_section();
    test_anchors();
    return check_report("test_report_writer");
}
