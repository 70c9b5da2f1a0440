/* The specular-occlusion section's claim records (issue 26; issue 42's
 * protocol) from a made-up result (no study runs): the rankings and the cap
 * intersections (so_rankings_section) and the visibility cone and the
 * dropped view angle (so_cone_view_section) add one row each, none refused,
 * each figure the struct's own (the darkening's sign turned: lower is
 * better) and each verdict the one its record gives: a visible margin
 * (a just-noticeable DSSIM, one 8-bit code value) decides "better" and "no
 * visible difference", gtlab's scenes turn a refutation into "fails under
 * gtlab's setting", and the dropped view angle, gtlab's inference, is a
 * limitation measured. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "report/claim_thresholds.h"
#include "specular_occlusion/specular_occlusion_section_parts.h"
#include "tests/check.h"

enum { ROWS = 9 };

static void set(so_paired_difference *d, double mean, double se)
{
    d->mean = mean, d->standard_error = se, d->cases = 4;
}

static void made_up(so_study_result *r)
{
    memset(r, 0, sizeof *r);
    so_ranking_setting *t = &r->rankings.settings[SO_SETTING_TALK];
    t->name = "talk", t->reference = "specocc_phong.V", t->lobe = "phong";
    r->rankings.settings[SO_SETTING_GTSO].name = "gtso";
    r->rankings.settings[SO_SETTING_GTSO].reference = "specocc.V";
    r->rankings.settings[SO_SETTING_GTSO].lobe = "ggx";
    set(&t->cone_minus_ao, -0.06, 0.01);                                  /* below -0.025: reproduced */
    set(&t->cone_minus_lagarde, -0.005, 0.005);                           /* within 0.025: no visible difference */
    set(&t->lobe_minus_cone[SO_REGION_SILHOUETTE], -0.024, 0.033);        /* straddles: not significant */
    set(&t->lobe_minus_cone_bias[SO_REGION_SILHOUETTE], -0.02, 0.002);    /* darker by 5 code values: fails */
    set(&t->talk_minus_drobot[SO_STUDY_ROUGHNESSES - 1], 0.002, 0.003);   /* no visible difference */
    set(&t->talk_minus_drobot[0], 0.001, 0.001);                          /* similar: reproduced */
    r->caps_max_difference = 9e-13, r->caps_configurations = 1000;        /* equivalent: reproduced */
    set(&r->cone_view.visibility, 0.07, 0.018);                           /* 18 code values: fails */
    set(&r->cone_view.dropped, 0.03, 0.01);                               /* measured, no verdict */
}

int main(void)
{
    static so_study_result r;
    made_up(&r);
    static claims_table claims;
    report doc;
    report_init(&doc, "test");
    report_context ctx = {{check_tmp_dir(), QUALITY_PREVIEW, 1, NULL, NULL, 0}, &doc, cJSON_CreateObject(), &claims};
    so_rankings_section(&ctx, &r, ctx.summary);
    so_cone_view_section(&ctx, &r, ctx.summary);
    CHECK_MSG(claims.count == ROWS && claims.refused == 0, "%d rows, %d refused: %s", claims.count, claims.refused,
              claims.first_refusal);
    const double figures[ROWS] = {-0.06, -0.005, -0.024, 0.02, 0.002, 0.001, 9e-13, 0.07, 0.03};
    const claim_verdict verdicts[ROWS] = {
        CLAIM_REPRODUCED,        CLAIM_NO_VISIBLE_DIFFERENCE, CLAIM_NOT_SIGNIFICANT,
        CLAIM_FAILS_GTLAB_SETTING, CLAIM_NO_VISIBLE_DIFFERENCE, CLAIM_REPRODUCED,
        CLAIM_REPRODUCED,        CLAIM_FAILS_GTLAB_SETTING,   CLAIM_LIMITATION_MEASURED};
    for (int i = 0; i < claims.count && i < ROWS; ++i) {
        CHECK_MSG(fabs(claims.rows[i].figure - figures[i]) < 1e-15, "claim %d: figure %g", i, claims.rows[i].figure);
        CHECK_MSG(claims.rows[i].verdict == verdicts[i], "claim %d: %s", i, claims.rows[i].verdict_name);
    }
    if (claims.count == ROWS) {
        /* similar to Drobot at high gloss fails either way past a just-noticeable DSSIM */
        CHECK(claim_verdict_of(&claims.rows[5].record, 2.0 * CLAIM_DSSIM_JUST_NOTICEABLE, 0.001) ==
              CLAIM_FAILS_GTLAB_SETTING);
        CHECK(claim_verdict_of(&claims.rows[5].record, -2.0 * CLAIM_DSSIM_JUST_NOTICEABLE, 0.001) ==
              CLAIM_FAILS_GTLAB_SETTING);
        /* the cap formulas 1e-9 sr apart are not equivalent: refuted (no image enters) */
        CHECK(claim_verdict_of(&claims.rows[6].record, 1e-9, 0.0) == CLAIM_REFUTED);
        /* a cone within a code value of the real visibility: a very good match */
        CHECK(claim_verdict_of(&claims.rows[7].record, 0.001, 0.001) == CLAIM_REPRODUCED);
    }
    cJSON_Delete(ctx.summary);
    report_free(&doc);
    return check_report("test_specular_occlusion_claims");
}
