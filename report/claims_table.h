/* The report's claims table: each statement a talk publishes, beside gtlab's
 * figure for it with its uncertainty, and a verdict computed from the two,
 * never typed in. A section adds one row per claim it measures (any section,
 * in the order of the report); `gtlab all` renders the table once, at the
 * end of the report, and as the array "claims" of summary.json.
 *
 * A claim is "the quantity lies in [low, high]" (either end may be
 * infinite: "at most", "at least"; both finite: "equals within a
 * tolerance"). gtlab's figure x has standard error s (0: an exact figure,
 * e.g. a fraction of a grid); its 95% interval is x +- CLAIM_Z s, and
 *     reproduced      the interval lies inside [low, high],
 *     refuted         the interval lies wholly outside [low, high],
 *     not significant the interval straddles an end.
 * Use:
 *     claim c = {.source = "Jimenez 2016, Multi-Bounce", .statement = "...",
 *                .quantity = "...", .figure = x, .standard_error = s,
 *                .low = -INFINITY, .high = t};
 *     claims_table_add(ctx->claims, &c);   (a NULL table ignores the row) */
#ifndef GTLAB_REPORT_CLAIMS_TABLE_H
#define GTLAB_REPORT_CLAIMS_TABLE_H

#include <cjson/cJSON.h>

#include "report/report_writer.h"

#define CLAIM_Z 1.959963984540054 /* the two-sided 95% normal quantile */

enum { CLAIMS_MAX = 128, CLAIM_TEXT = 320 };

typedef enum { CLAIM_NOT_SIGNIFICANT, CLAIM_REPRODUCED, CLAIM_REFUTED } claim_verdict;

typedef struct {
    char source[CLAIM_TEXT];    /* the talk and its section */
    char statement[CLAIM_TEXT]; /* what it says, as tested */
    char quantity[CLAIM_TEXT];  /* what gtlab measured (the figure's meaning and unit) */
    double figure, standard_error;
    double low, high;           /* the claim holds when the quantity lies in [low, high] */
    /* set by claims_table_add */
    double ci_low, ci_high;     /* figure -+ CLAIM_Z standard_error */
    claim_verdict verdict;
    const char *verdict_name;   /* claim_verdict_name(verdict) */
} claim;

typedef struct {
    int count;
    claim rows[CLAIMS_MAX];
} claims_table;

/* The verdict of a figure with its standard error on the claim [low, high]. */
claim_verdict claim_judge(double figure, double standard_error, double low, double high);
/* "reproduced", "refuted", "not significant". */
const char *claim_verdict_name(claim_verdict v);

/* Appends a copy of c with its interval and verdict computed; a NULL table
 * or a full one (CLAIMS_MAX rows) ignores it. */
void claims_table_add(claims_table *t, const claim *c);
/* The same from its parts (texts truncated to CLAIM_TEXT - 1 characters). */
void claims_table_add_figure(claims_table *t, const char *source, const char *statement, const char *quantity,
                             double figure, double standard_error, double low, double high);

/* The table in the report (heading "Claims of the talks"), a line counting
 * the verdicts in its "At a glance" list, and the array "claims" in
 * summary; nothing when the table is empty. */
void claims_table_render(const claims_table *t, report *doc, cJSON *summary);

#endif
