/* The report is data: a section rendered from a results struct made up here
 * (no study runs) puts the struct's fields into summary.json exactly (full
 * doubles, integers, text) and into the report's table with the column's
 * format, one row per struct row, in order. The AO references' section
 * (ao_section.c) stands for all: they share report/report_table.c. */
#include "ao/ao_section.h"
#include "tests/check.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static char *read_all(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *text = f ? calloc(1, 1 << 20) : NULL;
    if (text)
        CHECK(fread(text, 1, (1 << 20) - 1, f) > 0);
    if (f)
        fclose(f);
    return text;
}

static ao_references_result made_up_result(void)
{
    ao_references_result r;
    memset(&r, 0, sizeof r);
    r.request = (ao_references_request){.size = 64, .spp = 32, .target_stderr = 0, .seed = 7};
    r.count = 2;
    for (int i = 0; i < r.count; ++i) {
        ao_reference_row *row = &r.rows[i];
        snprintf(row->scene, sizeof row->scene, "scene%d", i);
        row->triangles = 1000003u * (uint64_t)(i + 1);
        row->width = 64;
        row->height = 48 + i;
        row->covered_pixels = 3000 + i;
        row->mean_spp = 31.5;
        row->seconds = 1.25 + i;
        row->rays_per_second = 2.5e6 * (i + 1);
        row->mean_stderr = 0.0123456789 / (i + 1);
        row->max_stderr = 0.1 + 1e-12 * i;
        row->noise_floor_dssim = 3.3e-4 * (i + 1);
    }
    return r;
}

static void test_summary_carries_the_fields(const ao_references_result *r, const cJSON *summary)
{
    const cJSON *list = cJSON_GetObjectItemCaseSensitive(summary, "ao_references");
    CHECK(cJSON_IsArray(list) && cJSON_GetArraySize(list) == r->count);
    for (int i = 0; i < r->count && i < cJSON_GetArraySize(list); ++i) {
        const cJSON *o = cJSON_GetArrayItem(list, i);
        const ao_reference_row *row = &r->rows[i];
        CHECK(strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(o, "scene")), row->scene) == 0);
        CHECK(cJSON_GetNumberValue(cJSON_GetObjectItem(o, "triangles")) == (double)row->triangles);
        CHECK(cJSON_GetNumberValue(cJSON_GetObjectItem(o, "height")) == row->height);
        CHECK(cJSON_GetNumberValue(cJSON_GetObjectItem(o, "mean_stderr_ao")) == row->mean_stderr);
        CHECK(cJSON_GetNumberValue(cJSON_GetObjectItem(o, "max_stderr_ao")) == row->max_stderr);
        CHECK(cJSON_GetNumberValue(cJSON_GetObjectItem(o, "noise_floor_dssim_ao")) == row->noise_floor_dssim);
        CHECK(cJSON_GetNumberValue(cJSON_GetObjectItem(o, "rays_per_second")) == row->rays_per_second);
    }
}

/* Each row's table line has its scene, size and formatted stderr, in order. */
static void test_table_carries_the_fields(const ao_references_result *r, const char *md)
{
    CHECK(md && strstr(md, "| scene |") && strstr(md, "mean stderr"));
    const char *at = md;
    for (int i = 0; i < r->count && at; ++i) {
        char scene[80], size[32], stderr_text[32];
        snprintf(scene, sizeof scene, "| %s |", r->rows[i].scene);
        snprintf(size, sizeof size, "| %dx%d |", r->rows[i].width, r->rows[i].height);
        snprintf(stderr_text, sizeof stderr_text, "| %.2e |", r->rows[i].mean_stderr);
        at = strstr(at, scene);
        CHECK(at != NULL);
        const char *end = at ? strchr(at, '\n') : NULL;
        CHECK(end && strstr(at, size) && strstr(at, size) < end && strstr(at, stderr_text) &&
              strstr(at, stderr_text) < end);
        at = end;
    }
}

int main(void)
{
    char dir[2048];
    snprintf(dir, sizeof dir, "%s/report_sections_output", check_tmp_dir());
    mkdir(dir, 0755);
    ao_references_result r = made_up_result();
    report doc;
    report_init(&doc, "test");
    report_context ctx = {{dir, QUALITY_PREVIEW, 1, NULL, NULL, 0}, &doc, cJSON_CreateObject(), NULL};
    gt_error e;
    CHECK(ao_references_section(&ctx, &r, &e) == 0);
    test_summary_carries_the_fields(&r, ctx.summary);
    CHECK(report_write(&doc, dir, &e) == 0);
    char path[4096];
    snprintf(path, sizeof path, "%s/report.md", dir);
    char *md = read_all(path);
    test_table_carries_the_fields(&r, md);
    free(md);
    report_free(&doc);
    cJSON_Delete(ctx.summary);
    return check_report("report_ao_section");
}
