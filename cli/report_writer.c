#include "cli/report_writer.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "core/atomic_file.h"

static void append(char **buf, size_t *len, size_t *cap, int *failed, const char *text)
{
    size_t n = strlen(text);
    if (*failed)
        return;
    if (*len + n + 1 > *cap) {
        size_t grown = (*cap ? *cap * 2 : 4096) + n;
        char *p = realloc(*buf, grown);
        if (!p) {
            *failed = 1;
            return;
        }
        *buf = p;
        *cap = grown;
    }
    memcpy(*buf + *len, text, n + 1);
    *len += n;
}

static void md(report *r, const char *text) { append(&r->md, &r->md_len, &r->md_cap, &r->failed, text); }
static void html(report *r, const char *text) { append(&r->html, &r->html_len, &r->html_cap, &r->failed, text); }

static void html_escaped(report *r, const char *text)
{
    char one[2] = {0, 0};
    for (const char *c = text; *c; ++c) {
        if (*c == '<')
            html(r, "&lt;");
        else if (*c == '>')
            html(r, "&gt;");
        else if (*c == '&')
            html(r, "&amp;");
        else if (*c == '"')
            html(r, "&quot;");
        else {
            one[0] = *c;
            html(r, one);
        }
    }
}

void report_init(report *r, const char *title)
{
    memset(r, 0, sizeof *r);
    md(r, "# ");
    md(r, title);
    md(r, "\n\n");
    html(r, "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>");
    html_escaped(r, title);
    html(r, "</title>\n<style>\n"
            "body{font-family:system-ui,sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;color:#222}\n"
            "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #ccc;padding:.3em .6em;"
            "text-align:right}th{background:#f3f3f3}td:first-child,th:first-child{text-align:left}\n"
            "figure{display:inline-block;margin:.5em;text-align:center}figure img{max-width:256px;"
            "image-rendering:pixelated;border:1px solid #ddd}figcaption{font-size:.85em;color:#555}\n"
            "</style></head><body>\n<h1>");
    html_escaped(r, title);
    html(r, "</h1>\n");
}

void report_heading(report *r, int level, const char *text)
{
    char tag[8];
    for (int i = 0; i < level; ++i)
        md(r, "#");
    md(r, " ");
    md(r, text);
    md(r, "\n\n");
    snprintf(tag, sizeof tag, "h%d", level);
    html(r, "<");
    html(r, tag);
    html(r, ">");
    html_escaped(r, text);
    html(r, "</");
    html(r, tag);
    html(r, ">\n");
}

void report_paragraph(report *r, const char *fmt, ...)
{
    char text[4096];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    md(r, text);
    md(r, "\n\n");
    html(r, "<p>");
    html_escaped(r, text);
    html(r, "</p>\n");
}

static void table_row(report *r, const char *const *cells, const char *cell_tag)
{
    md(r, "|");
    html(r, "<tr>");
    for (int c = 0; c < r->table_columns; ++c) {
        md(r, " ");
        md(r, cells[c]);
        md(r, " |");
        html(r, "<");
        html(r, cell_tag);
        html(r, ">");
        html_escaped(r, cells[c]);
        html(r, "</");
        html(r, cell_tag);
        html(r, ">");
    }
    md(r, "\n");
    html(r, "</tr>\n");
}

void report_table_begin(report *r, int columns, const char *const *headers)
{
    r->table_columns = columns;
    html(r, "<table>\n");
    table_row(r, headers, "th");
    md(r, "|");
    for (int c = 0; c < columns; ++c)
        md(r, c == 0 ? " --- |" : " ---: |");
    md(r, "\n");
}

void report_table_row(report *r, const char *const *cells) { table_row(r, cells, "td"); }

void report_table_end(report *r)
{
    r->table_columns = 0;
    md(r, "\n");
    html(r, "</table>\n");
}

void report_figures(report *r, int count, const char *const *paths, const char *const *captions)
{
    html(r, "<div>\n");
    for (int i = 0; i < count; ++i) {
        md(r, "![");
        md(r, captions[i]);
        md(r, "](");
        md(r, paths[i]);
        md(r, ") ");
        html(r, "<figure><a href=\"");
        html_escaped(r, paths[i]);
        html(r, "\"><img src=\"");
        html_escaped(r, paths[i]);
        html(r, "\" alt=\"");
        html_escaped(r, captions[i]);
        html(r, "\"></a><figcaption>");
        html_escaped(r, captions[i]);
        html(r, "</figcaption></figure>\n");
    }
    md(r, "\n\n");
    html(r, "</div>\n");
}

int report_write(report *r, const char *dir, gt_error *e)
{
    html(r, "</body></html>\n");
    if (r->failed)
        return gt_error_set(e, dir, "out of memory while writing the report");
    char path[4096];
    snprintf(path, sizeof path, "%s/report.md", dir);
    if (atomic_write_text(path, r->md, e) != 0)
        return -1;
    snprintf(path, sizeof path, "%s/report.html", dir);
    return atomic_write_text(path, r->html, e);
}

void report_free(report *r)
{
    free(r->md);
    free(r->html);
    memset(r, 0, sizeof *r);
}
