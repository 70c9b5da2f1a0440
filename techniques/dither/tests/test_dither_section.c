/* dither_section from made-up results (it runs nothing): the summary carries
 * the rows' fields, the claims rows take their figures from the right rows
 * and judge them under their records: a TPDF modulation of 0.01 reproduces
 * signal independence and 0.9 refutes it; RPDF's 1 reproduces its
 * modulation and 0.2 refutes it; the transcribed average's 1.1 fails the
 * stronger reading; blue and white DSSIMs 1e-5 apart are no visible
 * difference, 0.04 apart a reproduction. */
#include <math.h>
#include <string.h>

#include "dither/dither_section.h"
#include "tests/check.h"
#include "tests/section_test.h"

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

int main(void)
{
    static dither_result d, worse;
    static claims_table claims;
    static section_test t;
    made_up_dither(&d);
    made_up_dither(&worse); /* the TPDF modulated as much as RPDF, blue visibly ahead of white */
    worse.images[0].rows[2].modulation_amplitude = 0.9, worse.images[0].rows[1].modulation_amplitude = 0.2;
    worse.images[1].rows[2].dssim_blurred = 0.01, worse.images[1].rows[3].dssim_blurred = 0.05;
    section_test_begin(&t, "dither_section_output", &claims);
    report_context *ctx = &t.ctx;
    gt_error e;
    CHECK(dither_section(ctx, &d, &e) == 0);
    CHECK(dither_section(ctx, &worse, &e) == 0);
    CHECK(claims.count == 4 + 4 && claims.refused == 0);
    CHECK(claims.rows[0].figure == 0.01 && claims.rows[1].figure == 1.0 && claims.rows[2].figure == 1.1);
    CHECK(fabs(claims.rows[3].figure - (1e-5 - 2e-5)) < 1e-15);
    /* TPDF independent, RPDF modulated, (rand + rand) / 2 fails the stronger reading, blue and white DSSIMs
     * 1e-5 apart: no visible difference */
    check_verdicts(&claims, 0,
                   (const claim_verdict[]){CLAIM_REPRODUCED, CLAIM_REPRODUCED, CLAIM_FAILS_STRONGER_READING,
                                           CLAIM_NO_VISIBLE_DIFFERENCE},
                   4);
    check_verdicts(&claims, 4,
                   (const claim_verdict[]){CLAIM_REFUTED, CLAIM_REFUTED, CLAIM_FAILS_STRONGER_READING,
                                           CLAIM_REPRODUCED},
                   4);
    const cJSON *dither = cJSON_GetObjectItem(ctx->summary, "dither");
    const cJSON *gradient = cJSON_GetObjectItem(dither, "gradient");
    CHECK(cJSON_GetArraySize(gradient) == 6);
    const cJSON *first = cJSON_GetArrayItem(gradient, 1);
    CHECK(cJSON_GetObjectItem(first, "modulation_amplitude")->valuedouble == 1.0);
    CHECK(cJSON_GetObjectItem(first, "longest_run")->valueint == 19);
    section_test_end(&t);
    return check_report("test_dither_section");
}
