#include "report/report_table.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>

enum { CELL_MAX = 512, COLUMNS_MAX = 32 };

static const void *field(const void *row, const report_column *c) { return (const char *)row + c->offset; }

static void format_cell(const report_column *c, const void *row, char *text, size_t size)
{
    const void *f = field(row, c);
    switch (c->kind) {
    case REPORT_COLUMN_TEXT: snprintf(text, size, "%s", (const char *)f); break;
    case REPORT_COLUMN_STRING: snprintf(text, size, "%s", *(const char *const *)f); break;
    case REPORT_COLUMN_INT: snprintf(text, size, "%d", *(const int *)f); break;
    case REPORT_COLUMN_COUNT: snprintf(text, size, "%llu", (unsigned long long)*(const uint64_t *)f); break;
    case REPORT_COLUMN_REAL: snprintf(text, size, c->format ? c->format : "%g", *(const double *)f); break;
    case REPORT_COLUMN_CELL: c->cell(row, text, size); break;
    }
}

static void add_member(cJSON *o, const report_column *c, const void *row)
{
    const void *f = field(row, c);
    switch (c->kind) {
    case REPORT_COLUMN_TEXT: cJSON_AddStringToObject(o, c->key, (const char *)f); break;
    case REPORT_COLUMN_STRING: cJSON_AddStringToObject(o, c->key, *(const char *const *)f); break;
    case REPORT_COLUMN_INT: cJSON_AddNumberToObject(o, c->key, *(const int *)f); break;
    case REPORT_COLUMN_COUNT: cJSON_AddNumberToObject(o, c->key, (double)*(const uint64_t *)f); break;
    case REPORT_COLUMN_REAL: cJSON_AddNumberToObject(o, c->key, *(const double *)f); break;
    case REPORT_COLUMN_CELL: break;
    }
}

static void table_row(report *doc, const report_column *columns, int column_count, const void *row, int best)
{
    char cells[COLUMNS_MAX][CELL_MAX];
    const char *row_cells[COLUMNS_MAX];
    int n = 0;
    for (int i = 0; i < column_count && n < COLUMNS_MAX; ++i)
        if (columns[i].header) {
            format_cell(&columns[i], row, cells[n], CELL_MAX);
            row_cells[n] = cells[n];
            ++n;
        }
    if (best)
        report_table_best_row(doc, row_cells);
    else
        report_table_row(doc, row_cells);
}

/* The column the table ranks by: its first ranked real, or NULL. */
static const report_column *ranking_column(const report_column *columns, int column_count)
{
    for (int i = 0; i < column_count; ++i)
        if (columns[i].kind == REPORT_COLUMN_REAL && columns[i].rank != REPORT_UNRANKED)
            return &columns[i];
    return NULL;
}

/* The index of the best of `count` rows by the ranking column, or -1 (no
 * such column, fewer than two rows, or no row with a number). */
static int best_row(const report_column *columns, int column_count, const void *rows, size_t row_size, int count)
{
    const report_column *c = ranking_column(columns, column_count);
    if (!c || count < 2)
        return -1;
    int best = -1;
    double best_value = 0.0;
    for (int r = 0; r < count; ++r) {
        double v = *(const double *)field((const char *)rows + (size_t)r * row_size, c);
        int better = c->rank == REPORT_LOWEST_BEST ? v < best_value : v > best_value;
        if (!isnan(v) && (best < 0 || better))
            best = r, best_value = v;
    }
    return best;
}

static cJSON *json_row(const report_column *columns, int column_count, const void *row)
{
    cJSON *o = cJSON_CreateObject();
    for (int i = 0; i < column_count; ++i)
        if (columns[i].key)
            add_member(o, &columns[i], row);
    return o;
}

cJSON *report_object(cJSON *parent, const char *key, const report_column *columns, int column_count,
                     const void *row)
{
    cJSON *o = json_row(columns, column_count, row);
    cJSON_AddItemToObject(parent, key, o);
    return o;
}

static void table_begin(report *doc, const report_column *columns, int column_count)
{
    const char *headers[COLUMNS_MAX];
    int n = 0;
    for (int i = 0; i < column_count && n < COLUMNS_MAX; ++i)
        if (columns[i].header)
            headers[n++] = columns[i].header;
    report_table_begin(doc, n, headers);
}

void report_rows(report *doc, cJSON *json_list, const report_column *columns, int column_count, const void *rows,
                 size_t row_size, int count)
{
    int best = doc ? best_row(columns, column_count, rows, row_size, count) : -1;
    if (doc)
        table_begin(doc, columns, column_count);
    for (int r = 0; r < count; ++r) {
        const void *row = (const char *)rows + (size_t)r * row_size;
        if (doc)
            table_row(doc, columns, column_count, row, r == best);
        if (json_list)
            cJSON_AddItemToArray(json_list, json_row(columns, column_count, row));
    }
    if (doc)
        report_table_end(doc);
}
