/* The Decima talk's sphere-light claim rows (transcript 000) from results
 * made up here (no study runs): each section adds its records, and the
 * verdict follows the record's form, margin and setting:
 *   - the sun: the Newton step 0.17 +- 0.01 below Karis's point in mean
 *     |log error| is visibly better (reproduced); 0.005 +- 0.001 lies within
 *     the 1% margin (no visible difference);
 *   - the terminator's concession: limitation measured, whatever the figure;
 *   - the normalisation: 0.05 worse with it fails under gtlab's setting (the
 *     light_radius reading is gtlab's), never "refuted".
 * (The talk's anti-aliasing rows: techniques/anti_aliasing/tests/.) */
#include <string.h>

#include "sphere_light/sphere_light_section_parts.h"
#include "tests/check.h"
#include "tests/section_test.h"

static void sphere_rows(report_context *ctx)
{
    sphere_sun_result sun = {.configurations = 40, .samples = 1000, .gain = 0.17, .gain_se = 0.01};
    sphere_sun_section(ctx, &sun, ctx->summary);
    sun.gain = 0.005, sun.gain_se = 0.001;
    sphere_sun_section(ctx, &sun, ctx->summary);
    sphere_terminator_result t = {.configurations = 40, .samples = 1000, .talk_signed = 0.3, .talk_signed_se = 0.01};
    sphere_terminator_section(ctx, &t, ctx->summary);
    sphere_units_result u;
    memset(&u, 0, sizeof u);
    for (int r = 0; r < SPHERE_READINGS; ++r)
        u.rows[r].name = "sin", u.rows[r].meaning = "R/d";
    u.test = 40, u.gain = -0.05, u.gain_se = 0.005;
    sphere_units_section(ctx, &u, ctx->summary);
}

int main(void)
{
    static claims_table claims;
    static section_test t;
    section_test_begin(&t, "sphere_light_claims", &claims);
    sphere_rows(&t.ctx);
    gt_error e;
    CHECK_MSG(claims_table_check(&claims, &e) == 0, "%s", claims.first_refusal);
    CHECK(claims.count == 4);
    static const claim_verdict expected[] = {CLAIM_REPRODUCED, CLAIM_NO_VISIBLE_DIFFERENCE, CLAIM_LIMITATION_MEASURED,
                                             CLAIM_FAILS_GTLAB_SETTING};
    if (claims.count == 4)
        check_verdicts(&claims, 0, expected, 4);
    for (int i = 0; i < claims.count; ++i)
        CHECK_MSG(!strcmp(claims.rows[i].record.seed, "000"), "row %d: seed %s", i, claims.rows[i].record.seed);
    CHECK(claims.rows[0].figure == -0.17 && claims.rows[3].figure == 0.05); /* with minus without */
    section_test_end(&t);
    return check_report("sphere_light_claims");
}
