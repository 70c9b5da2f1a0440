/* The dither study's numbers without the report's prose, at small sizes:
 * rows in the published order, then the 10-bit target's (TPDF variance
 * 1/4 LSB^2, unbiased, unmodulated; RPDF modulation 1); TPDF rows have error variance 1/4 and
 * a modulation amplitude within 5 of its standard errors of 0 on the
 * gradient, RPDF rows near 1; no-dither has the longest runs; the talk's
 * tex / 255 into a rounding target is biased by +1/2 LSB; R11G11B10 TPDF
 * variance 1/4 +- 0.03 with no bias, undithered biased; the blue-noise files
 * exist and the texture is blue (low rings below a tenth of white's). */
#include <stdlib.h>
#include <string.h>

#include "dither/dither_study.h"
#include "tests/check.h"
#include "tests/test_files.h"

static const dither_row *row_of(const dither_image_result *im, const char *label)
{
    for (int k = 0; k < im->row_count; ++k)
        if (strcmp(im->rows[k].label, label) == 0)
            return &im->rows[k];
    return NULL;
}

static void check_dither(const char *dir)
{
    study_context ctx = {dir, QUALITY_PREVIEW, 2, NULL, NULL, 0};
    dither_request rq = {512, 64, 48, 32, 4, 16, 1};
    static dither_result r;
    gt_error e;
    char path[4096];
    CHECK_MSG(dither_study(&ctx, &rq, &r, &e) == 0, "%s", e.message);
    const dither_image_result *g = &r.images[0];
    CHECK(g->row_count == 14 && strcmp(g->rows[0].label, "none") == 0);
    /* 10-bit: TPDF variance 1/4 LSB^2 without modulation, RPDF's modulation 1 */
    const dither_row *none10 = row_of(g, "none, 10-bit"), *rpdf10 = row_of(g, "blue rpdf, 10-bit"),
                     *tpdf10 = row_of(g, "blue tpdf-remap, 10-bit");
    CHECK(none10 && rpdf10 && tpdf10);
    if (none10 && rpdf10 && tpdf10) {
        CHECK_NEAR(tpdf10->variance, 0.25, 0.01);
        CHECK(fabs(tpdf10->bias) < 0.01 && fabs(rpdf10->bias) < 0.01);
        CHECK(fabs(tpdf10->modulation_amplitude) < 5 * tpdf10->modulation_amplitude_se + 0.03);
        CHECK_MSG(fabs(rpdf10->modulation_amplitude - 1.0) < 0.1, "a %g", rpdf10->modulation_amplitude);
        /* undithered 10-bit runs are a quarter of 8-bit's (4x the levels over the gradient) */
        CHECK_MSG(abs(4 * none10->longest_run - g->rows[0].longest_run) <= 4, "runs %d, 8-bit %d", none10->longest_run,
                  g->rows[0].longest_run);
    }
    for (int p = 0; p < DITHER_PATTERN_COUNT; ++p) {
        const dither_row *rp = &g->rows[1 + 2 * p], *tp = &g->rows[2 + 2 * p];
        CHECK_NEAR(tp->variance, 0.25, 0.01);
        CHECK_MSG(fabs(tp->modulation_amplitude) < 5 * tp->modulation_amplitude_se + 0.03, "%s a %g se %g", tp->label,
                  tp->modulation_amplitude, tp->modulation_amplitude_se);
        CHECK_MSG(fabs(rp->modulation_amplitude - 1.0) < 0.1, "%s a %g", rp->label, rp->modulation_amplitude);
        CHECK(g->rows[0].longest_run > tp->longest_run);
    }
    const dither_row *written = row_of(g, "blue rpdf (as written)");
    CHECK(written && fabs(written->bias - 0.5) < 0.02);
    CHECK(fabs(r.small_float[2].best_variance - 0.25) < 0.03 && fabs(r.small_float[2].worst_variance - 0.25) < 0.03);
    CHECK(r.small_float[2].worst_bias < 0.03 && r.small_float[0].worst_bias > 0.4);
    CHECK(r.blue_low_ring_power < 0.1 && r.blue_high_ring_power > 0.9);
    snprintf(path, sizeof path, "%s/%s/blue_noise_16.exr", dir, DITHER_DIR);
    CHECK(file_exists(path));
}

int main(void)
{
    char dir[2048];
    gt_error e;
    study_context top = {check_tmp_dir(), QUALITY_PREVIEW, 2, NULL, NULL, 0};
    CHECK(study_make_dir(&top, "dither_study", dir, sizeof dir, &e) == 0);
    check_dither(dir);
    return check_report("test_dither_study");
}
