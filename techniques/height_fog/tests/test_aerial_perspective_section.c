/* The combination images' part of the height fog's section
 * (height_fog/aerial_perspective_section.c) from a results struct made up here
 * (no study runs): summary.json carries the cases in "views" and
 * "fisheyes" exactly, its figure is the largest median relative error of
 * the published combination over the cases, and no claims row is added
 * (the talk's "realistic" is not a numeric claim). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "height_fog/aerial_perspective_section.h"
#include "report/claims_table.h"
#include "tests/check.h"

static aerial_perspective_result made_up(double worst_median)
{
    aerial_perspective_result r;
    memset(&r, 0, sizeof r);
    r.request = aerial_perspective_default_request(QUALITY_PREVIEW);
    r.case_count = 2;
    for (int i = 0; i < 2; ++i) {
        aerial_case *c = &r.cases[i];
        snprintf(c->weather, sizeof c->weather, "%s", i ? "dense" : "sunny");
        c->sun_elevation_deg = 20.0;
        c->median_relative_view[AERIAL_MODEL_PUBLISHED] = i ? worst_median : worst_median / 3.0;
        c->median_relative_view[AERIAL_MODEL_SKY_ATTENUATED] = 0.9; /* not the claim's model */
        c->rmse_fisheye = 1.0 / 3.0;
    }
    return r;
}

static void check_section(double worst_median)
{
    aerial_perspective_result r = made_up(worst_median);
    report doc;
    claims_table claims = {0};
    report_init(&doc, "test");
    report_context ctx = {{check_tmp_dir(), QUALITY_PREVIEW, 1, NULL, NULL, 0}, &doc, cJSON_CreateObject(), &claims};
    aerial_perspective_section(&ctx, ctx.summary, "fog", &r);
    const cJSON *a = cJSON_GetObjectItem(ctx.summary, "aerial_perspective");
    CHECK(cJSON_GetArraySize(cJSON_GetObjectItem(a, "views")) == 2);
    const cJSON *fisheye = cJSON_GetArrayItem(cJSON_GetObjectItem(a, "fisheyes"), 1);
    CHECK(cJSON_GetNumberValue(cJSON_GetObjectItem(fisheye, "rmse_fisheye")) == 1.0 / 3.0);
    CHECK(cJSON_GetNumberValue(cJSON_GetObjectItem(a, "worst_median_relative_view")) == worst_median);
    CHECK(claims.count == 0);
    cJSON_Delete(ctx.summary);
    report_free(&doc);
}

int main(void)
{
    check_section(0.15);
    check_section(0.01);
    return check_report("test_aerial_perspective_section");
}
