/* The anti-aliasing claim rows of the Decima talk (transcript 000) from
 * made-up results (no study runs), the verdict following the record's form,
 * margin and setting (docs/claims-protocol.md): settle 0.5 of a code value
 * on a still camera is final (reproduced), a flicker 0.1 below no AA's is
 * calmer (reproduced), an RMSE gap of 0.001 is no visible difference, a
 * ghosting gap whose interval crosses the margin is not significant, and a
 * checkerboard at 2x flickering 0.02 more than the TAA fails under gtlab's
 * setting. */
#include <string.h>

#include "anti_aliasing/aa_temporal_section.h"
#include "tests/check.h"

static aa_temporal_result made_up_aa(void)
{
    static aa_temporal_result r;
    memset(&r, 0, sizeof r);
    r.request = aa_temporal_default_request(QUALITY_PREVIEW);
    r.row_count = AA_T_PATHS * AA_T_ROWS, r.truth_count = AA_T_PATHS;
    for (int p = 0; p < AA_T_PATHS; ++p) {
        r.truth[p].scene = r.request.scenes[0], r.truth[p].path = aa_temporal_path_names[p];
        for (int t = 0; t < AA_T_ROWS; ++t) {
            aa_temporal_row *x = &r.rows[p * AA_T_ROWS + t];
            x->scene = r.request.scenes[0], x->path = aa_temporal_path_names[p];
            x->technique = aa_temporal_technique_names[t];
            x->dssim = 0.1 + 0.01 * t, x->frames = 8;
            for (int u = 0; u < AA_T_ROWS; ++u)
                x->dssim_minus[u] = (cluster_mean){0.01 * (t - u), 0.001, 100, 20};
        }
    }
    enum { EDGE = 3 };
    r.rows[EDGE].settle = 0.5 / 255.0;
    aa_temporal_row *edge = &r.rows[AA_T_ROWS + EDGE], *two = &r.rows[AA_T_ROWS + AA_T_CHECKER_2X];
    edge->flicker_minus[0] = (cluster_mean){-0.1, 0.004, 19200, 300};
    edge->rmse_minus[1] = (cluster_mean){-0.001, 0.0005, 19200, 300};
    edge->ghost_minus[2] = (cluster_mean){-0.013, 0.0053, 400, 60};
    two->flicker_minus[EDGE] = (cluster_mean){0.02, 0.001, 19200, 300};
    return r;
}

int main(void)
{
    static claims_table claims;
    report doc;
    report_init(&doc, "test");
    report_context ctx = {{check_tmp_dir(), QUALITY_PREVIEW, 1, NULL, NULL, 0}, &doc, cJSON_CreateObject(), &claims};
    aa_temporal_result aa = made_up_aa();
    aa_temporal_section(&ctx, ctx.summary, &aa);
    gt_error e;
    CHECK_MSG(claims_table_check(&claims, &e) == 0, "%s", claims.first_refusal);
    CHECK(claims.count == 5);
    static const claim_verdict expected[] = {CLAIM_REPRODUCED, CLAIM_REPRODUCED, CLAIM_NO_VISIBLE_DIFFERENCE,
                                             CLAIM_NOT_SIGNIFICANT, CLAIM_FAILS_GTLAB_SETTING};
    for (int i = 0; i < claims.count && i < 5; ++i)
        CHECK_MSG(claims.rows[i].verdict == expected[i] && !strcmp(claims.rows[i].record.seed, "000"),
                  "row %d: %s (%g +- %g)", i, claims.rows[i].verdict_name, claims.rows[i].figure,
                  claims.rows[i].standard_error);
    cJSON_Delete(ctx.summary);
    report_free(&doc);
    return check_report("test_aa_temporal_section");
}
