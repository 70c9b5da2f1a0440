/* The claims table (report/claims_table.h): the verdict is computed from the
 * figure, its standard error and the region where the claim holds, at the
 * boundaries the 95% interval puts it; a table of made-up claims renders one
 * report row and one summary.json object per claim, in order, carrying the
 * fields exactly. */
#include "report/claims_table.h"
#include "tests/check.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* "At most t": the interval x +- z s decides, at its ends. */
static void test_verdict_at_most(void)
{
    const double t = 0.01, s = 0.001;
    CHECK(claim_judge(t - 1.01 * CLAIM_Z * s, s, -INFINITY, t) == CLAIM_REPRODUCED);
    CHECK(claim_judge(t - 0.99 * CLAIM_Z * s, s, -INFINITY, t) == CLAIM_NOT_SIGNIFICANT);
    CHECK(claim_judge(t + 0.99 * CLAIM_Z * s, s, -INFINITY, t) == CLAIM_NOT_SIGNIFICANT);
    CHECK(claim_judge(t + 1.01 * CLAIM_Z * s, s, -INFINITY, t) == CLAIM_REFUTED);
}

/* "Equals 0 within d": reproduced only when the whole interval is inside,
 * refuted on either side; an exact figure (s = 0) is judged by itself. */
static void test_verdict_within(void)
{
    const double d = 0.05, s = 0.01;
    CHECK(claim_judge(0.0, s, -d, d) == CLAIM_REPRODUCED);
    CHECK(claim_judge(d, s, -d, d) == CLAIM_NOT_SIGNIFICANT);
    CHECK(claim_judge(-d - 1.01 * CLAIM_Z * s, s, -d, d) == CLAIM_REFUTED);
    CHECK(claim_judge(d + 1.01 * CLAIM_Z * s, s, -d, d) == CLAIM_REFUTED);
    CHECK(claim_judge(0.5, 0.0, 0.0, 0.5) == CLAIM_REPRODUCED);
    CHECK(claim_judge(0.5000001, 0.0, 0.0, 0.5) == CLAIM_REFUTED);
    CHECK(claim_judge(NAN, s, -d, d) == CLAIM_NOT_SIGNIFICANT);
    CHECK(claim_judge(0.0, NAN, -d, d) == CLAIM_NOT_SIGNIFICANT);
}

static claims_table made_up_table(void)
{
    static claims_table t;
    memset(&t, 0, sizeof t);
    claims_table_add(NULL, &t.rows[0]); /* ignored */
    for (int i = 0; i < 3; ++i) {
        claim c = {.figure = 0.1 * i, .standard_error = 0.01 * (i + 1), .low = i == 2 ? 0.15 : -INFINITY,
                   .high = i == 2 ? INFINITY : 0.05};
        snprintf(c.source, sizeof c.source, "talk %d", i);
        snprintf(c.statement, sizeof c.statement, "statement number %d", i);
        snprintf(c.quantity, sizeof c.quantity, "quantity %d", i);
        claims_table_add(&t, &c);
    }
    return t;
}

static void test_summary(const claims_table *t, const cJSON *summary)
{
    const cJSON *list = cJSON_GetObjectItemCaseSensitive(summary, "claims");
    CHECK(cJSON_IsArray(list) && cJSON_GetArraySize(list) == t->count);
    for (int i = 0; i < t->count && i < cJSON_GetArraySize(list); ++i) {
        const cJSON *o = cJSON_GetArrayItem(list, i);
        const claim *c = &t->rows[i];
        CHECK(strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(o, "statement")), c->statement) == 0);
        CHECK(cJSON_GetNumberValue(cJSON_GetObjectItem(o, "figure")) == c->figure);
        CHECK(cJSON_GetNumberValue(cJSON_GetObjectItem(o, "standard_error")) == c->standard_error);
        CHECK(strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(o, "verdict")),
                     claim_verdict_name(claim_judge(c->figure, c->standard_error, c->low, c->high))) == 0);
        CHECK(cJSON_IsNull(cJSON_GetObjectItem(o, i == 2 ? "holds_to" : "holds_from")));
    }
}

/* Each claim's line of the Markdown table holds its statement and verdict, in order. */
static void test_table(const claims_table *t, const char *md)
{
    CHECK(md && strstr(md, "## Claims of the talks"));
    const char *at = md;
    for (int i = 0; i < t->count && at; ++i) {
        at = strstr(at, t->rows[i].statement);
        CHECK(at != NULL);
        const char *end = at ? strchr(at, '\n') : NULL;
        const char *verdict = at ? strstr(at, t->rows[i].verdict_name) : NULL;
        CHECK(end && verdict && verdict < end);
        at = end;
    }
}

int main(void)
{
    test_verdict_at_most();
    test_verdict_within();
    claims_table t = made_up_table();
    CHECK(t.count == 3);
    CHECK(t.rows[0].verdict == CLAIM_REPRODUCED && t.rows[1].verdict == CLAIM_REFUTED &&
          t.rows[2].verdict == CLAIM_NOT_SIGNIFICANT);
    report doc;
    report_init(&doc, "test");
    cJSON *summary = cJSON_CreateObject();
    claims_table_render(&t, &doc, summary);
    test_summary(&t, summary);
    test_table(&t, doc.md);
    CHECK(doc.findings_md && strstr(doc.findings_md, "3 measured (table at the end): 1 reproduced, 1 refuted, 1 not "
                                                     "significant"));
    report_free(&doc);
    cJSON_Delete(summary);
    return check_report("test_claims_table");
}
