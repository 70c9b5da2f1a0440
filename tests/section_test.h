/* What a report section's test shares, for the tests that run a section on
 * made-up results: a report context over a fresh report and summary.json
 * object, writing under check_tmp_dir()/<name>, and the claims rows checked
 * against their expected verdicts (docs/claims-protocol.md). */
#ifndef GTLAB_TESTS_SECTION_TEST_H
#define GTLAB_TESTS_SECTION_TEST_H

#include <stdio.h>
#include <sys/stat.h>

#include "report/report_context.h"
#include "tests/check.h"

typedef struct {
    char dir[2048];
    report doc;
    report_context ctx; /* points into this struct: do not copy it */
} section_test;

/* t->ctx: output folder check_tmp_dir()/name, preview quality, one thread,
 * a new report and summary, claims into claims (NULL: none). */
static inline void section_test_begin(section_test *t, const char *name, claims_table *claims)
{
    snprintf(t->dir, sizeof t->dir, "%s/%s", check_tmp_dir(), name);
    mkdir(t->dir, 0755);
    report_init(&t->doc, "test");
    t->ctx = (report_context){{t->dir, QUALITY_PREVIEW, 1, NULL, NULL, 0}, &t->doc, cJSON_CreateObject(), claims};
}

static inline void section_test_end(section_test *t)
{
    report_free(&t->doc);
    cJSON_Delete(t->ctx.summary);
}

/* Rows at .. at + count - 1 of c have the verdicts expected[0 .. count - 1]. */
static inline void check_verdicts(const claims_table *c, int at, const claim_verdict *expected, int count)
{
    for (int k = 0; k < count; ++k)
        CHECK_MSG(c->rows[at + k].verdict == expected[k], "row %d: %s", at + k, c->rows[at + k].verdict_name);
}

#endif
