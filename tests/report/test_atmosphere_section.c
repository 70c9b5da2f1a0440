/* The atmosphere LUTs' section (report/atmosphere_section.c) from a results
 * struct made up here (no study runs): summary.json carries the rows' fields
 * exactly, and the claims table gets two rows for the in-scatter table at the
 * talk's size (all points, daytime points) whose verdict follows the 2%
 * tolerance (or the quadrature's floor, when larger): 0.5 refuted, 0.005
 * reproduced; none for the sun and sky tables, whose one altitude the talk
 * takes at a representative position (not the setting scored here). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "core/atomic_file.h"
#include "report/atmosphere_section.h"
#include "tests/check.h"
#include "tests/report/claim_region_verdict.h"

static atmosphere_luts_result made_up(void)
{
    static const double total[3] = {0.5, 0.01, 0.03}, quadrature[3] = {1e-3, 1e-4, 0.04};
    atmosphere_luts_result r;
    memset(&r, 0, sizeof r);
    r.request = atmosphere_luts_default_request(QUALITY_PREVIEW);
    r.row_count = 3;
    for (int t = 0; t < 3; ++t) {
        atmosphere_luts_row *x = &r.rows[t];
        snprintf(x->label, sizeof x->label, "talk");
        x->table = t, x->talk = 1, x->bytes = t == 0 ? 131072 : 4096;
        x->error.total.p95 = total[t], x->error.quadrature.p95 = quadrature[t];
        x->error.interpolation.p95 = total[t] * 0.999, x->error.interpolation.max = 1.0 / 3.0;
        x->error.day_total.p95 = total[t] / 100.0;
        r.talk_row[t] = t, r.smallest_within[t] = t == 0 ? -1 : t;
    }
    return r;
}

int main(void)
{
    char dir[2048], luts[2100];
    gt_error e;
    snprintf(dir, sizeof dir, "%s/atmosphere_section_output", check_tmp_dir());
    snprintf(luts, sizeof luts, "%s/luts", dir);
    mkdir(dir, 0755), mkdir(luts, 0755);
    snprintf(luts, sizeof luts, "%s/luts/atmosphere_sizes.dat", dir);
    CHECK(atomic_write_text(luts, "0 131072 0.5 0.9 0.001 0.5 \"talk\"\n1 4096 0.01 0.02 0.0001 0.01 \"talk\"\n", &e) == 0);
    atmosphere_luts_result r = made_up();
    report doc;
    claims_table claims = {0};
    report_init(&doc, "test");
    report_context ctx = {{dir, QUALITY_PREVIEW, 1, NULL, NULL}, &doc, cJSON_CreateObject(), &claims};
    CHECK(atmosphere_section(&ctx, &r, &e) == 0);
    const cJSON *rows = cJSON_GetObjectItem(cJSON_GetObjectItem(ctx.summary, "atmosphere_luts"), "sizes");
    CHECK(cJSON_GetArraySize(rows) == 3);
    CHECK(cJSON_GetNumberValue(cJSON_GetObjectItem(cJSON_GetArrayItem(rows, 0), "interpolation_max")) == 1.0 / 3.0);
    CHECK(claims.count == 2); /* in-scatter: all points, then the daytime ones */
    CHECK(claims.count == 2 && claim_region_verdict(&claims.rows[0]) == CLAIM_REFUTED && claim_region_verdict(&claims.rows[1]) == CLAIM_REPRODUCED);
    cJSON_Delete(ctx.summary);
    report_free(&doc);
    return check_report("test_atmosphere_section");
}
