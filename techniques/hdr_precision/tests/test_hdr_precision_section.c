/* The precision section's three claims rows from made-up results (no study
 * runs): each verdict the one its made-up figures must give under its
 * record (docs/claims-protocol.md). */
#include "hdr_precision/hdr_precision_section.h"
#include "tests/check.h"
#include "tests/section_test.h"

#include <math.h>
#include <string.h>

/* Precision: the talk's own numbers reproduce; the power function's point
 * 0.236 refutes 116/255; bounds off by one unit of the printed last digit
 * are refuted. */
static void hdr_rows(void)
{
    static claims_table t;
    memset(&t, 0, sizeof t);
    hdr_precision_result r;
    memset(&r, 0, sizeof r);
    r.gamma22_point = 5.0 / 11.0, r.exponential_c_min = log(510.0 / 509.0), r.filmic_c_min = 0.0119052;
    hdr_precision_add_claims(&t, &r);
    const claim_verdict talk[3] = {CLAIM_REPRODUCED, CLAIM_REPRODUCED, CLAIM_REPRODUCED};
    CHECK(t.count == 3 && t.refused == 0);
    check_verdicts(&t, 0, talk, 3);
    r.gamma22_point = pow(2.2, -2.2 / 1.2), r.exponential_c_min = 0.00196272, r.filmic_c_min = 0.0119053;
    hdr_precision_add_claims(&t, &r);
    const claim_verdict off[3] = {CLAIM_REFUTED, CLAIM_REFUTED, CLAIM_REFUTED};
    CHECK(t.count == 3 + 3 && t.refused == 0);
    check_verdicts(&t, 3, off, 3);
}

int main(void)
{
    hdr_rows();
    return check_report("test_hdr_precision_section");
}
