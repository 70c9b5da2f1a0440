/* bloom_section from made-up results (it runs nothing): the summary carries
 * the fits, the claims rows take their figures from the right rows and judge
 * them under their records. */
#include <string.h>

#include "bloom/bloom_section.h"
#include "tests/check.h"
#include "tests/section_test.h"

static void made_up_bloom(bloom_result *r, double normalised)
{
    memset(r, 0, sizeof *r);
    for (int f = 0; f < BLOOM_FITS; ++f) {
        r->targets[f].target = "made up";
        r->targets[f].worst_normalised_error = normalised;
        r->targets[f].fit.worst_error = 0.005, r->targets[f].worst_odd_mip = 0.06;
        for (int k = 0; k < BLOOM_FIT_TAPS; ++k)
            r->targets[f].fit.taps[k].w = 1.0 / 9;
    }
    r->exact_levels_1080 = 3, r->exact_levels_1088 = 6, r->level_count = 1;
    r->levels[0] = (bloom_level_result){48, 27, 1, {1e-5, 1e-6, 1e-7}, {1e-5, 1e-6, 1e-7}};
}

/* The bloom rows: 0.083 reproduces the 0.08 and 0.2 refutes it; an off-half
 * error below the half-resolution one, and 5 exact mips from 1920x1088,
 * refute those rows. */
static void check_bloom(report_context *base)
{
    static bloom_result b, bad;
    static claims_table claims;
    report_context ctx = *base;
    ctx.claims = &claims;
    made_up_bloom(&b, 0.083);
    made_up_bloom(&bad, 0.2);
    bad.targets[0].worst_odd_mip = 0.004, bad.exact_levels_1088 = 5;
    gt_error e;
    CHECK(bloom_section(&ctx, &b, &e) == 0 && bloom_section(&ctx, &bad, &e) == 0);
    CHECK(claims.count == 3 + 3 && claims.refused == 0);
    CHECK(claims.rows[1].figure == 0.06 / 0.005 && claims.rows[2].figure == 63);
    check_verdicts(&claims, 0, (const claim_verdict[]){CLAIM_REPRODUCED, CLAIM_REPRODUCED, CLAIM_REPRODUCED}, 3);
    check_verdicts(&claims, 3, (const claim_verdict[]){CLAIM_REFUTED, CLAIM_REFUTED, CLAIM_REFUTED}, 3);
    const cJSON *bloom = cJSON_GetObjectItem(ctx.summary, "bloom");
    CHECK(cJSON_GetArraySize(cJSON_GetObjectItem(bloom, "fits")) == BLOOM_FITS);
}

int main(void)
{
    static section_test t;
    section_test_begin(&t, "bloom_section_output", NULL);
    check_bloom(&t.ctx);
    section_test_end(&t);
    return check_report("test_bloom_section");
}
