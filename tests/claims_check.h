/* The report sections' claim rows checked against their expected verdicts
 * (docs/claims-protocol.md): for the section tests that fill a claims table
 * from made-up results. Include after tests/check.h and report/claims_table.h. */
#ifndef GTLAB_TESTS_CLAIMS_CHECK_H
#define GTLAB_TESTS_CLAIMS_CHECK_H

#include "report/claims_table.h"
#include "tests/check.h"

/* Rows at .. at + count - 1 of c have the verdicts expected[0 .. count - 1]. */
static void check_verdicts(const claims_table *c, int at, const claim_verdict *expected, int count)
{
    for (int k = 0; k < count; ++k)
        CHECK_MSG(c->rows[at + k].verdict == expected[k], "row %d: %s", at + k, c->rows[at + k].verdict_name);
}

#endif
