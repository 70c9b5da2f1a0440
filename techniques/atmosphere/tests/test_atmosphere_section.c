/* The atmosphere LUTs' section (atmosphere/atmosphere_section.c) from a results
 * struct made up here (no study runs): summary.json carries the rows' fields
 * exactly, and the claims table gets two rows for the sky through the
 * in-scatter table at the talk's size under Yusov's parametrization (day,
 * twilight), judged against one sRGB code value (1.7%): a day figure of
 * 0.5% +- 0.1% is reproduced, a twilight figure of 8% +- 1% fails, under
 * gtlab's setting (the talk states neither altitude range nor atmospheres),
 * and a figure straddling 1.7% is not significant; none from the linear or
 * Bruneton rows, nor for the sun and sky tables, whose one altitude the talk
 * takes at a representative position (not the setting scored here). The
 * sizes table reports day and twilight apart and decides "within 2%" by the
 * 95% interval (yes, no, undecided); the written sets are listed in the
 * section and in summary.json. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "core/files/atomic_file.h"
#include "atmosphere/atmosphere_section.h"
#include "tests/check.h"

static atmosphere_luts_result made_up(void)
{
    /* in-scatter beyond 2%, sun within, sky straddling 2% */
    static const double total[3] = {0.5, 0.01, 0.019}, quadrature[3] = {1e-3, 1e-4, 0.002}, se[3] = {0.1, 0.002, 0.003};
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
        x->error.twilight_total = (atmosphere_error_stats){0.4, 0.3, 0.25, 0.09};
        x->error.day_points = 40, x->error.twilight_points = 8;
        x->error.total.p95_se = se[t];
        r.talk_row[t] = t, r.smallest_within[t] = t == 1 ? 1 : -1;
    }
    /* the sky: one talk-size row per parametrization, Yusov's last */
    static const atmosphere_lut_parametrization order[3] = {ATMOSPHERE_PARAM_LINEAR, ATMOSPHERE_PARAM_BRUNETON,
                                                            ATMOSPHERE_PARAM_YUSOV};
    r.sky_row_count = 3;
    for (int k = 0; k < 3; ++k) {
        atmosphere_sky_row *x = &r.sky_rows[k];
        snprintf(x->label, sizeof x->label, "talk");
        x->parametrization = order[k], x->talk = 1, x->bytes = 131072;
        x->sizes[0] = 8, x->sizes[1] = 64, x->sizes[2] = 8, x->sizes[3] = 4;
        x->day = (atmosphere_error_stats){0.9, 0.3, k == 2 ? 0.005 : 0.5, k == 2 ? 0.001 : 0.1};
        x->twilight = (atmosphere_error_stats){0.9, 0.3, k == 2 ? 0.08 : 0.001, 0.01};
        r.sky_talk_row[order[k]] = k;
    }
    /* the written sets: linear in every format, Yusov's as EXR */
    r.file_set_count = 2;
    r.file_sets[0] = (atmosphere_luts_file_set){ATMOSPHERE_PARAM_LINEAR, atmosphere_lut_sizes_talk(), 2,
                                                {"luts/atmosphere/atmosphere_inscatter.exr", "luts/atmosphere/atmosphere_luts.h"}};
    r.file_sets[1] = (atmosphere_luts_file_set){ATMOSPHERE_PARAM_YUSOV, atmosphere_lut_sizes_talk(), 1,
                                                {"luts/atmosphere/atmosphere_inscatter_yusov2013.exr"}};
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
    report_context ctx = {{dir, QUALITY_PREVIEW, 1, NULL, NULL, 0}, &doc, cJSON_CreateObject(), &claims};
    CHECK(atmosphere_section(&ctx, &r, &e) == 0);
    const cJSON *rows = cJSON_GetObjectItem(cJSON_GetObjectItem(ctx.summary, "atmosphere_luts"), "sizes");
    CHECK(cJSON_GetArraySize(rows) == 3);
    CHECK(cJSON_GetNumberValue(cJSON_GetObjectItem(cJSON_GetArrayItem(rows, 0), "interpolation_max")) == 1.0 / 3.0);
    const cJSON *sky = cJSON_GetObjectItem(cJSON_GetObjectItem(ctx.summary, "atmosphere_luts"), "sky");
    CHECK(cJSON_GetArraySize(sky) == 3);
    CHECK(cJSON_GetNumberValue(cJSON_GetObjectItem(cJSON_GetArrayItem(sky, 2), "twilight_p95")) == 0.08);
    /* the sizes table's day and twilight apart, and its decision by the interval */
    CHECK(cJSON_GetNumberValue(cJSON_GetObjectItem(cJSON_GetArrayItem(rows, 0), "twilight_total_p95")) == 0.25);
    CHECK(cJSON_GetNumberValue(cJSON_GetObjectItem(cJSON_GetArrayItem(rows, 0), "twilight_points")) == 8);
    CHECK(strstr(doc.md, "| no |") && strstr(doc.md, "| undecided |") && strstr(doc.md, "| yes |"));
    CHECK(strstr(doc.findings_md, "in twilight (8 points) 25.0% +- 9.0%"));
    /* the written files: listed in the section and in summary.json per parametrization */
    const cJSON *files = cJSON_GetObjectItem(cJSON_GetObjectItem(ctx.summary, "atmosphere_luts"), "files");
    CHECK(cJSON_GetArraySize(files) == 2);
    CHECK(strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(cJSON_GetArrayItem(files, 1), "parametrization")),
                 "yusov2013") == 0);
    CHECK(strcmp(cJSON_GetStringValue(cJSON_GetArrayItem(cJSON_GetObjectItem(cJSON_GetArrayItem(files, 1), "paths"), 0)),
                 "luts/atmosphere/atmosphere_inscatter_yusov2013.exr") == 0);
    CHECK(strstr(doc.md, "Yusov 2013 parametrization (gtlab.lut.parametrization \"yusov2013\")") &&
          strstr(doc.md, "luts/atmosphere/atmosphere_inscatter_yusov2013.exr"));
    CHECK(claims.count == 2); /* Yusov's table: the day, then twilight */
    CHECK(claims.count == 2 && claims.rows[0].verdict == CLAIM_REPRODUCED);
    CHECK(claims.count == 2 && claims.rows[1].verdict == CLAIM_FAILS_GTLAB_SETTING);
    CHECK(claims.count == 2 && strstr(claims.rows[0].record.quote, "[Yus13]") && claims.rows[0].record.seed[0] == '0');
    CHECK(claims_table_check(&claims, &e) == 0);
    /* an interval straddling one code value decides nothing */
    claims_table straddle = {0};
    r.sky_rows[2].twilight = (atmosphere_error_stats){0.9, 0.3, 0.017, 0.002};
    report_context again = ctx;
    again.claims = &straddle, again.summary = cJSON_CreateObject();
    CHECK(atmosphere_section(&again, &r, &e) == 0);
    CHECK(straddle.count == 2 && straddle.rows[1].verdict == CLAIM_NOT_SIGNIFICANT);
    cJSON_Delete(again.summary);
    cJSON_Delete(ctx.summary);
    report_free(&doc);
    return check_report("test_atmosphere_section");
}
