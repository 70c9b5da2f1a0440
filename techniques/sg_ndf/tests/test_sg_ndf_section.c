/* The SG NDF claim row from made-up results (no study runs): the verdict
 * its made-up figures must give under its record (docs/claims-protocol.md). */
#include "sg_ndf/sg_ndf_section.h"
#include "tests/check.h"

#include <string.h>

/* SG NDF: a Ward 7-lobe E below 1% reproduces; above it gives no row (a
 * local optimum bounds the best error from above only); GGX gives none. */
static void sg_rows(void)
{
    static sg_ndf_result r;
    memset(&r, 0, sizeof r);
    r.request.material_count = 3;
    const double e7[3] = {0.003, 0.05, 0.001};
    for (int i = 0; i < 3; ++i) {
        r.materials[i].ndf.kind = i == 2 ? NDF_GGX : NDF_WARD;
        r.materials[i].fitted = 9;
        r.materials[i].fits[6].l2_error = e7[i];
    }
    static claims_table t;
    memset(&t, 0, sizeof t);
    report doc;
    report_init(&doc, "test");
    report_context ctx = {{check_tmp_dir(), QUALITY_PREVIEW, 1, NULL, NULL, 0}, &doc, NULL, &t};
    sg_ndf_claim_rows(&ctx, &r);
    CHECK_MSG(t.refused == 0, "refused: %s", t.first_refusal);
    CHECK_MSG(t.count == 1, "%d rows", t.count);
    CHECK_MSG(t.rows[0].verdict == CLAIM_REPRODUCED, "%s", claim_verdict_name(t.rows[0].verdict));
    CHECK(t.rows[0].figure == 0.003);
    report_free(&doc);
}

int main(void)
{
    sg_rows();
    return check_report("test_sg_ndf_section");
}
