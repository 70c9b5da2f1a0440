/* The claims rows of Kaplanyan 2010 (CryENGINE 3) from made-up results (no
 * study runs): the precision section's three and the colour-grading row,
 * each verdict the one its made-up figures must give under its record
 * (docs/claims-protocol.md); best-fit normals' and the SG NDF's rows are
 * tested in techniques/best_fit_normals/tests/ and techniques/sg_ndf/tests/. */
#include "report/color_grading_section.h"
#include "report/hdr_precision_section.h"
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

/* Colour grading: 2 or 3 of 5 looks never decide "the majority" (the
 * binomial s.e. of so few looks); 0 or 40 of 40 do, either way. */
static void grading_rows(void)
{
    static claims_table t;
    memset(&t, 0, sizeof t);
    static grading_row rows[41];
    const char *names[2] = {"identity", "a look"};
    const int cases[4][2] = {{5, 2}, {5, 3}, {40, 0}, {40, 40}};
    const claim_verdict expected[4] = {CLAIM_NOT_SIGNIFICANT, CLAIM_NOT_SIGNIFICANT, CLAIM_FAILS_GTLAB_SETTING,
                                       CLAIM_REPRODUCED};
    for (int c = 0; c < 4; ++c) {
        int looks = cases[c][0], enough = cases[c][1];
        for (int i = 0; i <= looks; ++i) {
            memset(&rows[i], 0, sizeof rows[i]);
            rows[i].grade = names[i > 0], rows[i].size = 16;
            double de = i > 0 && i <= enough ? 0.5 : 2.0;
            rows[i].image[0].max_de = rows[i].image[2].max_de = i == 0 ? 0.0 : de;
        }
        color_grading_add_claim(&t, rows, looks + 1);
        CHECK(t.count == c + 1 && t.rows[c].figure == (double)enough / looks);
    }
    CHECK(t.count == 4 && t.refused == 0);
    check_verdicts(&t, 0, expected, 4);
}

int main(void)
{
    hdr_rows();
    grading_rows();
    return check_report("test_cryengine_claims");
}
