/* The multi-bounce section from a made-up result (no study runs): it adds
 * one claims-table row per measured item of issue 25 (items 1 to 5), each
 * figure and standard error the struct's own and each verdict the one its
 * figures give, and the items' objects to summary.json. */
#include "report/multibounce_section.h"
#include "tests/check.h"
#include "tests/report/claim_region_verdict.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

static multibounce_study_result made_up(void)
{
    static multibounce_study_result r;
    memset(&r, 0, sizeof r);
    r.albedo_count = 1;
    r.validation_mean.noise_floor_rmse = 0.02;
    r.validation_mean.dssim_talk = 0.05;
    r.clamp.heldout_count = 2;
    r.clamp.heldout_mean_difference = 0.002, r.clamp.heldout_difference_se = 0.001;   /* reproduced */
    r.bounce_counts.four_minus_best_other = -0.01, r.bounce_counts.four_minus_best_other_se = 0.02; /* n.s. */
    r.bounce_counts.best_other = 1;
    r.gtao_input.rows[1].difference = 0.14, r.gtao_input.rows[1].difference_se = 0.03; /* refuted */
    r.contrast.count = 1;
    r.contrast.premise_cost = 0.075, r.contrast.premise_cost_se = 0.04;  /* n.s.: 0.075 - 1.96 * 0.04 < 0.02 */
    r.colour.mean_dssim_luminance = 0.01, r.colour.mean_dssim_luminance_se = 0.005; /* reproduced */
    return r;
}

int main(void)
{
    char dir[2048];
    snprintf(dir, sizeof dir, "%s/multibounce_claims_output", check_tmp_dir());
    mkdir(dir, 0755);
    multibounce_study_result r = made_up();
    static claims_table claims;
    report doc;
    report_init(&doc, "test");
    report_context ctx = {{dir, QUALITY_PREVIEW, 1, NULL, NULL}, &doc, cJSON_CreateObject(), &claims};
    gt_error e;
    CHECK(multibounce_section(&ctx, &r, &e) == 0);
    CHECK(claims.count == 5);
    const double figures[5] = {0.002, -0.01, 0.14, 0.075, 0.01};
    const claim_verdict verdicts[5] = {CLAIM_REPRODUCED, CLAIM_NOT_SIGNIFICANT, CLAIM_REFUTED,
                                       CLAIM_NOT_SIGNIFICANT, CLAIM_REPRODUCED};
    for (int i = 0; i < claims.count && i < 5; ++i) {
        CHECK_MSG(claims.rows[i].figure == figures[i], "claim %d: figure %g", i, claims.rows[i].figure);
        claim_verdict v = claim_region_verdict(&claims.rows[i]);
        CHECK_MSG(v == verdicts[i], "claim %d: %s", i, claim_verdict_name(v));
    }
    const cJSON *mb = cJSON_GetObjectItemCaseSensitive(ctx.summary, "multibounce");
    const char *const members[] = {"clamp", "bounce_counts", "gtao_input", "contrast", "colour"};
    for (int i = 0; i < 5; ++i)
        CHECK_MSG(cJSON_GetObjectItemCaseSensitive(mb, members[i]) != NULL, "no %s", members[i]);
    report_free(&doc);
    cJSON_Delete(ctx.summary);
    return check_report("test_multibounce_claims");
}
