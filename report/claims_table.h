/* The report's claims table: each statement a talk publishes, tested as the
 * talk states it, in its setting, with a tolerance from its own words
 * (docs/claims-protocol.md). A section measures a claim and adds one row:
 * the claim's record (static text, quoted from the talk) and gtlab's figure
 * with its standard error; the verdict is computed here, never typed in.
 * `gtlab all` renders the table once, at the end of the report, the array
 * "claims" of summary.json, and claims.md (one paragraph per claim).
 *
 * A record holds
 *   - the talk's words verbatim (`quote`, checked against the transcripts
 *     by tests/audit/claims_quotes.sh), the transcript (`seed`) and the
 *     section or slide title they stand under;
 *   - the talk's setting (resolution, parametrization, content, regime,
 *     what the technique is for) and how gtlab's compares (claim_setting);
 *   - gtlab's reading of the claim in one sentence, and, when the row tests
 *     more than the talk says, the stronger reading it tests;
 *   - the claim's form (claim_form) with its region or margin, and where
 *     the tolerance comes from (claim_tolerance_source) in words.
 * A record whose tolerance is a reference's noise floor, or that lacks the
 * quote, the setting, the reading or the tolerance's words, is refused:
 * claims_table_add returns -1, the table counts it and names it, and
 * `gtlab all` fails (a noise floor decides significance, never a claim).
 *
 * gtlab's figure x has standard error s (0: exact); its 95% interval is
 * x -+ CLAIM_Z s. The verdict (claim_verdict):
 *   CLAIM_RANGE     ("the quantity lies in [low, high]"): reproduced when the
 *                   interval lies inside, refuted when wholly outside, not
 *                   significant when it straddles an end;
 *   CLAIM_BETTER    ("A is better than B"; x = error(A) - error(B), lower is
 *                   better; margin m > 0 the smallest difference a viewer
 *                   could see): reproduced when the interval lies below -m,
 *                   refuted when above +m, "no visible difference" when
 *                   within [-m, m], not significant otherwise;
 *   CLAIM_AS_GOOD   ("A is as good as B", same x and m): reproduced when the
 *                   interval lies below +m, refuted when above, not
 *                   significant when it straddles +m;
 *   CLAIM_ASSUMPTION (the talk states an assumption or a concession): the
 *                   figure, "limitation measured", no verdict;
 *   CLAIM_UNTESTABLE (`reading` says what would test it): "not testable here".
 * A refutation becomes "fails a stronger reading" when the record names one,
 * and "fails under gtlab's setting" when the talk's setting is not
 * reproduced (CLAIM_SETTING_GTLAB). A verdict that is not significant says
 * what would decide it: how much narrower the interval must be, and so how
 * many times the data its standard error is over.
 *
 * Use:
 *     static const claim_record kFastMath = {
 *         .talk = "Jimenez et al. 2016 (GTAO)", .seed = "001", .section = "...",
 *         .quote = "...", .setting = "...", .setting_match = CLAIM_SETTING_TALK,
 *         .reading = "...", .form = CLAIM_AS_GOOD, .margin = GTAO_ONE_CODE_VALUE,
 *         .tolerance_source = CLAIM_TOLERANCE_VISIBILITY, .tolerance = "one 8-bit code value"};
 *     claims_table_add(ctx->claims, &kFastMath, x, s, "mean |AO(fast) - AO(exact)| over %d scenes", n);
 * The record's strings must outlive the table (string literals). */
#ifndef GTLAB_REPORT_CLAIMS_TABLE_H
#define GTLAB_REPORT_CLAIMS_TABLE_H

#include <cjson/cJSON.h>

#include "core/error.h"
#include "report/claim_verdict.h"
#include "report/report_writer.h"

#define CLAIM_Z 1.959963984540054 /* the two-sided 95% normal quantile */

enum { CLAIMS_MAX = 128, CLAIM_TEXT = 480 };

typedef enum {
    CLAIM_RANGE,      /* the quantity lies in [low, high] (an end may be infinite) */
    CLAIM_BETTER,     /* error(A) - error(B) below -margin */
    CLAIM_AS_GOOD,    /* error(A) - error(B) below +margin */
    CLAIM_ASSUMPTION, /* an assumption or concession of the talk: measured, not judged */
    CLAIM_UNTESTABLE  /* not testable here; the reading says what would test it */
} claim_form;

/* Where a claim's tolerance comes from, in the protocol's order. */
typedef enum {
    CLAIM_TOLERANCE_NONE,            /* CLAIM_ASSUMPTION, CLAIM_UNTESTABLE: no tolerance */
    CLAIM_TOLERANCE_CLAIM_NUMBER,    /* the claim's own number at its stated precision */
    CLAIM_TOLERANCE_VISIBILITY,      /* a visibility threshold of the output the technique feeds */
    CLAIM_TOLERANCE_TALK_COMPARISON, /* the talk's own comparison (A as good as / better than B) */
    CLAIM_TOLERANCE_NOISE_FLOOR      /* a reference's noise floor: refused */
} claim_tolerance_source;

/* How gtlab's setting compares with the talk's. */
typedef enum {
    CLAIM_SETTING_TALK,        /* the talk's resolution, parametrization, content and regime */
    CLAIM_SETTING_INDEPENDENT, /* differs only where the claim does not depend on it (setting_note says why) */
    CLAIM_SETTING_GTLAB        /* the talk's setting is not reproduced (setting_note says what differs) */
} claim_setting;

/* What the talk says and how gtlab reads it: static text. */
typedef struct {
    const char *talk;    /* authors, year and talk ("Jimenez et al. 2016 (GTAO)") */
    const char *seed;    /* the transcript holding the quote: "001" for ../shared/seeds/001_*.txt */
    const char *section; /* the talk's section or slide title */
    const char *quote;   /* the talk's words, verbatim */
    const char *setting; /* the talk's setting */
    claim_setting setting_match;
    const char *setting_note;     /* gtlab's setting where it differs, and why it may; NULL if the talk's */
    const char *reading;          /* gtlab's reading, one sentence */
    const char *stronger_reading; /* the stronger reading this row tests, or NULL */
    claim_form form;
    double low, high; /* CLAIM_RANGE */
    double margin;    /* CLAIM_BETTER, CLAIM_AS_GOOD: the smallest visible difference (> 0) */
    claim_tolerance_source tolerance_source;
    const char *tolerance; /* the tolerance and its source in words */
} claim_record;

typedef struct {
    claim_record record;
    char quantity[CLAIM_TEXT]; /* what the figure is, with its unit and what its s.e. is over */
    double figure, standard_error;
    /* set by claims_table_add */
    double ci_low, ci_high; /* figure -+ CLAIM_Z standard_error */
    claim_verdict verdict;
    const char *verdict_name;   /* claim_verdict_name(verdict) */
    char decided_by[CLAIM_TEXT]; /* not significant: what would decide it ("" otherwise) */
} claim;

typedef struct {
    int count;
    claim rows[CLAIMS_MAX];
    int refused;                 /* records refused by claims_table_add */
    char first_refusal[CLAIM_TEXT]; /* the first refusal's reason */
} claims_table;

/* The verdict of a figure with its standard error on a record, before the
 * setting and stronger-reading qualifiers (claim_verdict_of applies them). */
claim_verdict claim_judge(const claim_record *r, double figure, double standard_error);
claim_verdict claim_verdict_of(const claim_record *r, double figure, double standard_error);
/* Whether a record meets the protocol; -1 with e naming what it lacks. */
int claim_record_check(const claim_record *r, gt_error *e);

/* Appends the row (quantity printf-formatted); -1 when the record is
 * refused (counted in t->refused) or the table is full. A NULL table
 * ignores the row and returns 0. */
int claims_table_add(claims_table *t, const claim_record *r, double figure, double standard_error,
                     const char *quantity_fmt, ...) __attribute__((format(printf, 5, 6)));

/* The table in the report (heading "Claims of the talks"), the verdicts
 * counted by class in its "At a glance" list, the array "claims" and the
 * object "claim_verdicts" in summary; nothing when the table is empty. */
void claims_table_render(const claims_table *t, report *doc, cJSON *summary);
/* claims.md: one paragraph per claim, from the records alone. Returns a
 * malloc'd text (NULL if out of memory). */
char *claims_table_markdown(const claims_table *t);
/* A row as JSON (a stage's part, report/report_part.h): its record's
 * fields, quantity, figure and standard error (doubles exact,
 * core/files/json_file.h). */
cJSON *claim_to_json(const claim *c);
/* claims_table_add of a row claim_to_json wrote. The record's texts point
 * into o, which must outlive the table. 0, or -1 (nothing added) when o is
 * not such a row. */
int claims_table_add_json(claims_table *t, const cJSON *o);

/* -1 with e when any record was refused (gtlab all fails with it). */
int claims_table_check(const claims_table *t, gt_error *e);

#endif
