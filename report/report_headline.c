/* The report's summary table; see report_headline.h. */
#define _GNU_SOURCE
#include "report/report_headline.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "report/claims_table.h"
#include "report/html_text.h"

int headline_rank(report_headline *h, int count, const char *const *labels, const double *errors)
{
    int best = -1, second = -1;
    for (int i = 0; i < count; ++i) {
        if (isnan(errors[i]))
            continue;
        if (best < 0 || errors[i] < errors[best])
            second = best, best = i;
        else if (second < 0 || errors[i] < errors[second])
            second = i;
    }
    if (second < 0)
        return -1;
    snprintf(h->best, sizeof h->best, "%s", labels[best]);
    snprintf(h->runner_up, sizeof h->runner_up, "%s", labels[second]);
    h->best_error = errors[best];
    h->runner_up_error = errors[second];
    return 0;
}

void headline_from_difference(report_headline *h, double d, double s, const char *over)
{
    if (isnan(s) || isnan(d)) {
        h->significance = HEADLINE_NOT_COMPUTED;
        snprintf(h->basis, sizeof h->basis, "too few cases for a standard error (%s)", over);
        return;
    }
    h->significance = fabs(d) > CLAIM_Z * s ? HEADLINE_SIGNIFICANT : HEADLINE_NOT_SIGNIFICANT;
    snprintf(h->basis, sizeof h->basis, "difference %+.4g +- %.2g, %s", d, s, over);
}

void headline_from_noise_floor(report_headline *h, double floor)
{
    double gap = fabs(h->runner_up_error - h->best_error);
    h->significance = gap > floor ? HEADLINE_ABOVE_NOISE_FLOOR : HEADLINE_NOT_SIGNIFICANT;
    snprintf(h->basis, sizeof h->basis, "gap %.2g %s the references' noise floor %.2g", gap,
             gap > floor ? "above" : "below", floor);
}

const char *headline_significance_name(headline_significance s)
{
    static const char *const names[] = {"not computed", "significant at 95%", "not significant at this quality",
                                        "above the noise floor (no interval)"};
    return names[s];
}

/* A Markdown cell: '|' would end it. */
static void put_md_cell(FILE *f, const char *text)
{
    fputc(' ', f);
    for (const char *c = text; *c; ++c)
        fputs(*c == '|' ? "\\|" : (char[2]){*c, 0}, f);
    fputs(" |", f);
}

/* The cells of a row after the technique: measure, best, its error, the
 * runner-up, its error, the verdict with its basis. */
static void row_cells(const report_headline *h, char cells[6][2 * HEADLINE_TEXT])
{
    snprintf(cells[0], sizeof cells[0], "%s", h->measure);
    snprintf(cells[1], sizeof cells[1], "%s", h->best);
    snprintf(cells[2], sizeof cells[2], "%.4g", h->best_error);
    snprintf(cells[3], sizeof cells[3], "%s", h->runner_up);
    snprintf(cells[4], sizeof cells[4], "%.4g", h->runner_up_error);
    if (h->basis[0])
        snprintf(cells[5], sizeof cells[5], "%s (%s)", headline_significance_name(h->significance), h->basis);
    else
        snprintf(cells[5], sizeof cells[5], "%s", headline_significance_name(h->significance));
}

static const char *const kHeaders[7] = {"technique", "measure", "best", "its error", "runner-up", "its error",
                                        "gap significant?"};

static void render_md(FILE *f, const report_headline *rows, int count)
{
    fputs("|", f);
    for (int c = 0; c < 7; ++c)
        put_md_cell(f, kHeaders[c]);
    fputs("\n| --- | --- | --- | ---: | --- | ---: | --- |\n", f);
    for (int i = 0; i < count; ++i) {
        char cells[6][2 * HEADLINE_TEXT], topic[HEADLINE_TEXT + 160];
        row_cells(&rows[i], cells);
        snprintf(topic, sizeof topic, "[%s](#%s)", rows[i].topic, rows[i].anchor);
        fputs("|", f);
        put_md_cell(f, topic);
        for (int c = 0; c < 6; ++c)
            put_md_cell(f, cells[c]);
        fputs("\n", f);
    }
    fputs("\n", f);
}

static void render_html(FILE *f, const report_headline *rows, int count)
{
    fputs("<table class=\"glance\">\n<tr>", f);
    for (int c = 0; c < 7; ++c)
        fprintf(f, "<th>%s</th>", kHeaders[c]);
    fputs("</tr>\n", f);
    for (int i = 0; i < count; ++i) {
        char cells[6][2 * HEADLINE_TEXT];
        row_cells(&rows[i], cells);
        fprintf(f, "<tr class=\"%s\"><td><a href=\"#%s\">", rows[i].significance == HEADLINE_SIGNIFICANT ? "sig" : "",
                rows[i].anchor);
        html_put_escaped(f, rows[i].topic);
        fputs("</a></td>", f);
        for (int c = 0; c < 6; ++c) {
            fputs("<td>", f);
            html_put_escaped(f, cells[c]);
            fputs("</td>", f);
        }
        fputs("</tr>\n", f);
    }
    fputs("</table>\n", f);
}

int headlines_render(const report_headline *rows, int count, char **md, char **html)
{
    size_t md_size = 0, html_size = 0;
    *md = *html = NULL;
    FILE *fm = open_memstream(md, &md_size), *fh = open_memstream(html, &html_size);
    if (fm && count > 0)
        render_md(fm, rows, count);
    if (fh && count > 0)
        render_html(fh, rows, count);
    int ok = fm && fh;
    if (fm)
        fclose(fm);
    if (fh)
        fclose(fh);
    if (!ok) {
        free(*md), free(*html);
        *md = *html = NULL;
        return -1;
    }
    return 0;
}
