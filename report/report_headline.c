/* The report's summary table; see report_headline.h. */
#define _GNU_SOURCE
#include "report/report_headline.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cjson/cJSON.h>

#include "core/files/json_file.h"
#include "core/statistics/paired_power.h"
#include "core/statistics/sample_mean.h"
#include "metrics/noise_corrected.h"
#include "report/claims_table.h"
#include "report/html_text.h"

/* The indices of the two lowest of errors[0..count) (NaNs left out, ties
 * keep the earlier) into best and second; -1 when fewer than two. */
static int two_lowest(int count, const double *errors, int *best_out, int *second_out)
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
    *best_out = best, *second_out = second;
    return second < 0 ? -1 : 0;
}

static void set_ranked(report_headline *h, const char *const *labels, const double *errors, int best, int second)
{
    snprintf(h->best, sizeof h->best, "%s", labels[best]);
    snprintf(h->runner_up, sizeof h->runner_up, "%s", labels[second]);
    h->best_error = errors[best];
    h->runner_up_error = errors[second];
}

int headline_rank(report_headline *h, int count, const char *const *labels, const double *errors)
{
    int best, second;
    if (two_lowest(count, errors, &best, &second) != 0)
        return -1;
    set_ranked(h, labels, errors, best, second);
    return 0;
}

/* The mean of each candidate's numeric cases into means (NaN if none). */
static void case_means(int count, const double *errors, int cases, double *means)
{
    for (int i = 0; i < count; ++i) {
        double sum = 0.0;
        int n = 0;
        for (int k = 0; k < cases; ++k)
            if (!isnan(errors[i * cases + k]))
                sum += errors[i * cases + k], ++n;
        means[i] = n ? sum / n : NAN;
    }
}

/* The verdict of errors[second] - errors[best] paired over the cases both have. */
static void pair_indices(report_headline *h, const double *errors, int stride, int cases, int best, int second,
                         const char *over)
{
    double diff[256], d = NAN, s = NAN;
    int n = 0;
    for (int k = 0; k < cases && n < 256; ++k)
        if (!isnan(errors[second * stride + k]) && !isnan(errors[best * stride + k]))
            diff[n++] = errors[second * stride + k] - errors[best * stride + k];
    sample_mean_se(diff, n, &d, &s);
    headline_from_paired_cases(h, d, s, n, over);
}

int headline_rank_paired(report_headline *h, int count, const char *const *labels, const double *errors, int cases,
                         const char *over)
{
    double *means = malloc(sizeof *means * (size_t)(count > 0 ? count : 1));
    int best, second;
    if (!means)
        return -1;
    case_means(count, errors, cases, means);
    int rc = two_lowest(count, means, &best, &second);
    if (rc == 0) {
        set_ranked(h, labels, means, best, second);
        pair_indices(h, errors, cases, cases, best, second, over);
    }
    free(means);
    return rc;
}

void headline_pair_cases(report_headline *h, int count, const char *const *labels, const double *errors, int stride,
                         int cases, const char *over)
{
    int best = -1, second = -1;
    for (int i = 0; i < count; ++i) {
        best = !strcmp(labels[i], h->best) ? i : best;
        second = !strcmp(labels[i], h->runner_up) ? i : second;
    }
    if (best < 0 || second < 0)
        headline_from_difference(h, NAN, NAN, over);
    else
        pair_indices(h, errors, stride, cases, best, second, over);
}

/* A decided gap that a viewer could not see is no difference: |d| + w
 * within the margin (w the interval's half width), or a significant |d|
 * below it, which is undecided on what matters. */
void headline_apply_margin(report_headline *h, double d, double w)
{
    if (!(h->margin > 0) || h->significance == HEADLINE_NOT_COMPUTED)
        return;
    size_t k = strlen(h->basis);
    if (fabs(d) + w <= h->margin)
        h->significance = HEADLINE_NO_VISIBLE_DIFFERENCE;
    else if (h->significance != HEADLINE_NOT_SIGNIFICANT && fabs(d) <= h->margin)
        h->significance = HEADLINE_NOT_SIGNIFICANT;
    snprintf(h->basis + k, sizeof h->basis - k, "; visible from %.2g", h->margin);
}

/* Not decided: how many paired cases would decide it at 80% power, if the
 * gap and the per-case spread stay as observed (core/statistics/paired_power.h). The
 * gap to resolve is |d| (is there a difference?) or, with a margin m, its
 * distance | |d| - m | (visible or not?). */
static void say_cases_to_decide(report_headline *h, double d, double spread)
{
    if (h->significance != HEADLINE_NOT_SIGNIFICANT)
        return;
    double effect = fabs(fabs(d) - (h->margin > 0 ? h->margin : 0.0));
    int n = paired_cases_needed(effect, spread, 0.8, 1000000);
    size_t k = strlen(h->basis);
    h->cases_to_decide = n;
    if (n > 0)
        snprintf(h->basis + k, sizeof h->basis - k, "; about %d such cases would decide it (80%% power)", n);
    else
        snprintf(h->basis + k, sizeof h->basis - k, "; no number of cases would decide it at this gap");
}

void headline_from_difference(report_headline *h, double d, double s, const char *over)
{
    h->cases_to_decide = h->cases = 0, h->samples_factor_to_decide = 0.0;
    if (isnan(s) || isnan(d)) {
        h->significance = HEADLINE_NOT_COMPUTED;
        snprintf(h->basis, sizeof h->basis, "too few cases for a standard error (%s)", over);
        return;
    }
    h->significance = fabs(d) > CLAIM_Z * s ? HEADLINE_SIGNIFICANT : HEADLINE_NOT_SIGNIFICANT;
    snprintf(h->basis, sizeof h->basis, "difference %+.4g +- %.2g s.e., %s", d, s, over);
    headline_apply_margin(h, d, CLAIM_Z * s);
}

/* Not decided against a noise floor: the floor falls as 1/sqrt(samples),
 * so (floor / gap)^2 times the samples bring it down to the gap. */
static void say_samples_to_decide(report_headline *h, double gap, double floor)
{
    if (h->significance != HEADLINE_NOT_SIGNIFICANT || !(gap > 0))
        return;
    h->samples_factor_to_decide = (floor / gap) * (floor / gap);
    size_t k = strlen(h->basis);
    snprintf(h->basis + k, sizeof h->basis - k, "; about %.3g times the references' samples would decide it, if the floor "
             "falls as 1/sqrt(samples)",
             h->samples_factor_to_decide);
}

void headline_from_noise_floor(report_headline *h, double floor)
{
    double gap = fabs(h->runner_up_error - h->best_error);
    h->cases_to_decide = h->cases = 0, h->samples_factor_to_decide = 0.0;
    h->significance = gap > floor ? HEADLINE_ABOVE_NOISE_FLOOR : HEADLINE_NOT_SIGNIFICANT;
    snprintf(h->basis, sizeof h->basis, "gap %.2g %s the references' noise floor %.2g", gap,
             gap > floor ? "above" : "below", floor);
    headline_apply_margin(h, gap, 0.0);
    say_samples_to_decide(h, gap, floor);
}

void headline_from_paired_cases(report_headline *h, double d, double s, int cases, const char *over)
{
    double margin = h->margin;
    h->margin = 0.0; /* applied once, below, with Student's t */
    headline_from_difference(h, d, s, over);
    h->margin = margin;
    if (h->significance == HEADLINE_NOT_COMPUTED)
        return;
    double t = student_t_975(cases - 1);
    h->significance = fabs(d) > t * s ? HEADLINE_SIGNIFICANT : HEADLINE_NOT_SIGNIFICANT;
    size_t k = strlen(h->basis);
    snprintf(h->basis + k, sizeof h->basis - k, "; critical t(%d) = %.3g", cases - 1, t);
    headline_apply_margin(h, d, t * s);
    h->cases = cases;
    say_cases_to_decide(h, d, s * sqrt((double)cases));
}

void noise_budget_phrase(double noise, double figure, double margin, char *out, size_t size)
{
    double truth = noise_corrected_rmse(figure, noise * noise);
    double budget = noise_budget_for_measured_rmse(figure, noise, margin);
    if (noise <= budget)
        snprintf(out, size, "noise RMSE %.2g, within its budget %.2g", noise, budget);
    else
        snprintf(out, size, "noise RMSE %.2g, over its budget %.2g: figures near %.2g read up to %.2g high", noise,
                 budget, figure, figure - truth);
}

/* The best figure is measured against the noisy references: its true RMSE
 * is estimated with their noise taken out, and the budget is that
 * figure's (noise_budget_for_rmse). */
void headline_state_reference_noise(report_headline *h, double noise)
{
    if (!(noise >= 0) || !(h->margin > 0))
        return;
    h->reference_noise = noise;
    h->noise_budget = noise_budget_for_measured_rmse(h->best_error, noise, h->margin);
    char phrase[HEADLINE_TEXT];
    noise_budget_phrase(noise, h->best_error, h->margin, phrase, sizeof phrase);
    size_t k = strlen(h->basis);
    snprintf(h->basis + k, sizeof h->basis - k, "; references' %s", phrase);
}

int headline_missed_noise_budget(const report_headline *h)
{
    return h->noise_budget > 0 && h->reference_noise > h->noise_budget;
}

/* The rows whose references missed their noise budget, appended to out. */
static void append_missed_budgets(const report_headline *rows, int count, char *out, size_t size)
{
    const char *lead = " The references of ";
    int missed = 0;
    for (int i = 0; i < count; ++i) {
        if (!headline_missed_noise_budget(&rows[i]))
            continue;
        size_t k = strlen(out);
        snprintf(out + k, size - k, "%s%s (noise RMSE %.2g, budget %.2g)", lead, rows[i].topic,
                 rows[i].reference_noise, rows[i].noise_budget);
        lead = ", ", ++missed;
    }
    if (missed > 0) {
        size_t k = strlen(out);
        snprintf(out + k, size - k, " missed their noise budget at this quality: %s figures read high and %s gaps "
                 "low (the noise adds the same variance to both sides of a gap, so it cannot reverse a ranking, only "
                 "hide a visible gap).",
                 missed == 1 ? "its" : "their", missed == 1 ? "its" : "their");
    }
}

const char *headline_significance_name(headline_significance s)
{
    static const char *const names[] = {"not computed", "significant at 95%", "not significant at this quality",
                                        "above the noise floor (no interval)", "no visible difference"};
    return names[s];
}

/* What would decide an undecided row, appended to out: "X: about 42 paired
 * cases (it has 6)" or "X: about 24 times the references' samples". */
static void append_what_decides(const report_headline *h, char *out, size_t size)
{
    size_t k = strlen(out);
    if (h->cases_to_decide > 0)
        snprintf(out + k, size - k, "%s: about %d paired cases (it has %d)", h->topic, h->cases_to_decide, h->cases);
    else if (h->cases_to_decide < 0)
        snprintf(out + k, size - k, "%s: no number of cases (its gap sits at the visible margin)", h->topic);
    else if (h->samples_factor_to_decide > 0)
        snprintf(out + k, size - k, "%s: about %.3g times the references' samples (if their noise floor falls as "
                 "1/sqrt(samples))", h->topic,
                 h->samples_factor_to_decide);
    else
        snprintf(out + k, size - k, "%s: a measure with an interval", h->topic);
}

/* How many rows have verdict s. */
static int count_verdict(const report_headline *rows, int count, headline_significance s)
{
    int n = 0;
    for (int i = 0; i < count; ++i)
        n += rows[i].significance == s;
    return n;
}

void headlines_opening(const report_headline *rows, int count, char *out, size_t size)
{
    out[0] = 0;
    if (count <= 0 || size == 0)
        return;
    int decided = count_verdict(rows, count, HEADLINE_SIGNIFICANT);
    int equal = count_verdict(rows, count, HEADLINE_NO_VISIBLE_DIFFERENCE);
    int undecided = count_verdict(rows, count, HEADLINE_NOT_SIGNIFICANT);
    int rest = count - decided - equal - undecided;
    snprintf(out, size, "Of %d %s, %d %s decided (a significant gap, past its visible margin where it states one), "
             "%d %s no difference a viewer could see, %d %s undecided at this quality", count,
             count == 1 ? "ranking" : "rankings", decided, decided == 1 ? "is" : "are", equal,
             equal == 1 ? "shows" : "show", undecided, undecided == 1 ? "is" : "are");
    if (rest > 0) {
        size_t k = strlen(out);
        snprintf(out + k, size - k, ", and %d %s no interval (above the noise floor, or not computed)", rest,
                 rest == 1 ? "has" : "have");
    }
    const char *lead = "; what would decide them: ";
    for (int i = 0; i < count; ++i) {
        if (rows[i].significance != HEADLINE_NOT_SIGNIFICANT)
            continue;
        size_t k = strlen(out);
        snprintf(out + k, size - k, "%s", lead);
        append_what_decides(&rows[i], out, size);
        lead = "; ";
    }
    size_t k = strlen(out);
    snprintf(out + k, size - k, ".");
    append_missed_budgets(rows, count, out, size);
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
                                        "gap significant and visible?"};

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

/* The row's fields for its JSON form (the anchor is report_add_headline's). */
#define TEXT_FIELD(f) {#f, offsetof(report_headline, f), JSON_FIELD_TEXT_ARRAY, HEADLINE_TEXT}
#define DOUBLE_FIELD(f) {#f, offsetof(report_headline, f), JSON_FIELD_DOUBLE, 0}
#define INT_FIELD(f) {#f, offsetof(report_headline, f), JSON_FIELD_INT, 0}
static const json_field headline_fields[] = {
    TEXT_FIELD(topic),       TEXT_FIELD(measure),         TEXT_FIELD(best),
    TEXT_FIELD(runner_up),   TEXT_FIELD(basis),           DOUBLE_FIELD(best_error),
    DOUBLE_FIELD(runner_up_error), DOUBLE_FIELD(margin),  DOUBLE_FIELD(samples_factor_to_decide),
    DOUBLE_FIELD(reference_noise), DOUBLE_FIELD(noise_budget), INT_FIELD(significance),
    INT_FIELD(cases_to_decide),    INT_FIELD(cases)};
_Static_assert(sizeof(headline_significance) == sizeof(int), "significance kept as an int");

cJSON *headline_to_json(const report_headline *h)
{
    cJSON *o = cJSON_CreateObject();
    json_fields_add(o, h, headline_fields, sizeof headline_fields / sizeof headline_fields[0]);
    return o;
}

int headline_from_json(const cJSON *o, report_headline *h)
{
    memset(h, 0, sizeof *h);
    return json_fields_read(o, h, headline_fields, sizeof headline_fields / sizeof headline_fields[0]);
}
