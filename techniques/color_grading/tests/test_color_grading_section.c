/* The colour-grading claims row from made-up results (no study runs): the
 * verdict the made-up share of looks within dE00 1 at 16^3 must give under
 * its record (docs/claims-protocol.md). */
#include "color_grading/color_grading_section.h"
#include "tests/check.h"
#include "tests/section_test.h"

#include <string.h>

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
    grading_rows();
    return check_report("test_color_grading_section");
}
