/* report/dither_section and report/bloom_section from made-up results (they
 * run nothing): the summary carries the rows' fields, the claims rows take
 * their figures from the right rows and judge them (a TPDF amplitude of 0
 * reproduces signal independence, the as-written average's 1.1 refutes it;
 * 0.083 reproduces the bloom's 0.08, 0.2 refutes it). */
#include <string.h>
#include <sys/stat.h>

#include "report/bloom_section.h"
#include "report/dither_section.h"
#include "tests/check.h"
#include "tests/report/claim_region_verdict.h"

static void made_up_dither(dither_result *r)
{
    static const char *const labels[] = {"none", "white rpdf", "blue tpdf-remap", "white tpdf-remap",
                                         "white tpdf-average (as written)", "blue rpdf (as written)"};
    static const double amplitude[] = {0.0, 1.0, 0.01, 0.02, 1.1, -0.9};
    memset(r, 0, sizeof *r);
    for (int i = 0; i < DITHER_IMAGES; ++i) {
        r->images[i].image_name = i ? "sphere light" : "gradient";
        r->images[i].row_count = 6;
        for (int k = 0; k < 6; ++k) {
            dither_row *w = &r->images[i].rows[k];
            snprintf(w->label, sizeof w->label, "%s", labels[k]);
            w->modulation_amplitude = amplitude[k], w->modulation_amplitude_se = 0.01;
            w->dssim_blurred = k == 2 ? 1e-5 : 2e-5, w->longest_run = 20 - k, w->bias = k == 5 ? 0.5 : 0.0;
        }
    }
    for (int k = 0; k < DITHER_SMALL_FLOAT_ROWS; ++k)
        r->small_float[k].kind = "tpdf-sum";
}

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

int main(void)
{
    char dir[2048];
    snprintf(dir, sizeof dir, "%s/inside_sections_output", check_tmp_dir());
    mkdir(dir, 0755);
    static dither_result d;
    static bloom_result b, bad;
    static claims_table claims;
    made_up_dither(&d);
    made_up_bloom(&b, 0.083);
    made_up_bloom(&bad, 0.2);
    report doc;
    report_init(&doc, "test");
    report_context ctx = {{dir, QUALITY_PREVIEW, 1, NULL, NULL}, &doc, cJSON_CreateObject(), &claims};
    gt_error e;
    CHECK(dither_section(&ctx, &d, &e) == 0 && bloom_section(&ctx, &b, &e) == 0 && bloom_section(&ctx, &bad, &e) == 0);
    CHECK(claims.count == 4 + 3 + 3);
    CHECK(claim_region_verdict(&claims.rows[0]) == CLAIM_REPRODUCED && claims.rows[0].figure == 0.01);
    CHECK(claim_region_verdict(&claims.rows[1]) == CLAIM_REPRODUCED && claims.rows[1].figure == 1.0);
    CHECK(claim_region_verdict(&claims.rows[2]) == CLAIM_REFUTED && claims.rows[2].figure == 1.1);
    CHECK(claim_region_verdict(&claims.rows[3]) == CLAIM_REPRODUCED && claims.rows[3].figure == 0.5);
    CHECK(claim_region_verdict(&claims.rows[4]) == CLAIM_REPRODUCED && claim_region_verdict(&claims.rows[7]) == CLAIM_REFUTED);
    CHECK(claims.rows[5].figure == 0.06 / 0.005 && claim_region_verdict(&claims.rows[6]) == CLAIM_REPRODUCED);
    const cJSON *dither = cJSON_GetObjectItem(ctx.summary, "dither");
    const cJSON *gradient = cJSON_GetObjectItem(dither, "gradient");
    CHECK(cJSON_GetArraySize(gradient) == 6);
    const cJSON *first = cJSON_GetArrayItem(gradient, 1);
    CHECK(cJSON_GetObjectItem(first, "modulation_amplitude")->valuedouble == 1.0);
    CHECK(cJSON_GetObjectItem(first, "longest_run")->valueint == 19);
    const cJSON *bloom = cJSON_GetObjectItem(ctx.summary, "bloom");
    CHECK(cJSON_GetArraySize(cJSON_GetObjectItem(bloom, "fits")) == BLOOM_FITS);
    report_free(&doc);
    cJSON_Delete(ctx.summary);
    return check_report("test_inside_sections");
}
