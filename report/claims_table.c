#define _GNU_SOURCE
#include "report/claims_table.h"

#include <math.h>
#include <stddef.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/json_file.h"
#include "report/report_table.h"

static int text_given(const char *s) { return s && s[0] != '\0'; }

int claim_record_check(const claim_record *r, gt_error *e)
{
    const char *what = r->talk ? r->talk : "a claim";
    if (!text_given(r->quote) || !text_given(r->seed) || !text_given(r->section))
        return gt_error_set(e, what, "claim record without the talk's words, transcript or section");
    if (!text_given(r->setting))
        return gt_error_set(e, what, "claim record \"%.60s\" without the talk's setting", r->quote);
    if (!text_given(r->reading))
        return gt_error_set(e, what, "claim record \"%.60s\" without gtlab's reading", r->quote);
    if (r->setting_match != CLAIM_SETTING_TALK && !text_given(r->setting_note))
        return gt_error_set(e, what, "claim record \"%.60s\" does not say how gtlab's setting differs", r->quote);
    if (r->tolerance_source == CLAIM_TOLERANCE_NOISE_FLOOR)
        return gt_error_set(e, what, "claim record \"%.60s\" takes its tolerance from a noise floor, which decides "
                                     "significance, never the claim", r->quote);
    int judged = r->form == CLAIM_RANGE || r->form == CLAIM_BETTER || r->form == CLAIM_AS_GOOD;
    if (judged && (r->tolerance_source == CLAIM_TOLERANCE_NONE || !text_given(r->tolerance)))
        return gt_error_set(e, what, "claim record \"%.60s\" without its tolerance and where it comes from", r->quote);
    if ((r->form == CLAIM_BETTER || r->form == CLAIM_AS_GOOD) && !(r->margin > 0))
        return gt_error_set(e, what, "claim record \"%.60s\": a comparison needs a visible margin > 0", r->quote);
    if (r->form == CLAIM_RANGE && !(r->low <= r->high))
        return gt_error_set(e, what, "claim record \"%.60s\": empty region [%g, %g]", r->quote, r->low, r->high);
    return 0;
}

/* Where the interval [lo, hi] lies against the region [low, high]. */
static claim_verdict judge_range(double lo, double hi, double low, double high)
{
    if (lo >= low && hi <= high)
        return CLAIM_REPRODUCED;
    if (hi < low || lo > high)
        return CLAIM_REFUTED;
    return CLAIM_NOT_SIGNIFICANT;
}

/* "A better than B" past the margin m: below -m better, within [-m, m] no
 * visible difference, above +m worse. */
static claim_verdict judge_better(double lo, double hi, double m)
{
    if (hi < -m)
        return CLAIM_REPRODUCED;
    if (lo > m)
        return CLAIM_REFUTED;
    if (lo >= -m && hi <= m)
        return CLAIM_NO_VISIBLE_DIFFERENCE;
    return CLAIM_NOT_SIGNIFICANT;
}

claim_verdict claim_judge(const claim_record *r, double figure, double standard_error)
{
    double lo = figure - CLAIM_Z * standard_error, hi = figure + CLAIM_Z * standard_error;
    if (r->form == CLAIM_ASSUMPTION)
        return CLAIM_LIMITATION_MEASURED;
    if (r->form == CLAIM_UNTESTABLE)
        return CLAIM_NOT_TESTABLE;
    if (!(lo <= hi)) /* NaN: nothing can be said */
        return CLAIM_NOT_SIGNIFICANT;
    if (r->form == CLAIM_BETTER)
        return judge_better(lo, hi, r->margin);
    if (r->form == CLAIM_AS_GOOD)
        return judge_range(lo, hi, -INFINITY, r->margin);
    return judge_range(lo, hi, r->low, r->high);
}

claim_verdict claim_verdict_of(const claim_record *r, double figure, double standard_error)
{
    claim_verdict v = claim_judge(r, figure, standard_error);
    if (v != CLAIM_REFUTED)
        return v;
    if (r->setting_match == CLAIM_SETTING_GTLAB)
        return CLAIM_FAILS_GTLAB_SETTING;
    return text_given(r->stronger_reading) ? CLAIM_FAILS_STRONGER_READING : CLAIM_REFUTED;
}

/* The boundary of the record's region nearest the figure (NaN: none). */
static double nearest_boundary(const claim_record *r, double x)
{
    double ends[4] = {r->low, r->high, -r->margin, r->margin};
    int first = r->form == CLAIM_RANGE ? 0 : 2, last = r->form == CLAIM_AS_GOOD ? 3 : first + 1;
    if (r->form == CLAIM_AS_GOOD)
        first = 3;
    double best = NAN;
    for (int i = first; i <= last; ++i)
        if (isfinite(ends[i]) && (isnan(best) || fabs(x - ends[i]) < fabs(x - best)))
            best = ends[i];
    return best;
}

/* Not significant: the interval must shrink by (z s) / |x - b| to clear the
 * nearest boundary b, i.e. that factor squared times the data. */
static void say_what_decides(claim *c)
{
    double b = nearest_boundary(&c->record, c->figure), gap = fabs(c->figure - b);
    if (c->verdict != CLAIM_NOT_SIGNIFICANT || isnan(b))
        return;
    if (!(gap > 0) || !(c->standard_error > 0)) {
        snprintf(c->decided_by, sizeof c->decided_by, "the figure lies on the boundary %.3g: no amount of data "
                 "decides it", b);
        return;
    }
    double narrower = CLAIM_Z * c->standard_error / gap;
    snprintf(c->decided_by, sizeof c->decided_by,
             "an interval %.2gx narrower would decide it: about %.2gx the data its standard error is over "
             "(if the figure stays at %.3g)", narrower, narrower * narrower, c->figure);
}

static claim *next_row(claims_table *t)
{
    if (t->count >= CLAIMS_MAX) {
        t->refused++;
        snprintf(t->first_refusal, sizeof t->first_refusal, "more than %d claims", CLAIMS_MAX);
        return NULL;
    }
    claim *row = &t->rows[t->count++];
    memset(row, 0, sizeof *row);
    return row;
}

static void fill_row(claim *row, const claim_record *r, double figure, double standard_error)
{
    row->record = *r;
    row->figure = figure;
    row->standard_error = standard_error;
    row->ci_low = figure - CLAIM_Z * standard_error;
    row->ci_high = figure + CLAIM_Z * standard_error;
    row->verdict = claim_verdict_of(r, figure, standard_error);
    row->verdict_name = claim_verdict_name(row->verdict);
    say_what_decides(row);
}

int claims_table_add(claims_table *t, const claim_record *r, double figure, double standard_error,
                     const char *quantity_fmt, ...)
{
    gt_error e = {{0}};
    if (!t)
        return 0;
    if (claim_record_check(r, &e) != 0) {
        if (t->refused++ == 0)
            snprintf(t->first_refusal, sizeof t->first_refusal, "%.400s", e.message);
        return -1;
    }
    claim *row = next_row(t);
    if (!row)
        return -1;
    fill_row(row, r, figure, standard_error);
    va_list ap;
    va_start(ap, quantity_fmt);
    vsnprintf(row->quantity, sizeof row->quantity, quantity_fmt, ap);
    va_end(ap);
    return 0;
}

int claims_table_check(const claims_table *t, gt_error *e)
{
    if (!t || t->refused == 0)
        return 0;
    return gt_error_set(e, "claims table", "%d claim record(s) refused; the first: %s", t->refused,
                        t->first_refusal);
}

static const char *or_blank(const char *s) { return s ? s : ""; }

static const char *tolerance_source_name(claim_tolerance_source s)
{
    static const char *const names[] = {"none", "the claim's own number", "a visibility threshold",
                                        "the talk's own comparison", "a noise floor (refused)"};
    return names[s];
}

static const char *setting_name(claim_setting s)
{
    static const char *const names[] = {"the talk's", "differs where the claim does not depend on it",
                                        "gtlab's, not the talk's"};
    return names[s];
}

static const char *form_name(claim_form f)
{
    static const char *const names[] = {"range", "better", "as good", "assumption", "untestable"};
    return names[f];
}

/* "x ± s" with 3 significant digits ("x (exact)" for an exact figure). */
static void figure_text(const claim *c, char *text, size_t size)
{
    if (c->record.form == CLAIM_UNTESTABLE)
        snprintf(text, size, "-");
    else if (c->standard_error > 0)
        snprintf(text, size, "%.3g ± %.2g", c->figure, c->standard_error);
    else
        snprintf(text, size, "%.3g (exact)", c->figure);
}

/* Where the claim holds: "[low, high]", "≤ high", "≥ low", "< -m (m visible)". */
static void region_text(const claim_record *r, char *text, size_t size)
{
    if (r->form == CLAIM_BETTER)
        snprintf(text, size, "< -%.3g (visibly better)", r->margin);
    else if (r->form == CLAIM_AS_GOOD)
        snprintf(text, size, "≤ %.3g (no visibly worse)", r->margin);
    else if (r->form != CLAIM_RANGE)
        snprintf(text, size, "-");
    else if (isinf(r->low) && isinf(r->high))
        snprintf(text, size, "any");
    else if (isinf(r->low))
        snprintf(text, size, "≤ %.3g", r->high);
    else if (isinf(r->high))
        snprintf(text, size, "≥ %.3g", r->low);
    else
        snprintf(text, size, "[%.3g, %.3g]", r->low, r->high);
}

static void talk_cell(const void *row, char *text, size_t size)
{
    const claim *c = row;
    snprintf(text, size, "%s%s%s", or_blank(c->record.talk), text_given(c->record.section) ? ", " : "",
             or_blank(c->record.section));
}

static void words_cell(const void *row, char *text, size_t size)
{
    snprintf(text, size, "\"%s\"", ((const claim *)row)->record.quote); /* every record has one */
}

static void reading_cell(const void *row, char *text, size_t size)
{
    const claim *c = row;
    const char *stronger = c->record.stronger_reading;
    const size_t n = strlen(c->record.reading);
    const int ends_sentence = n > 0 && c->record.reading[n - 1] == '.';
    snprintf(text, size, "%s%s%s", c->record.reading,
             !text_given(stronger) ? "" : ends_sentence ? " Stronger reading tested: " : ". Stronger reading tested: ",
             or_blank(stronger));
}

static void figure_cell(const void *row, char *text, size_t size) { figure_text(row, text, size); }
static void region_cell(const void *row, char *text, size_t size)
{
    region_text(&((const claim *)row)->record, text, size);
}
static void tolerance_cell(const void *row, char *text, size_t size)
{
    const claim *c = row;
    snprintf(text, size, "%s", tolerance_source_name(c->record.tolerance_source));
}
static void setting_cell(const void *row, char *text, size_t size)
{
    const claim *c = row;
    snprintf(text, size, "%s", setting_name(c->record.setting_match));
}
static void verdict_cell(const void *row, char *text, size_t size)
{
    snprintf(text, size, "%s", ((const claim *)row)->verdict_name);
}

static const report_column kColumns[] = {
    REPORT_CELL("talk, section", talk_cell),     REPORT_CELL("the talk's words", words_cell),
    REPORT_CELL("gtlab's reading", reading_cell), REPORT_CELL("setting", setting_cell),
    REPORT_CELL("figure ± s.e.", figure_cell),   REPORT_CELL("holds if", region_cell),
    REPORT_CELL("tolerance from", tolerance_cell), REPORT_CELL("verdict", verdict_cell),
};

/* JSON cannot hold an infinity: an open end is null. */
static void add_number(cJSON *o, const char *key, double value)
{
    if (isfinite(value))
        cJSON_AddNumberToObject(o, key, value);
    else
        cJSON_AddNullToObject(o, key);
}

static void add_text(cJSON *o, const char *key, const char *value)
{
    if (value)
        cJSON_AddStringToObject(o, key, value);
    else
        cJSON_AddNullToObject(o, key);
}

static cJSON *claim_json(const claim *c)
{
    const claim_record *r = &c->record;
    cJSON *o = cJSON_CreateObject();
    add_text(o, "talk", r->talk), add_text(o, "seed", r->seed), add_text(o, "section", r->section);
    add_text(o, "quote", r->quote), add_text(o, "setting", r->setting);
    add_text(o, "setting_match", setting_name(r->setting_match)), add_text(o, "setting_note", r->setting_note);
    add_text(o, "reading", r->reading), add_text(o, "stronger_reading", r->stronger_reading);
    add_text(o, "form", form_name(r->form)), add_text(o, "quantity", c->quantity);
    add_number(o, "holds_from", r->low), add_number(o, "holds_to", r->high);
    add_number(o, "margin", r->margin);
    add_text(o, "tolerance_source", tolerance_source_name(r->tolerance_source));
    add_text(o, "tolerance", r->tolerance);
    add_number(o, "figure", c->figure), add_number(o, "standard_error", c->standard_error);
    add_number(o, "ci_low", c->ci_low), add_number(o, "ci_high", c->ci_high);
    add_text(o, "verdict", c->verdict_name), add_text(o, "decided_by", c->decided_by);
    return o;
}

/* "N claims: a reproduced, b refuted, ..." (classes with none left out). */
static void verdict_counts_text(const claims_table *t, char *text, size_t size)
{
    int counts[CLAIM_VERDICT_COUNT] = {0};
    for (int i = 0; i < t->count; ++i)
        counts[t->rows[i].verdict]++;
    int n = snprintf(text, size, "%d claims:", t->count);
    const char *sep = " ";
    for (int v = 0; v < CLAIM_VERDICT_COUNT && n > 0 && (size_t)n < size; ++v)
        if (counts[v]) {
            n += snprintf(text + n, size - (size_t)n, "%s%d %s", sep, counts[v], claim_verdict_name(v));
            sep = ", ";
        }
}

static void add_verdict_counts(const claims_table *t, cJSON *summary)
{
    cJSON *o = cJSON_AddObjectToObject(summary, "claim_verdicts");
    int counts[CLAIM_VERDICT_COUNT] = {0};
    for (int i = 0; i < t->count; ++i)
        counts[t->rows[i].verdict]++;
    for (int v = 0; v < CLAIM_VERDICT_COUNT; ++v)
        cJSON_AddNumberToObject(o, claim_verdict_name(v), counts[v]);
}

void claims_table_render(const claims_table *t, report *doc, cJSON *summary)
{
    if (!t || t->count == 0)
        return;
    char counts[512];
    verdict_counts_text(t, counts, sizeof counts);
    report_heading(doc, 2, "Claims of the talks");
    report_paragraph(doc,
                     "Each statement a talk publishes that this run measures, tested as the talk states it "
                     "(docs/claims-protocol.md): the talk's words, gtlab's reading, whether the talk's setting is "
                     "reproduced, gtlab's figure with its standard error, where the claim holds and where that "
                     "tolerance comes from (the claim's own number, a visibility threshold of the output, or the "
                     "talk's own comparison; never a reference's noise floor, which decides significance only). "
                     "The verdict is computed from the 95%% interval figure -+ %.2f s.e.; claims.md holds one "
                     "paragraph per claim with the talk's setting and gtlab's.",
                     CLAIM_Z);
    report_finding(doc, "Claims of the talks", "%s (table at the end).", counts);
    report_rows(doc, NULL, kColumns, (int)(sizeof kColumns / sizeof kColumns[0]), t->rows, sizeof t->rows[0],
                t->count);
    cJSON *list = cJSON_AddArrayToObject(summary, "claims");
    for (int i = 0; i < t->count; ++i)
        cJSON_AddItemToArray(list, claim_json(&t->rows[i]));
    add_verdict_counts(t, summary);
}

/* One claim's paragraph of claims.md. */
static void claim_paragraph(FILE *out, int number, const claim *c)
{
    const claim_record *r = &c->record;
    char figure[96], region[96];
    figure_text(c, figure, sizeof figure);
    region_text(r, region, sizeof region);
    fprintf(out, "### %d. %s%s%s\n\n", number, or_blank(r->talk), text_given(r->section) ? " — " : "",
            or_blank(r->section));
    if (text_given(r->quote))
        fprintf(out, "> %s\n\n(transcript %s)\n\n", r->quote, r->seed);
    fprintf(out, "**%s.** ", c->verdict_name);
    fprintf(out, "The talk's setting: %s. gtlab's setting: %s%s%s. gtlab reads the claim as: %s", r->setting,
            setting_name(r->setting_match), text_given(r->setting_note) ? " — " : "", or_blank(r->setting_note),
            r->reading);
    if (text_given(r->stronger_reading))
        fprintf(out, " This row tests a stronger reading: %s", r->stronger_reading);
    if (r->form == CLAIM_UNTESTABLE) {
        fprintf(out, "\n\n");
        return;
    }
    fprintf(out, " Measured: %s = %s (95%% interval [%.3g, %.3g]).", c->quantity, figure, c->ci_low, c->ci_high);
    if (r->form != CLAIM_ASSUMPTION)
        fprintf(out, " The claim holds if the figure is %s; tolerance from %s: %s.", region,
                tolerance_source_name(r->tolerance_source), r->tolerance);
    if (text_given(c->decided_by))
        fprintf(out, " Not decided: %s.", c->decided_by);
    fprintf(out, "\n\n");
}

char *claims_table_markdown(const claims_table *t)
{
    char *text = NULL, counts[512] = "0 claims";
    size_t size = 0;
    FILE *out = open_memstream(&text, &size);
    if (!out)
        return NULL;
    if (t)
        verdict_counts_text(t, counts, sizeof counts);
    fprintf(out, "# Claims of the talks\n\nGenerated by `gtlab all` from the claim records (report/claims_table.h, "
                 "docs/claims-protocol.md); do not edit. %s.\n\n", counts);
    for (int i = 0; t && i < t->count; ++i)
        claim_paragraph(out, i + 1, &t->rows[i]);
    if (fclose(out) != 0)
        return free(text), NULL;
    return text;
}

/* A row's fields for its JSON form: its record's, then its own. */
#define RECORD_TEXT(f) {#f, offsetof(claim, record.f), JSON_FIELD_TEXT_POINTER, 0}
#define RECORD_NUMBER(f, kind) {#f, offsetof(claim, record.f), kind, 0}
static const json_field claim_fields[] = {
    RECORD_TEXT(talk),    RECORD_TEXT(seed),         RECORD_TEXT(section),
    RECORD_TEXT(quote),   RECORD_TEXT(setting),      RECORD_TEXT(setting_note),
    RECORD_TEXT(reading), RECORD_TEXT(stronger_reading), RECORD_TEXT(tolerance),
    RECORD_NUMBER(low, JSON_FIELD_DOUBLE), RECORD_NUMBER(high, JSON_FIELD_DOUBLE),
    RECORD_NUMBER(margin, JSON_FIELD_DOUBLE), RECORD_NUMBER(setting_match, JSON_FIELD_INT),
    RECORD_NUMBER(form, JSON_FIELD_INT), RECORD_NUMBER(tolerance_source, JSON_FIELD_INT),
    {"quantity", offsetof(claim, quantity), JSON_FIELD_TEXT_ARRAY, CLAIM_TEXT},
    {"figure", offsetof(claim, figure), JSON_FIELD_DOUBLE, 0},
    {"standard_error", offsetof(claim, standard_error), JSON_FIELD_DOUBLE, 0}};
_Static_assert(sizeof(claim_setting) == sizeof(int) && sizeof(claim_form) == sizeof(int) &&
                   sizeof(claim_tolerance_source) == sizeof(int),
               "a record's enums kept as ints");

cJSON *claim_to_json(const claim *c)
{
    cJSON *o = cJSON_CreateObject();
    json_fields_add(o, c, claim_fields, sizeof claim_fields / sizeof claim_fields[0]);
    return o;
}

int claims_table_add_json(claims_table *t, const cJSON *o)
{
    claim *c = calloc(1, sizeof *c); /* its record's texts point into o */
    int rc = !c || json_fields_read(o, c, claim_fields, sizeof claim_fields / sizeof claim_fields[0]) != 0
                 ? -1
                 : claims_table_add(t, &c->record, c->figure, c->standard_error, "%s", c->quantity);
    free(c);
    return rc;
}
