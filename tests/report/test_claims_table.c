/* The claims table (report/claims_table.h): the verdict of each claim form
 * is computed from the figure, its standard error and the region or visible
 * margin, at the boundaries the 95% interval puts it; the setting and the
 * stronger reading qualify a refutation; a record without the talk's words,
 * setting or reading, or with a noise floor for its tolerance, is refused;
 * every verdict class renders from a made-up record into the report's
 * Markdown and HTML, summary.json and claims.md, and the headline counts
 * them by class. */
#include "report/claims_table.h"
#include "tests/check.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const claim_record kRange = {
    .talk = "A 2020", .seed = "000", .section = "Slide 1", .quote = "at most one percent", .setting = "1080p",
    .reading = "the error is at most 0.01", .form = CLAIM_RANGE, .low = -INFINITY, .high = 0.01,
    .tolerance_source = CLAIM_TOLERANCE_CLAIM_NUMBER, .tolerance = "the claim's 1%"};

static claim_record with_form(claim_form f, double margin)
{
    claim_record r = kRange;
    r.form = f, r.margin = margin;
    return r;
}

/* "At most t": the interval x +- z s decides, at its ends. */
static void test_range(void)
{
    const double t = 0.01, s = 0.001;
    CHECK(claim_judge(&kRange, t - 1.01 * CLAIM_Z * s, s) == CLAIM_REPRODUCED);
    CHECK(claim_judge(&kRange, t - 0.99 * CLAIM_Z * s, s) == CLAIM_NOT_SIGNIFICANT);
    CHECK(claim_judge(&kRange, t + 0.99 * CLAIM_Z * s, s) == CLAIM_NOT_SIGNIFICANT);
    CHECK(claim_judge(&kRange, t + 1.01 * CLAIM_Z * s, s) == CLAIM_REFUTED);
    CHECK(claim_judge(&kRange, 0.0100001, 0.0) == CLAIM_REFUTED);
    CHECK(claim_judge(&kRange, NAN, s) == CLAIM_NOT_SIGNIFICANT);
}

/* "A better than B" past the margin m: three decided outcomes and the gaps
 * between them; "as good as": only +m matters. */
static void test_comparisons(void)
{
    const double m = 0.004, s = 0.0005, w = CLAIM_Z * s;
    claim_record better = with_form(CLAIM_BETTER, m), as_good = with_form(CLAIM_AS_GOOD, m);
    CHECK(claim_judge(&better, -m - 1.01 * w, s) == CLAIM_REPRODUCED);
    CHECK(claim_judge(&better, -m - 0.99 * w, s) == CLAIM_NOT_SIGNIFICANT);
    CHECK(claim_judge(&better, 1e-6, s) == CLAIM_NO_VISIBLE_DIFFERENCE); /* a tiny, significant difference: equal */
    CHECK(claim_judge(&better, 1e-6, 1e-9) == CLAIM_NO_VISIBLE_DIFFERENCE);
    CHECK(claim_judge(&better, m + 1.01 * w, s) == CLAIM_REFUTED);
    CHECK(claim_judge(&better, m + 0.99 * w, s) == CLAIM_NOT_SIGNIFICANT);
    CHECK(claim_judge(&as_good, m - 1.01 * w, s) == CLAIM_REPRODUCED);
    CHECK(claim_judge(&as_good, -1.0, s) == CLAIM_REPRODUCED);
    CHECK(claim_judge(&as_good, m, s) == CLAIM_NOT_SIGNIFICANT);
    CHECK(claim_judge(&as_good, m + 1.01 * w, s) == CLAIM_REFUTED);
}

/* A refutation outside the talk's setting, or of a stronger reading, is
 * named as such; a reproduction is not touched by either. */
static void test_qualifiers(void)
{
    claim_record gtlab = kRange, stronger = kRange;
    gtlab.setting_match = CLAIM_SETTING_GTLAB, gtlab.setting_note = "256x256, not 1080p";
    stronger.stronger_reading = "at most 0.01 at every pixel";
    CHECK(claim_verdict_of(&gtlab, 1.0, 0.0) == CLAIM_FAILS_GTLAB_SETTING);
    CHECK(claim_verdict_of(&stronger, 1.0, 0.0) == CLAIM_FAILS_STRONGER_READING);
    CHECK(claim_verdict_of(&gtlab, 0.0, 0.0) == CLAIM_REPRODUCED);
    CHECK(claim_verdict_of(&kRange, 1.0, 0.0) == CLAIM_REFUTED);
    CHECK(claim_verdict_of(&(claim_record){.form = CLAIM_ASSUMPTION}, 1.0, 0.1) == CLAIM_LIMITATION_MEASURED);
    CHECK(claim_verdict_of(&(claim_record){.form = CLAIM_UNTESTABLE}, NAN, 0.0) == CLAIM_NOT_TESTABLE);
}

/* The builder refuses what the protocol forbids, counts it and names it. */
static void test_refusals(void)
{
    static claims_table t;
    claim_record noise = kRange, no_quote = kRange, no_setting = kRange, no_note = kRange, no_margin;
    noise.tolerance_source = CLAIM_TOLERANCE_NOISE_FLOOR;
    no_quote.quote = NULL, no_setting.setting = "", no_note.setting_match = CLAIM_SETTING_INDEPENDENT;
    no_margin = with_form(CLAIM_BETTER, 0.0);
    const claim_record *bad[] = {&noise, &no_quote, &no_setting, &no_note, &no_margin};
    for (int i = 0; i < 5; ++i) {
        gt_error e = {{0}};
        CHECK(claim_record_check(bad[i], &e) == -1 && e.message[0]);
        CHECK(claims_table_add(&t, bad[i], 0.0, 0.0, "x") == -1);
    }
    CHECK(t.count == 0 && t.refused == 5 && strstr(t.first_refusal, "noise floor"));
    gt_error e = {{0}};
    CHECK(claims_table_check(&t, &e) == -1 && strstr(e.message, "5 claim record"));
    CHECK(claims_table_add(NULL, &noise, 0.0, 0.0, "x") == 0); /* no table: nothing gathered */
}

/* One made-up record per verdict class, in the class order. */
static void fill_every_class(claims_table *t)
{
    claim_record better = with_form(CLAIM_BETTER, 0.004), gtlab = kRange, stronger = kRange;
    gtlab.setting_match = CLAIM_SETTING_GTLAB, gtlab.setting_note = "at 256x256";
    stronger.stronger_reading = "at every pixel";
    claim_record limitation = with_form(CLAIM_ASSUMPTION, 0), untestable = with_form(CLAIM_UNTESTABLE, 0);
    limitation.tolerance_source = untestable.tolerance_source = CLAIM_TOLERANCE_NONE;
    struct { const claim_record *r; double x, s; } cases[] = {
        {&kRange, 0.0, 0.001}, {&kRange, 0.5, 0.001}, {&stronger, 0.5, 0.0}, {&gtlab, 0.5, 0.0},
        {&better, 1e-6, 1e-7}, {&limitation, 0.3, 0.01}, {&kRange, 0.0105, 0.001}, {&untestable, NAN, 0.0}};
    for (int i = 0; i < 8; ++i)
        CHECK(claims_table_add(t, cases[i].r, cases[i].x, cases[i].s, "case %d figure", i) == 0);
}

static int occurrences(const char *text, const char *word)
{
    int n = 0;
    for (const char *at = text; at && (at = strstr(at, word)) != NULL; at += strlen(word))
        ++n;
    return n;
}

static void test_rendering(const claims_table *t)
{
    report doc;
    report_init(&doc, "test");
    cJSON *summary = cJSON_CreateObject();
    claims_table_render(t, &doc, summary);
    const cJSON *list = cJSON_GetObjectItemCaseSensitive(summary, "claims");
    const cJSON *counts = cJSON_GetObjectItemCaseSensitive(summary, "claim_verdicts");
    CHECK(cJSON_GetArraySize(list) == CLAIM_VERDICT_COUNT);
    char *md = claims_table_markdown(t);
    for (int v = 0; v < CLAIM_VERDICT_COUNT; ++v) {
        const char *name = claim_verdict_name(v);
        CHECK_MSG(t->rows[v].verdict == (claim_verdict)v, "row %d: %s", v, t->rows[v].verdict_name);
        const cJSON *o = cJSON_GetArrayItem(list, v);
        CHECK(strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(o, "verdict")), name) == 0);
        CHECK(cJSON_GetNumberValue(cJSON_GetObjectItem(counts, name)) == 1);
        CHECK_MSG(occurrences(doc.md, name) >= 1 && occurrences(doc.html, name) >= 1, "%s", name);
        CHECK_MSG(md && strstr(md, name), "claims.md lacks %s", name);
    }
    CHECK(strstr(doc.md, "\"at most one percent\"") && md && strstr(md, "> at most one percent"));
    CHECK(strstr(cJSON_GetStringValue(cJSON_GetObjectItem(cJSON_GetArrayItem(list, 6), "decided_by")), "narrower"));
    CHECK(cJSON_IsNull(cJSON_GetObjectItem(cJSON_GetArrayItem(list, 0), "holds_from")));
    CHECK(doc.findings_md && strstr(doc.findings_md, "8 claims: 1 reproduced, 1 refuted, 1 fails a stronger "
                                                     "reading, 1 fails under gtlab's setting, 1 no visible "
                                                     "difference"));
    free(md);
    report_free(&doc);
    cJSON_Delete(summary);
}

int main(void)
{
    test_range();
    test_comparisons();
    test_qualifiers();
    test_refusals();
    static claims_table t;
    fill_every_class(&t);
    CHECK(t.count == CLAIM_VERDICT_COUNT && t.refused == 0);
    test_rendering(&t);
    return check_report("test_claims_table");
}
