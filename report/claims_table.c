#include "report/claims_table.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "report/report_table.h"

claim_verdict claim_judge(double figure, double standard_error, double low, double high)
{
    double lo = figure - CLAIM_Z * standard_error, hi = figure + CLAIM_Z * standard_error;
    if (!(lo <= hi) || !(low <= high)) /* NaN anywhere: nothing can be said */
        return CLAIM_NOT_SIGNIFICANT;
    if (lo >= low && hi <= high)
        return CLAIM_REPRODUCED;
    if (hi < low || lo > high)
        return CLAIM_REFUTED;
    return CLAIM_NOT_SIGNIFICANT;
}

const char *claim_verdict_name(claim_verdict v)
{
    static const char *const names[] = {"not significant", "reproduced", "refuted"};
    return names[v];
}

void claims_table_add(claims_table *t, const claim *c)
{
    if (!t || t->count >= CLAIMS_MAX)
        return;
    claim *row = &t->rows[t->count++];
    *row = *c;
    row->ci_low = c->figure - CLAIM_Z * c->standard_error;
    row->ci_high = c->figure + CLAIM_Z * c->standard_error;
    row->verdict = claim_judge(c->figure, c->standard_error, c->low, c->high);
    row->verdict_name = claim_verdict_name(row->verdict);
}

void claims_table_add_figure(claims_table *t, const char *source, const char *statement, const char *quantity,
                             double figure, double standard_error, double low, double high)
{
    claim c = {.figure = figure, .standard_error = standard_error, .low = low, .high = high};
    snprintf(c.source, sizeof c.source, "%s", source);
    snprintf(c.statement, sizeof c.statement, "%s", statement);
    snprintf(c.quantity, sizeof c.quantity, "%s", quantity);
    claims_table_add(t, &c);
}

/* "x ± s" with 3 significant digits ("x" alone for an exact figure). */
static void figure_cell(const void *row, char *text, size_t size)
{
    const claim *c = row;
    if (c->standard_error > 0)
        snprintf(text, size, "%.3g ± %.2g", c->figure, c->standard_error);
    else
        snprintf(text, size, "%.3g (exact)", c->figure);
}

/* "[low, high]", "≤ high", "≥ low". */
static void region_cell(const void *row, char *text, size_t size)
{
    const claim *c = row;
    if (isinf(c->low) && isinf(c->high))
        snprintf(text, size, "any");
    else if (isinf(c->low))
        snprintf(text, size, "≤ %.3g", c->high);
    else if (isinf(c->high))
        snprintf(text, size, "≥ %.3g", c->low);
    else
        snprintf(text, size, "[%.3g, %.3g]", c->low, c->high);
}

static void interval_cell(const void *row, char *text, size_t size)
{
    const claim *c = row;
    snprintf(text, size, "[%.3g, %.3g]", c->ci_low, c->ci_high);
}

/* JSON cannot hold an infinity: an open end is null. */
static void add_end(cJSON *o, const char *key, double value)
{
    if (isfinite(value))
        cJSON_AddNumberToObject(o, key, value);
    else
        cJSON_AddNullToObject(o, key);
}

static const report_column kColumns[] = {
    REPORT_TEXT("source", "source", claim, source),
    REPORT_TEXT("the talk's statement", "statement", claim, statement),
    REPORT_TEXT("gtlab measured", "quantity", claim, quantity),
    REPORT_CELL("figure ± s.e.", figure_cell),
    REPORT_REAL(NULL, "figure", NULL, claim, figure),
    REPORT_REAL(NULL, "standard_error", NULL, claim, standard_error),
    REPORT_CELL("95% interval", interval_cell),
    REPORT_CELL("claim holds if", region_cell),
    REPORT_STRING("verdict", "verdict", claim, verdict_name),
};

void claims_table_render(const claims_table *t, report *doc, cJSON *summary)
{
    if (!t || t->count == 0)
        return;
    report_heading(doc, 2, "Claims of the talks");
    report_paragraph(doc,
                     "Each statement a talk publishes that this run measures: gtlab's figure with its standard "
                     "error, the 95%% interval figure -+ %.2f s.e., and the verdict computed from them: reproduced "
                     "when the interval lies where the claim holds, refuted when it lies wholly outside, not "
                     "significant when it straddles the boundary.",
                     CLAIM_Z);
    int verdicts[3] = {0};
    for (int i = 0; i < t->count; ++i)
        verdicts[t->rows[i].verdict]++;
    report_finding(doc, "Claims of the talks",
                   "%d measured (table at the end): %d reproduced, %d refuted, %d not significant at 95%%.",
                   t->count, verdicts[CLAIM_REPRODUCED], verdicts[CLAIM_REFUTED], verdicts[CLAIM_NOT_SIGNIFICANT]);
    cJSON *list = cJSON_AddArrayToObject(summary, "claims");
    report_rows(doc, list, kColumns, (int)(sizeof kColumns / sizeof kColumns[0]), t->rows, sizeof t->rows[0],
                t->count);
    for (int i = 0; i < t->count; ++i) {
        cJSON *o = cJSON_GetArrayItem(list, i);
        add_end(o, "holds_from", t->rows[i].low);
        add_end(o, "holds_to", t->rows[i].high);
    }
}
