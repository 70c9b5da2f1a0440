/* ao_decals_section from a made-up result (it runs nothing): the claims rows
 * take their figures from the right fields and judge them under their
 * records. */
#include <string.h>

#include "ao_decals/ao_decals_section.h"
#include "tests/check.h"
#include "tests/section_test.h"

/* The AO decals' rows: Quilez against the exact sphere within a code value
 * (1e-7) reproduces, 0.01 refutes; the point decal's exponent is a
 * limitation measured whatever its figure. */
static void check_ao_decals(report_context *base)
{
    static ao_decals_result r;
    static claims_table claims;
    report_context ctx = *base;
    ctx.claims = &claims, ctx.summary = cJSON_CreateObject();
    gt_error e;
    memset(&r, 0, sizeof r);
    for (int k = 0; k < AO_DECAL_VARIANTS; ++k)
        r.rows[k].variant = "made up";
    r.fit.params[AO_DECAL_SHAPE] = 0.4, r.fit.standard_errors[AO_DECAL_SHAPE] = 0.01;
    r.quilez_exact_worst[0] = 1e-7, r.quilez_exact_worst[1] = 2e-7;
    CHECK(ao_decals_section(&ctx, &r, &e) == 0);
    r.quilez_exact_worst[1] = 0.01;
    CHECK(ao_decals_section(&ctx, &r, &e) == 0);
    CHECK(claims.count == 4 && claims.refused == 0);
    CHECK(claims.rows[0].figure == 2e-7 && claims.rows[0].verdict == CLAIM_REPRODUCED);
    CHECK(claims.rows[2].figure == 0.01 && claims.rows[2].verdict == CLAIM_REFUTED);
    CHECK(claims.rows[1].figure == 0.4 && claims.rows[1].verdict == CLAIM_LIMITATION_MEASURED);
    cJSON_Delete(ctx.summary);
}

int main(void)
{
    static section_test t;
    section_test_begin(&t, "ao_decals_section_output", NULL);
    check_ao_decals(&t.ctx);
    section_test_end(&t);
    return check_report("test_ao_decals_section");
}
