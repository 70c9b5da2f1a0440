/* The claims rows of best-fit normals (Kaplanyan 2010's "Storage techniques
 * breakdown") from made-up results (no study runs): each verdict the one its
 * made-up counts must give under its record (docs/claims-protocol.md). */
#include "best_fit_normals/best_fit_normals_section.h"
#include "tests/check.h"
#include "tests/section_test.h"

#include <math.h>
#include <string.h>

/* Normals: the talk's exact counts everywhere reproduce the three cell rows;
 * counts off by 6% fail only under gtlab's counting (the talk's is not
 * stated); the bits row is log2 of the talk's own 289880, 18.15: it fails the
 * stronger reading (bits over the whole sphere) its record names. */
static void normals_rows(void)
{
    static normals_result r;
    memset(&r, 0, sizeof r);
    r.request.face_count = 1;
    r.sampled[0].face = 2048;
    static claims_table t;
    memset(&t, 0, sizeof t);
    r.cells_sphere = 289880, r.cells_surface = 390152, r.cells_distinct = 16482364;
    normals_add_claims(&t, &r);
    const claim_verdict talk[4] = {CLAIM_REPRODUCED, CLAIM_REPRODUCED, CLAIM_REPRODUCED, CLAIM_FAILS_STRONGER_READING};
    CHECK(t.count == 4 && t.refused == 0);
    check_verdicts(&t, 0, talk, 4);
    CHECK(fabs(t.rows[3].figure - log2(289880.0)) < 1e-12);
    r.cells_sphere = 306608, r.cells_surface = 390152 + 2000, r.cells_distinct = 15930488;
    normals_add_claims(&t, &r);
    const claim_verdict other[4] = {CLAIM_FAILS_GTLAB_SETTING, CLAIM_REFUTED, CLAIM_FAILS_GTLAB_SETTING,
                                    CLAIM_FAILS_STRONGER_READING};
    CHECK(t.count == 4 + 4 && t.refused == 0);
    check_verdicts(&t, 4, other, 4);
}

int main(void)
{
    normals_rows();
    return check_report("test_best_fit_normals_section");
}
