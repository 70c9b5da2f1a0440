/* INSIDE's volumetric-light section from a made-up result (it runs
 * nothing): the claims rows take their figures from the right fields and
 * judge them under their records (dithering's, bloom's and the AO decals':
 * techniques/dither/, techniques/bloom/, techniques/ao_decals/). */
#include <string.h>
#include <sys/stat.h>

#include "report/vlight_section.h"
#include "tests/check.h"
#include "tests/section_test.h"

/* The volumetric rows: blue 0.05 below white (past the 1% margin)
 * reproduces, 0.005 below is no visible difference; Bayer's and IGN's
 * structure are limitations measured; the talk's configuration 0.05 DSSIM
 * below uniform reproduces, 0.05 above fails under gtlab's setting (not the
 * talk's scene). */
static void check_vlight(report_context *base)
{
    static vlight_result r;
    static claims_table claims;
    report_context ctx = *base;
    ctx.claims = &claims, ctx.summary = cJSON_CreateObject();
    char path[2200];
    snprintf(path, sizeof path, "%s/%s", base->study.output_dir, VLIGHT_DIR);
    mkdir(path, 0755);
    snprintf(path, sizeof path, "%s/%s/error_vs_spp.dat", base->study.output_dir, VLIGHT_DIR);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f)
        return;
    fprintf(f, "1 1 1 1 1 1 1 1 1 1 1\n3 .5 .5 .5 .5 .5 .5 .5 .5 .5 .5\n");
    fclose(f);
    gt_error e;
    memset(&r, 0, sizeof r);
    r.request = vlight_default_request(QUALITY_PREVIEW);
    r.uniform128.rmse = 0.001;
    r.blue_blurred_gap[RAYMARCH_NOISE_WHITE] = -0.05, r.blue_blurred_gap_se[RAYMARCH_NOISE_WHITE] = 0.005;
    r.peak_over_blue[RAYMARCH_NOISE_BAYER] = 30, r.peak_over_blue[RAYMARCH_NOISE_IGN] = 20;
    r.cost_dssim_gap = -0.05, r.cost_dssim_gap_se = 0.005;
    CHECK(vlight_section(&ctx, &r, &e) == 0);
    r.blue_blurred_gap[RAYMARCH_NOISE_WHITE] = -0.005, r.blue_blurred_gap_se[RAYMARCH_NOISE_WHITE] = 0.001;
    r.cost_dssim_gap = 0.05;
    CHECK(vlight_section(&ctx, &r, &e) == 0);
    CHECK(claims.count == 8 && claims.refused == 0);
    check_verdicts(&claims, 0,
                   (const claim_verdict[]){CLAIM_REPRODUCED, CLAIM_LIMITATION_MEASURED, CLAIM_LIMITATION_MEASURED,
                                           CLAIM_REPRODUCED, CLAIM_NO_VISIBLE_DIFFERENCE, CLAIM_LIMITATION_MEASURED,
                                           CLAIM_LIMITATION_MEASURED, CLAIM_FAILS_GTLAB_SETTING},
                   8);
    CHECK(claims.rows[1].figure == 30 && claims.rows[2].figure == 20 && claims.rows[3].figure == -0.05);
    cJSON_Delete(ctx.summary);
}

int main(void)
{
    static section_test t;
    section_test_begin(&t, "inside_sections_output", NULL);
    check_vlight(&t.ctx);
    section_test_end(&t);
    return check_report("test_inside_sections");
}
