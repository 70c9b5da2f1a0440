#define _GNU_SOURCE
#include "report/report_writer.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "core/files/atomic_file.h"
#include "report/claim_verdict.h"
#include "report/compare_viewer.h"
#include "report/figure_resolve.h"
#include "report/html_text.h"

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

/* Inserts text into a growing buffer at offset `at` (<= *len). */
static void insert(char **buf, size_t *len, size_t *cap, int *failed, size_t at, const char *text)
{
    size_t n = strlen(text), old = *len;
    append(buf, len, cap, failed, text); /* grows it by n */
    if (*failed)
        return;
    memmove(*buf + at + n, *buf + at, old - at);
    memcpy(*buf + at, text, n);
}

static void md(report *r, const char *text) { append(&r->md, &r->md_len, &r->md_cap, &r->failed, text); }
static void html(report *r, const char *text) { append(&r->html, &r->html_len, &r->html_cap, &r->failed, text); }

/* Appends text to an HTML buffer with <, >, & and " escaped. */
static void append_escaped(char **buf, size_t *len, size_t *cap, int *failed, const char *text)
{
    char one[2] = {0, 0};
    for (const char *c = text; *c; ++c) {
        const char *entity = *c == '<' ? "&lt;" : *c == '>' ? "&gt;" : *c == '&' ? "&amp;" : *c == '"' ? "&quot;" : NULL;
        one[0] = *c;
        append(buf, len, cap, failed, entity ? entity : one);
    }
}

static void html_escaped(report *r, const char *text)
{
    append_escaped(&r->html, &r->html_len, &r->html_cap, &r->failed, text);
}

static void finding_md(report *r, const char *text)
{
    append(&r->findings_md, &r->findings_md_len, &r->findings_md_cap, &r->failed, text);
}

/* text appended to one of r's HTML buffers, escaped or as it is. */
static void put_html(report *r, char **buf, size_t *len, size_t *cap, const char *text, int escaped)
{
    if (escaped)
        append_escaped(buf, len, cap, &r->failed, text);
    else
        append(buf, len, cap, &r->failed, text);
}

static void finding_html(report *r, const char *text, int escaped)
{
    put_html(r, &r->findings_html, &r->findings_html_len, &r->findings_html_cap, text, escaped);
}

static void section_md(report *r, const char *text)
{
    append(&r->section_md, &r->section_md_len, &r->section_md_cap, &r->failed, text);
}

static void section_html(report *r, const char *text, int escaped)
{
    put_html(r, &r->section_html, &r->section_html_len, &r->section_html_cap, text, escaped);
}

/* Moves text[at, end) back to `to` (to <= at), the text between moving on:
 * its length is unchanged. */
static void move_back(report *r, char *text, size_t to, size_t at, size_t end)
{
    size_t n = end - at;
    char *piece = r->failed || to > at || at > end ? NULL : malloc(n ? n : 1);
    if (!piece) {
        r->failed |= to <= at && at <= end; /* out of memory; a bad range is left as it is */
        return;
    }
    memcpy(piece, text + at, n);
    memmove(text + to + n, text + to, at - to);
    memcpy(text + to, piece, n);
    free(piece);
}

/* The section's lead figure (its first row of figures) moved up to just
 * after its heading, where its conclusions will precede it. */
static void lead_figure_up(report *r)
{
    if (!r->lead_found)
        return;
    r->lead_found = 0;
    move_back(r, r->md, r->section_md_at, r->lead_md_at, r->lead_md_end);
    move_back(r, r->html, r->section_html_at, r->lead_html_at, r->lead_html_end);
}

/* The current level-2 section's findings, as its conclusions, inserted just
 * after its heading, above its lead figure; the section is closed. */
static void close_section(report *r)
{
    lead_figure_up(r);
    if (r->section_md_len > 0) {
        insert(&r->section_md, &r->section_md_len, &r->section_md_cap, &r->failed, 0, "Conclusions:\n\n");
        section_md(r, "\n");
        insert(&r->md, &r->md_len, &r->md_cap, &r->failed, r->section_md_at, r->section_md);
        insert(&r->section_html, &r->section_html_len, &r->section_html_cap, &r->failed, 0,
               "<ul class=\"conclusions\">\n");
        section_html(r, "</ul>\n", 0);
        insert(&r->html, &r->html_len, &r->html_cap, &r->failed, r->section_html_at, r->section_html);
    }
    r->section_md_len = r->section_html_len = 0;
    if (r->section_md)
        r->section_md[0] = '\0';
    if (r->section_html)
        r->section_html[0] = '\0';
}

static void contents_md(report *r, const char *text)
{
    append(&r->contents_md, &r->contents_md_len, &r->contents_md_cap, &r->failed, text);
}

static void contents_html(report *r, const char *text, int escaped)
{
    put_html(r, &r->contents_html, &r->contents_html_len, &r->contents_html_cap, text, escaped);
}

/* The heading's slug (report_writer.h), without the repeat suffix. */
static void heading_slug(const char *text, char *slug, size_t size)
{
    size_t n = 0;
    for (const unsigned char *c = (const unsigned char *)text; *c && n + 1 < size; ++c)
        if (isalnum(*c) || *c == '-' || *c == '_')
            slug[n++] = (char)tolower(*c);
        else if (*c == ' ')
            slug[n++] = '-';
    slug[n] = '\0';
}

/* Whether anchor was used before (r->anchors holds "\n"-separated anchors). */
static int anchor_used(const report *r, const char *anchor)
{
    size_t n = strlen(anchor);
    for (const char *p = r->anchors; p && (p = strstr(p, anchor)) != NULL; p += n)
        if ((p == r->anchors || p[-1] == '\n') && p[n] == '\n')
            return 1;
    return 0;
}

/* A new unique anchor for a heading (size >= 8), remembered. */
static void heading_anchor(report *r, const char *text, char *anchor, size_t size)
{
    char slug[112];
    heading_slug(text, slug, sizeof slug);
    snprintf(anchor, size, "%s", slug);
    for (int k = 1; anchor_used(r, anchor); ++k)
        snprintf(anchor, size, "%s-%d", slug, k);
    append(&r->anchors, &r->anchors_len, &r->anchors_cap, &r->failed, anchor);
    append(&r->anchors, &r->anchors_len, &r->anchors_cap, &r->failed, "\n");
}

/* One entry of the table of contents. */
static void add_contents_entry(report *r, const char *text, const char *anchor)
{
    contents_md(r, "- [");
    contents_md(r, text);
    contents_md(r, "](#");
    contents_md(r, anchor);
    contents_md(r, ")\n");
    contents_html(r, "<li><a href=\"#", 0);
    contents_html(r, anchor, 0);
    contents_html(r, "\">", 0);
    contents_html(r, text, 1);
    contents_html(r, "</a></li>\n", 0);
}

/* A journal entry [name] appended to r->journal (NULL: none kept). */
static cJSON *journal_entry(report *r, const char *name)
{
    if (!r->journal)
        return NULL;
    cJSON *entry = cJSON_CreateArray();
    if (!entry || !cJSON_AddItemToArray(entry, cJSON_CreateString(name)) ||
        !cJSON_AddItemToArray(r->journal, entry)) {
        cJSON_Delete(entry);
        r->failed = 1;
        return NULL;
    }
    return entry;
}

static void journal_add(report *r, cJSON *entry, cJSON *item)
{
    if (entry && !cJSON_AddItemToArray(entry, item))
        r->failed = 1;
}

static void journal_text(report *r, cJSON *entry, const char *text)
{
    if (entry)
        journal_add(r, entry, cJSON_CreateString(text ? text : ""));
}

static void journal_texts(report *r, cJSON *entry, int count, const char *const *texts)
{
    if (!entry)
        return;
    cJSON *a = cJSON_CreateArray();
    for (int i = 0; a && i < count; ++i)
        if (!cJSON_AddItemToArray(a, cJSON_CreateString(texts[i] ? texts[i] : "")))
            r->failed = 1;
    journal_add(r, entry, a);
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
            "text-align:right}th{background:#f3f3f3}td:first-child,th:first-child,td.prose,th.l{text-align:left}td.long{min-width:14em}\n"
            /* a figure as wide as its image (its caption wraps there): rows of maps line up */
            "figure{display:inline-block;vertical-align:top;width:min-content;margin:.5em;text-align:center}"
            "figure img{max-width:256px;min-width:160px;image-rendering:pixelated;border:1px solid #ddd}"
            "figcaption{font-size:.85em;color:#555}\n"
            "table.glance td{text-align:left}table.glance tr.sig td:last-child{font-weight:bold}\n"
            "tr.best td{font-weight:bold;background:#eef7ee}\n"
            "td.v-holds{color:#1a7f37}td.v-fails{color:#b42318;font-weight:bold}td.v-measured{color:#1f4e99}"
            "td.v-open{color:#8a6d00}\n"
            "ul.conclusions{background:#f6f8fa;border-left:4px solid #4a7;padding:.5em 1em .5em 2em}\n"
            "details{margin:.6em 0}details>summary{cursor:pointer;color:#444}"
            "details[open]>summary .lead{display:none}\n"
            "figure:has(img[src$=\".svg\"]){display:block;width:auto}figure img[src$=\".svg\"]{max-width:100%;width:100%;"
            "image-rendering:auto;border:0}\n"
            ".cbar{display:flex;align-items:center;gap:.3em;font-size:.8em;width:100%;max-width:256px;margin:2px auto}"
            ".cbar-ramp{flex:1;height:10px;border:1px solid #999}\n"
            "</style>\n");
    html(r, compare_viewer_head());
    html(r, "</head><body>\n<h1>");
    html_escaped(r, title);
    html(r, "</h1>\n");
    append(&r->anchors, &r->anchors_len, &r->anchors_cap, &r->failed, "at-a-glance\ncontents\n"); /* report_write's */
}

void report_heading(report *r, int level, const char *text)
{
    cJSON *entry = journal_entry(r, "heading");
    if (entry)
        journal_add(r, entry, cJSON_CreateNumber(level)), journal_text(r, entry, text);
    char tag[8], anchor[128];
    heading_anchor(r, text, anchor, sizeof anchor);
    if (level == 2) {
        close_section(r);
        r->lead_taken = 0;
        snprintf(r->section_anchor, sizeof r->section_anchor, "%s", anchor);
        add_contents_entry(r, text, anchor);
    }
    for (int i = 0; i < level; ++i)
        md(r, "#");
    md(r, " ");
    md(r, text);
    md(r, "\n\n");
    snprintf(tag, sizeof tag, "h%d", level);
    html(r, "<");
    html(r, tag);
    html(r, " id=\"");
    html(r, anchor);
    html(r, "\">");
    html_escaped(r, text);
    html(r, "</");
    html(r, tag);
    html(r, ">\n");
    if (level == 2) {
        r->section_md_at = r->md_len;
        r->section_html_at = r->html_len;
        r->in_section = 1;
    }
}

/* The length of text's opening words: its first sentence (up to ". "),
 * cut at a space before REPORT_FOLD_CHARACTERS / 2 characters if longer. */
static size_t lead_length(const char *text)
{
    const char *stop = strstr(text, ". ");
    size_t n = stop ? (size_t)(stop - text) + 1 : strlen(text), limit = REPORT_FOLD_CHARACTERS / 2;
    if (n <= limit)
        return n;
    while (limit > 0 && text[limit] != ' ')
        --limit;
    return limit > 0 ? limit : REPORT_FOLD_CHARACTERS / 2;
}

/* A long paragraph in report.html: folded, its opening words showing. */
static void folded_paragraph(report *r, const char *text)
{
    char lead[REPORT_FOLD_CHARACTERS];
    size_t n = lead_length(text);
    snprintf(lead, sizeof lead, "%.*s", (int)n, text);
    html(r, "<details><summary><span class=\"lead\">");
    html_escaped(r, lead);
    html(r, text[n] ? " &hellip;</span> <i>(more)</i></summary><p>" : "</span></summary><p>");
    html_escaped(r, text);
    html(r, "</p></details>\n");
}

void report_paragraph(report *r, const char *fmt, ...)
{
    char text[4096];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    journal_text(r, journal_entry(r, "paragraph"), text);
    md(r, text);
    md(r, "\n\n");
    if (strlen(text) > REPORT_FOLD_CHARACTERS)
        folded_paragraph(r, text);
    else {
        html(r, "<p>");
        html_escaped(r, text);
        html(r, "</p>\n");
    }
}

/* A Markdown table cell: a '|' inside it would end the cell, so it is
 * written "\|" (GitHub-flavoured Markdown's escape). */
static void md_cell(report *r, const char *text)
{
    char one[2] = {0, 0};
    for (const char *c = text; *c; ++c) {
        one[0] = *c;
        md(r, *c == '|' ? "\\|" : one);
    }
}

/* Whether a cell reads as a figure ("0.12", "-3e-4 (2%)", "256x256",
 * "12 s"), right-aligned, rather than prose, left-aligned. */
static int cell_is_figure(const char *text)
{
    while (*text == ' ')
        ++text;
    if (*text == '+' || *text == '-')
        ++text;
    if (*text == '.')
        ++text;
    return isdigit((unsigned char)*text);
}

/* A prose cell at least this long is a paragraph ("prose long"): its column
 * is given a paragraph's width, so that it does not wrap to a word a line
 * beside shorter columns (issue 41: the claims table's readings). */
enum { PARAGRAPH_CELL_CHARS = 120 };

/* The class of a prose cell: "prose", "prose long" for a paragraph, and a
 * claim verdict's tone when the cell is exactly a verdict's name
 * (report/claim_verdict.h). */
static const char *verdict_class(const char *text)
{
    if (strlen(text) >= PARAGRAPH_CELL_CHARS)
        return " class=\"prose long\"";
    static const char *const tones[] = {[CLAIM_TONE_HOLDS] = " class=\"prose v-holds\"",
                                        [CLAIM_TONE_FAILS] = " class=\"prose v-fails\"",
                                        [CLAIM_TONE_MEASURED] = " class=\"prose v-measured\"",
                                        [CLAIM_TONE_OPEN] = " class=\"prose v-open\""};
    int v = claim_verdict_from_name(text);
    return v < 0 ? " class=\"prose\"" : tones[claim_verdict_tone((claim_verdict)v)];
}

/* A header cell's alignment class, left over prose, right over figures; of
 * one length, so that the first body row can turn one into the other in
 * place (align_html_headers). */
#define HEAD_PROSE " class=\"l\""
#define HEAD_FIGURE " class=\"r\""

/* A row of the open table; best: drawn bold (its table's best, report_table_best_row). */
static void table_row(report *r, const char *const *cells, const char *cell_tag, int best)
{
    md(r, "|");
    html(r, best ? "<tr class=\"best\">" : "<tr>");
    for (int c = 0; c < r->table_columns; ++c) {
        int bold = best && cells[c][0];
        md(r, bold ? " **" : " ");
        md_cell(r, cells[c]);
        md(r, bold ? "** |" : " |");
        html(r, "<");
        html(r, cell_tag);
        if (c > 0 && cell_tag[1] == 'd' && !cell_is_figure(cells[c]))
            html(r, verdict_class(cells[c]));
        else if (c > 0 && cell_tag[1] == 'h')
            html(r, HEAD_PROSE); /* turned into HEAD_FIGURE over a column of figures */
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
    journal_texts(r, journal_entry(r, "table_begin"), columns, headers);
    r->table_columns = columns, r->table_rows = 0;
    r->table_at = r->html_len;
    html(r, "<table>\n");
    r->table_head_at = r->html_len;
    table_row(r, headers, "th", 0);
    md(r, "|");
    r->table_align_at = r->md_len, r->table_aligned = 0;
    for (int c = 0; c < columns; ++c)
        md(r, " :--- |"); /* the first row turns a figure's column into " ---: |" */
    md(r, "\n");
}

/* The Markdown alignment row, from the table's first row: right for a
 * column of figures, left for prose and the first column. */
static void align_markdown_columns(report *r, const char *const *cells)
{
    enum { ALIGN_CELL = 7 }; /* strlen(" :--- |") == strlen(" ---: |") */
    r->table_aligned = 1;
    if (r->failed || r->table_align_at + (size_t)r->table_columns * ALIGN_CELL > r->md_len)
        return;
    for (int c = 1; c < r->table_columns; ++c)
        if (cell_is_figure(cells[c]))
            memcpy(r->md + r->table_align_at + (size_t)c * ALIGN_CELL, " ---: |", ALIGN_CELL);
}

/* The HTML header row's alignment, from the table's first row: each
 * header over a column of figures right-aligned like its column. */
static void align_html_headers(report *r, const char *const *cells)
{
    if (r->failed || r->table_head_at > r->html_len)
        return;
    char *at = r->html + r->table_head_at;
    for (int c = 1; c < r->table_columns && at; ++c) {
        at = strstr(at + 1, "<th" HEAD_PROSE ">");
        if (at && cell_is_figure(cells[c]))
            memcpy(at + 3, HEAD_FIGURE, sizeof HEAD_FIGURE - 1);
    }
}

/* A body row, journalled as `name`. */
static void body_row(report *r, const char *name, const char *const *cells, int best)
{
    journal_texts(r, journal_entry(r, name), r->table_columns, cells);
    if (!r->table_aligned) {
        align_markdown_columns(r, cells);
        align_html_headers(r, cells);
    }
    r->table_rows++;
    table_row(r, cells, "td", best);
}

void report_table_row(report *r, const char *const *cells) { body_row(r, "table_row", cells, 0); }

void report_table_best_row(report *r, const char *const *cells) { body_row(r, "table_best_row", cells, 1); }

/* A long table (more than REPORT_FOLD_ROWS rows) folded in HTML, its
 * summary the row count: "<details class="rows"><summary>24 rows (show)". */
static void fold_long_table(report *r)
{
    if (r->table_rows <= REPORT_FOLD_ROWS || r->failed || r->table_at > r->html_len)
        return;
    char summary[128];
    snprintf(summary, sizeof summary, "<details class=\"rows\"><summary>a table of %d rows <i>(show)</i></summary>\n",
             r->table_rows);
    insert(&r->html, &r->html_len, &r->html_cap, &r->failed, r->table_at, summary);
    html(r, "</details>\n");
}

void report_table_end(report *r)
{
    journal_entry(r, "table_end");
    r->table_columns = 0;
    md(r, "\n");
    html(r, "</table>\n");
    fold_long_table(r);
}

/* An image's source and its colour bar's place, marked for
 * figures_resolve (report/figure_resolve.h): FIGURE_SRC path FIGURE_SRC. */
static void html_marked(report *r, const char *mark, const char *path)
{
    html(r, mark);
    html(r, path);
    html(r, mark);
}

/* The Markdown of a row of figures: the images with their captions. */
static void md_figures(report *r, int count, const char *const *paths, const char *const *captions)
{
    for (int i = 0; i < count; ++i) {
        md(r, "![");
        md(r, captions[i]);
        md(r, "](");
        md(r, paths[i]);
        md(r, ") ");
    }
    md(r, "\n\n");
}

/* One image with its caption: linked to itself in a row of figures, or
 * as a pane of a comparison view; its colour bar's place marked. */
static void html_figure(report *r, int in_view, const char *path, const char *caption)
{
    html(r, in_view ? "<figure class=\"cmp-pane\"><div class=\"cmp-clip\">" : "<figure><a href=\"");
    if (!in_view) {
        html_marked(r, FIGURE_SRC, path);
        html(r, "\">");
    }
    html(r, "<img src=\"");
    html_marked(r, FIGURE_SRC, path);
    html(r, "\" alt=\"");
    html_escaped(r, caption);
    html(r, in_view ? "\" draggable=\"false\"></div>" : "\"></a>");
    html_marked(r, FIGURE_BAR, path);
    html(r, "<figcaption>");
    html_escaped(r, caption);
    html(r, "</figcaption></figure>\n");
}

void report_figures(report *r, int count, const char *const *paths, const char *const *captions)
{
    cJSON *entry = journal_entry(r, "figures");
    journal_texts(r, entry, count, paths);
    journal_texts(r, entry, count, captions);
    const int lead = r->in_section && !r->lead_taken;
    if (lead)
        r->lead_md_at = r->md_len, r->lead_html_at = r->html_len;
    md_figures(r, count, paths, captions);
    html(r, "<div>\n");
    for (int i = 0; i < count; ++i)
        html_figure(r, 0, paths[i], captions[i]);
    html(r, "</div>\n");
    if (lead)
        r->lead_md_end = r->md_len, r->lead_html_end = r->html_len, r->lead_found = r->lead_taken = 1;
}

void report_comparison(report *r, int count, const char *const *paths, const char *const *labels, int exposed,
                       const char *caption)
{
    cJSON *entry = journal_entry(r, "comparison");
    journal_texts(r, entry, count, paths);
    journal_texts(r, entry, count, labels);
    if (entry)
        journal_add(r, entry, cJSON_CreateNumber(exposed)), journal_text(r, entry, caption);
    char attribute[64];
    md(r, caption);
    md(r, ":\n\n");
    md_figures(r, count, paths, labels);
    snprintf(attribute, sizeof attribute, "<div class=\"cmp\" tabindex=\"0\" data-exposed=\"%d\">\n", exposed);
    html(r, attribute);
    html(r, "<div class=\"cmp-panes\">\n");
    for (int i = 0; i < count; ++i)
        html_figure(r, 1, paths[i], labels[i]);
    html(r, "</div><p class=\"cmp-cap\">");
    html_escaped(r, caption);
    html(r, " <i>(click or keys 1-9, n, p to flip; s side by side; wheel to zoom, drag to pan, 0 to reset)</i></p>"
            "</div>\n");
}

void report_findings_here(report *r)
{
    journal_entry(r, "findings_here");
    r->findings_md_at = r->md_len;
    r->findings_html_at = r->html_len;
}

/* One finding as a list item of a Markdown and an HTML list; with an
 * anchor, its topic links there. */
static void finding_item(report *r, void (*put_md)(report *, const char *),
                         void (*put)(report *, const char *, int), const char *anchor, const char *topic,
                         const char *text)
{
    put_md(r, anchor ? "- **[" : "- **");
    put_md(r, topic);
    if (anchor) {
        put_md(r, "](#");
        put_md(r, anchor);
        put_md(r, ")");
        put(r, "<li><b><a href=\"#", 0);
        put(r, anchor, 0);
        put(r, "\">", 0);
    } else
        put(r, "<li><b>", 0);
    put_md(r, "**: ");
    put_md(r, text);
    put_md(r, "\n");
    put(r, topic, 1);
    put(r, anchor ? "</a></b>: " : "</b>: ", 0);
    put(r, text, 1);
    put(r, "</li>\n", 0);
}

void report_finding(report *r, const char *topic, const char *fmt, ...)
{
    char text[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    cJSON *entry = journal_entry(r, "finding");
    journal_text(r, entry, topic);
    journal_text(r, entry, text);
    const char *anchor = r->section_anchor[0] ? r->section_anchor : NULL;
    finding_item(r, finding_md, finding_html, anchor, topic, text);
    if (anchor) /* the section's own conclusions */
        finding_item(r, section_md, section_html, NULL, topic, text);
}

void report_add_headline(report *r, const report_headline *h)
{
    cJSON *entry = journal_entry(r, "headline");
    if (entry)
        journal_add(r, entry, headline_to_json(h));
    if (r->headline_count >= HEADLINES_MAX)
        return;
    report_headline *row = &r->headlines[r->headline_count++];
    *row = *h;
    snprintf(row->anchor, sizeof row->anchor, "%s", r->section_anchor);
}

/* `body` with the sections glance and contents (each with its head and
 * tail, or nothing when NULL) inserted at offset `at`, written atomically. */
static int write_with_sections(const char *path, const char *body, size_t at, const char *const glance[3],
                               const char *const contents[3], const char *resolve_dir, gt_error *e)
{
    const char *parts[6];
    size_t n = strlen(body) + 1;
    for (int i = 0; i < 6; ++i) {
        const char *const *section = i < 3 ? glance : contents;
        parts[i] = section ? section[i % 3] : "";
        n += strlen(parts[i]);
    }
    char *text = malloc(n);
    if (!text)
        return gt_error_set(e, path, "out of memory");
    snprintf(text, n, "%.*s%s%s%s%s%s%s%s", (int)at, body, parts[0], parts[1], parts[2], parts[3], parts[4],
             parts[5], body + at);
    char *resolved = resolve_dir ? figures_resolve(text, resolve_dir) : NULL;
    int rc = resolve_dir && !resolved ? gt_error_set(e, path, "out of memory")
                                      : atomic_write_text(path, resolved ? resolved : text, e);
    free(resolved);
    free(text);
    return rc;
}

/* The summary's opening sentence as a Markdown paragraph and an HTML one
 * (empty without rows). */
static void glance_opening(const report *r, char *md, size_t md_size, char *html_text, size_t html_size)
{
    char sentence[4 * HEADLINE_TEXT];
    headlines_opening(r->headlines, r->headline_count, sentence, sizeof sentence);
    md[0] = html_text[0] = 0;
    if (!sentence[0])
        return;
    snprintf(md, md_size, "%s\n\n", sentence);
    FILE *f = fmemopen(html_text, html_size, "w");
    if (!f)
        return;
    fputs("<p>", f);
    html_put_escaped(f, sentence);
    fputs("</p>\n", f);
    fclose(f);
}

/* The heads of the "At a glance" section: its title, the opening sentence,
 * the summary table and the findings list's opening (malloc'd; NULL when out
 * of memory). */
static int glance_heads(const report *r, char **md_head, char **html_head)
{
    char *table_md = NULL, *table_html = NULL, opening_md[8 * HEADLINE_TEXT], opening_html[16 * HEADLINE_TEXT];
    *md_head = *html_head = NULL;
    glance_opening(r, opening_md, sizeof opening_md, opening_html, sizeof opening_html);
    if (headlines_render(r->headlines, r->headline_count, &table_md, &table_html) == 0 &&
        (asprintf(md_head, "## At a glance\n\n%s%s", opening_md, table_md) < 0 ||
         asprintf(html_head, "<h2 id=\"at-a-glance\">At a glance</h2>\n%s%s<ul>\n", opening_html, table_html) < 0))
        *md_head = *html_head = NULL; /* asprintf leaves them undefined */
    free(table_md);
    free(table_html);
    return *md_head && *html_head ? 0 : -1;
}

int report_write(report *r, const char *dir, gt_error *e)
{
    close_section(r);
    html(r, "</body></html>\n");
    char *md_head, *html_head;
    if (glance_heads(r, &md_head, &html_head) != 0 || r->failed) {
        free(md_head), free(html_head);
        return gt_error_set(e, dir, "out of memory while writing the report");
    }
    int glance = r->findings_md_len > 0 || r->headline_count > 0;
    int contents = r->findings_html_at > 0 && r->contents_md_len > 0;
    const char *const glance_md[3] = {md_head, r->findings_md ? r->findings_md : "", "\n"};
    const char *const contents_md[3] = {"## Contents\n\n", r->contents_md, "\n"};
    const char *const glance_html[3] = {html_head, r->findings_html ? r->findings_html : "", "</ul>\n"};
    const char *const contents_html[3] = {"<h2 id=\"contents\">Contents</h2>\n<ul>\n", r->contents_html, "</ul>\n"};
    char path[4096];
    snprintf(path, sizeof path, "%s/report.md", dir);
    int rc = write_with_sections(path, r->md, glance || contents ? r->findings_md_at : 0, glance ? glance_md : NULL,
                                 contents ? contents_md : NULL, NULL, e);
    snprintf(path, sizeof path, "%s/report.html", dir);
    if (rc == 0)
        rc = write_with_sections(path, r->html, glance || contents ? r->findings_html_at : 0,
                                 glance ? glance_html : NULL, contents ? contents_html : NULL, dir, e);
    free(md_head);
    free(html_head);
    return rc;
}

void report_free(report *r)
{
    free(r->md);
    free(r->html);
    free(r->findings_md);
    free(r->findings_html);
    free(r->contents_md);
    free(r->contents_html);
    free(r->anchors);
    free(r->section_md);
    free(r->section_html);
    memset(r, 0, sizeof *r);
}
