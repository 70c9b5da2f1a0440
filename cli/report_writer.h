/* The accuracy report: one document built once and written twice, as
 * report.md (for reading in a repository) and report.html (self-contained
 * page with the figures inline as links). Stages of `gtlab all` append
 * headings, paragraphs, tables and figures in order. */
#ifndef GTLAB_CLI_REPORT_WRITER_H
#define GTLAB_CLI_REPORT_WRITER_H

#include <stdio.h>

#include "core/error.h"

typedef struct {
    char *md, *html;   /* growing texts */
    size_t md_len, html_len, md_cap, html_cap;
    int table_columns; /* > 0 inside a table */
    int failed;        /* out of memory at some point */
} report;

void report_init(report *r, const char *title);
void report_heading(report *r, int level, const char *text);
/* A paragraph of plain text (no markup; HTML special characters escaped). */
void report_paragraph(report *r, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void report_table_begin(report *r, int columns, const char *const *headers);
void report_table_row(report *r, const char *const *cells);
void report_table_end(report *r);
/* A row of figures: image paths relative to the report, with captions. */
void report_figures(report *r, int count, const char *const *paths, const char *const *captions);
/* Writes <dir>/report.md and <dir>/report.html atomically. */
int report_write(report *r, const char *dir, gt_error *e);
void report_free(report *r);

#endif
