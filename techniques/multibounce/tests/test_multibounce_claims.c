/* The multi-bounce section from a made-up result (no study runs): it adds
 * one claim record per measured item of issue 25 (items 1 to 5; issue 42's
 * protocol), each figure and standard error the struct's own and each
 * verdict the one its record gives those figures (and other figures the
 * verdict they must give: the tests can fail), none refused; GTAO's V_d,
 * not ground truth, adds no row; and the items' objects to summary.json. */
#include "multibounce/multibounce_section.h"
#include "report/claim_thresholds.h"
#include "tests/check.h"

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
    /* as good, within a code value (1/255 = 0.0039): 0.001 + 1.96 x 0.001 < 0.0039 */
    r.clamp.heldout_mean_difference = 0.001, r.clamp.heldout_difference_se = 0.001;
    /* 4 bounces closest? -0.01 +- 1.96 x 0.02 straddles -0.0039: not significant */
    r.bounce_counts.four_minus_best_other = -0.01, r.bounce_counts.four_minus_best_other_se = 0.02;
    r.bounce_counts.best_other = 1;
    /* agnostic: 0.001 +- 1.96 x 0.0005 within +-0.0039 */
    r.gtao_input.agnostic.difference = 0.001, r.gtao_input.agnostic.difference_se = 0.0005;
    r.gtao_input.rows[1].difference = 0.14, r.gtao_input.rows[1].difference_se = 0.03; /* no row: not ground truth */
    r.contrast.count = 1;
    r.contrast.premise_cost = 0.075, r.contrast.premise_cost_se = 0.04; /* an assumption: no verdict */
    /* colour minus grey DSSIM 0.01 - 0.05 = -0.04, below the just-noticeable 0.025 */
    r.colour.mean_dssim_luminance = 0.01, r.colour.mean_dssim_luminance_se = 0.005;
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
    report_context ctx = {{dir, QUALITY_PREVIEW, 1, NULL, NULL, 0}, &doc, cJSON_CreateObject(), &claims};
    gt_error e;
    CHECK(multibounce_section(&ctx, &r, &e) == 0);
    CHECK(claims.count == 5 && claims.refused == 0);
    const double figures[5] = {0.001, -0.01, 0.001, 0.075, 0.01 - 0.05};
    const claim_verdict verdicts[5] = {CLAIM_REPRODUCED, CLAIM_NOT_SIGNIFICANT, CLAIM_REPRODUCED,
                                       CLAIM_LIMITATION_MEASURED, CLAIM_REPRODUCED};
    for (int i = 0; i < claims.count && i < 5; ++i) {
        CHECK_MSG(fabs(claims.rows[i].figure - figures[i]) < 1e-15, "claim %d: figure %g", i, claims.rows[i].figure);
        CHECK_MSG(claims.rows[i].verdict == verdicts[i], "claim %d: %s", i, claims.rows[i].verdict_name);
    }
    if (claims.count == 5) {
        /* the clamp 0.01 +- 0.001 above a code value: refuted, but in gtlab's scenes */
        CHECK(claim_verdict_of(&claims.rows[0].record, 0.01, 0.001) == CLAIM_FAILS_GTLAB_SETTING);
        /* 4 bounces closer by 0.02 +- 0.005: reproduced; 0.001 +- 0.0005: no visible difference */
        CHECK(claim_verdict_of(&claims.rows[1].record, -0.02, 0.005) == CLAIM_REPRODUCED);
        CHECK(claim_verdict_of(&claims.rows[1].record, 0.001, 0.0005) == CLAIM_NO_VISIBLE_DIFFERENCE);
        /* agnostic: the two sources' errors (each against its own world's truth) 2 code values apart,
         * either way, fails (in gtlab's scenes); -0.006 +- 0.0028 (the preview's figures) straddles
         * -0.0039: not significant */
        CHECK(claim_verdict_of(&claims.rows[2].record, 2.0 * CLAIM_ONE_CODE_VALUE_8BIT, 1e-4) ==
              CLAIM_FAILS_GTLAB_SETTING);
        CHECK(claim_verdict_of(&claims.rows[2].record, -2.0 * CLAIM_ONE_CODE_VALUE_8BIT, 1e-4) ==
              CLAIM_FAILS_GTLAB_SETTING);
        CHECK(claim_verdict_of(&claims.rows[2].record, -0.006, 0.0028) == CLAIM_NOT_SIGNIFICANT);
        CHECK(strstr(claims.rows[2].record.setting_note, "its own world") != NULL);
        /* the premise never gets a verdict */
        CHECK(claim_verdict_of(&claims.rows[3].record, 1.0, 0.0) == CLAIM_LIMITATION_MEASURED);
        /* colour 0.1 +- 0.01 worse than grey: fails, in gtlab's scenes */
        CHECK(claim_verdict_of(&claims.rows[4].record, 0.1, 0.01) == CLAIM_FAILS_GTLAB_SETTING);
    }
    const cJSON *mb = cJSON_GetObjectItemCaseSensitive(ctx.summary, "multibounce");
    const char *const members[] = {"clamp", "bounce_counts", "agnostic", "gtao_input", "contrast", "colour"};
    for (int i = 0; i < 6; ++i)
        CHECK_MSG(cJSON_GetObjectItemCaseSensitive(mb, members[i]) != NULL, "no %s", members[i]);
    report_free(&doc);
    cJSON_Delete(ctx.summary);
    return check_report("multibounce_claims");
}
