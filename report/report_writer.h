/* The accuracy report: one document built once and written twice, as
 * report.md (for reading in a repository) and report.html (self-contained
 * page with the figures inline as links). Stages of `gtlab all` append
 * headings, paragraphs, tables and figures in order.
 *
 * Every heading below the title has a stable anchor: its text lowercased,
 * spaces turned into '-', every other character but letters, digits, '-'
 * and '_' dropped, and "-1", "-2", ... added to repeats (GitHub's rule for
 * Markdown headings, ASCII only), so links into report.md on a forge and
 * into report.html agree. The level-2 headings make the table of contents,
 * and each finding links to the section it came from.
 *
 * Read at a glance: the top holds the summary table (report_headline.h: one
 * row per technique that ranks variants) and the findings; each level-2
 * section opens with its own findings (its conclusions, each with its
 * number), and in report.html a paragraph longer than
 * REPORT_FOLD_CHARACTERS is folded into <details> under its opening words. */
#ifndef GTLAB_CLI_REPORT_WRITER_H
#define GTLAB_CLI_REPORT_WRITER_H

#include <stdio.h>

#include "core/error.h"
#include "report/report_headline.h"

enum { REPORT_FOLD_CHARACTERS = 320 };
/* A table of more body rows than this is folded in report.html: the
 * reader opens it (issue 41: "the long tables fold below"). */
enum { REPORT_FOLD_ROWS = 12 };

typedef struct {
    char *md, *html;   /* growing texts */
    size_t md_len, html_len, md_cap, html_cap;
    int table_columns; /* > 0 inside a table */
    /* Where the Markdown table's alignment row is, and whether its first
     * row set it yet (report_table_row: a number's column is right-aligned,
     * prose left). */
    size_t table_align_at;
    size_t table_head_at; /* html offset of the open table's header row */
    size_t table_at;      /* html offset of the open table */
    int table_rows;       /* its body rows so far */
    int table_aligned;
    int failed;        /* out of memory at some point */
    /* The "At a glance" list: gathered while the stages run, written where
     * report_findings_here marked (after the introduction). */
    char *findings_md, *findings_html;
    size_t findings_md_len, findings_html_len, findings_md_cap, findings_html_cap;
    size_t findings_md_at, findings_html_at;
    /* The table of contents (level-2 headings), the anchors used so far
     * ("\n"-separated), and the current level-2 section's anchor. */
    char *contents_md, *contents_html, *anchors;
    size_t contents_md_len, contents_html_len, anchors_len, contents_md_cap, contents_html_cap, anchors_cap;
    char section_anchor[128];
    /* The current level-2 section's findings and where they go (just after
     * its heading), inserted when the next one starts or at report_write. */
    char *section_md, *section_html;
    size_t section_md_len, section_html_len, section_md_cap, section_html_cap, section_md_at, section_html_at;
    /* The current level-2 section's lead figure: its first row of figures
     * (md and html ranges), moved up under its conclusions when the
     * section closes, so that a section opens with its verdict and one
     * figure (issue 41). */
    size_t lead_md_at, lead_md_end, lead_html_at, lead_html_end;
    int in_section, lead_taken, lead_found;
    int headline_count;
    report_headline headlines[HEADLINES_MAX];
    /* When set, every call below (but init, write and free) is also
     * appended to it as [name, its arguments...], text already formatted:
     * a `gtlab all` stage's part, replayed into the report by
     * report/report_part.h. */
    struct cJSON *journal;
} report;

void report_init(report *r, const char *title);
void report_heading(report *r, int level, const char *text);
/* A paragraph of plain text (no markup; HTML special characters escaped). */
void report_paragraph(report *r, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void report_table_begin(report *r, int columns, const char *const *headers);
void report_table_row(report *r, const char *const *cells);
/* A row drawn bold (Markdown **cell**, HTML tr.best): the best of its table
 * by the column report_table.h ranks it by. */
void report_table_best_row(report *r, const char *const *cells);
void report_table_end(report *r);
/* A row of figures: image paths relative to the report, with captions. In
 * report.html a gnuplot plot is shown as its SVG at full width, and a
 * heatmap with its colour bar (report/figure_resolve.h). */
void report_figures(report *r, int count, const char *const *paths, const char *const *captions);
/* One view shown several ways (report/compare_viewer.h): in report.html the
 * images flip in one place, zoom and pan together, the first `exposed`
 * (radiance previews) under an exposure slider, the rest (error maps) not;
 * in report.md a row of figures. Paths relative to the report. */
void report_comparison(report *r, int count, const char *const *paths, const char *const *labels, int exposed,
                       const char *caption);
/* Marks where the "At a glance" section and the contents go. */
void report_findings_here(report *r);
/* One finding for that section: a topic and a sentence computed from the
 * run's numbers (plain text), linked to the current level-2 section. */
void report_finding(report *r, const char *topic, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* One row of the summary table, linked to the current level-2 section
 * (ignored beyond HEADLINES_MAX rows). */
void report_add_headline(report *r, const report_headline *h);
/* Writes <dir>/report.md and <dir>/report.html atomically. */
int report_write(report *r, const char *dir, gt_error *e);
void report_free(report *r);

#endif
