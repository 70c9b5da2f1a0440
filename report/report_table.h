/* A study's rows rendered from one description of their columns: the same
 * field of the same struct becomes a cell of the report's table (Markdown and
 * HTML, printed with the column's format) and a member of summary.json (the
 * full double), so no figure is written twice by hand.
 *
 *   static const report_column columns[] = {
 *       REPORT_TEXT("scene", "scene", ao_reference_row, scene),
 *       REPORT_REAL("mean stderr", "mean_stderr_ao", "%.2e", ao_reference_row, mean_stderr),
 *   };
 *   report_rows(doc, json_list, columns, 2, result.rows, sizeof result.rows[0], result.count);
 *
 * A column with no header is JSON only; one with no key is table only (its
 * cell may be drawn by a function from several fields). */
#ifndef GTLAB_CLI_REPORT_TABLE_H
#define GTLAB_CLI_REPORT_TABLE_H

#include <cjson/cJSON.h>
#include <stddef.h>

#include "report/report_writer.h"

typedef enum {
    REPORT_COLUMN_TEXT,   /* char array */
    REPORT_COLUMN_STRING, /* const char * */
    REPORT_COLUMN_INT,    /* int */
    REPORT_COLUMN_COUNT,  /* uint64_t */
    REPORT_COLUMN_REAL,   /* double */
    REPORT_COLUMN_CELL    /* table only: drawn by `cell` */
} report_column_kind;

/* Which value of a REPORT_COLUMN_REAL column is its table's best: the row
 * holding it is drawn bold (report_table_best_row). A table ranks by its
 * first ranked column (one with neither header nor key ranks a table whose
 * cell shows the figure another way, e.g. with its standard error); NaN
 * never ranks, and a table of one row marks none. */
typedef enum { REPORT_UNRANKED, REPORT_LOWEST_BEST, REPORT_HIGHEST_BEST } report_rank;

typedef struct {
    const char *header; /* table heading, or NULL: JSON only */
    const char *key;    /* summary.json member, or NULL: table only */
    report_column_kind kind;
    size_t offset;      /* of the field in the row struct */
    const char *format; /* of the table cell (REPORT_COLUMN_REAL; default "%g") */
    void (*cell)(const void *row, char *text, size_t size); /* REPORT_COLUMN_CELL */
    report_rank rank;   /* REPORT_COLUMN_REAL: whether the table's best row is its lowest or highest */
} report_column;

#define REPORT_TEXT(header, key, type, field) {header, key, REPORT_COLUMN_TEXT, offsetof(type, field), NULL, NULL, REPORT_UNRANKED}
#define REPORT_STRING(header, key, type, field) {header, key, REPORT_COLUMN_STRING, offsetof(type, field), NULL, NULL, REPORT_UNRANKED}
#define REPORT_INT(header, key, type, field) {header, key, REPORT_COLUMN_INT, offsetof(type, field), NULL, NULL, REPORT_UNRANKED}
#define REPORT_COUNT(header, key, type, field) {header, key, REPORT_COLUMN_COUNT, offsetof(type, field), NULL, NULL, REPORT_UNRANKED}
#define REPORT_REAL(header, key, format, type, field) \
    {header, key, REPORT_COLUMN_REAL, offsetof(type, field), format, NULL, REPORT_UNRANKED}
#define REPORT_CELL(header, function) {header, NULL, REPORT_COLUMN_CELL, 0, NULL, function, REPORT_UNRANKED}
/* A real the table ranks its rows by (rank: REPORT_LOWEST_BEST for an error). */
#define REPORT_RANKED(header, key, format, type, field, rank) \
    {header, key, REPORT_COLUMN_REAL, offsetof(type, field), format, NULL, rank}

/* The table of `count` rows (each `row_size` bytes from `rows`) in the
 * report, and one object per row appended to json_list (either may be NULL). */
void report_rows(report *doc, cJSON *json_list, const report_column *columns, int column_count, const void *rows,
                 size_t row_size, int count);

/* One struct's fields as members of an object `key` added to parent (JSON
 * only: for figures that are not a table, e.g. a fit's coefficients).
 * Returns the object. */
cJSON *report_object(cJSON *parent, const char *key, const report_column *columns, int column_count,
                     const void *row);

#endif
