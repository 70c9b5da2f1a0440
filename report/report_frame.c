/* The report's frame; see report_frame.h. */
#include "report/report_frame.h"

#include <stdio.h>
#include <stdlib.h>

#include "core/files/atomic_file.h"

void report_introduce(report_context *ctx, const char *stage_list, const char *project, const char *earlier)
{
    const char *quality = study_quality_name(ctx->study.quality);
    cJSON_AddStringToObject(ctx->summary, "gtlab_version", GTLAB_VERSION);
    cJSON_AddStringToObject(ctx->summary, "quality", quality);
    char stage_option[512] = "";
    if (stage_list || project)
        snprintf(stage_option, sizeof stage_option, "%s%s%s%s", stage_list ? " --stages " : "",
                 stage_list ? stage_list : "", project ? " --project " : "", project ? project : "");
    report_paragraph(ctx->doc,
                     "Made by gtlab %s with 'gtlab all --quality %s%s'. Every figure below comes from that run; "
                     "rerunning the command on the same machine reproduces the images bit for bit (timings vary; another CPU "
                     "model changes last digits, docs/decisions.md). "
                     "Machine-readable figures: summary.json. In a table that ranks what it lists, the best row is bold.",
                     GTLAB_VERSION, quality, stage_option);
    if (earlier && earlier[0])
        report_paragraph(ctx->doc,
                         "The sections of the stages %s come from earlier runs into this folder, at the same quality "
                         "and for the same project: each stage's part of the report is kept in parts/ and the "
                         "report is assembled from them, so rerunning some stages keeps the others' sections.",
                         earlier);
    report_findings_here(ctx->doc);
}

/* Writes text (malloc'd, freed here; NULL: out of memory) as DIR/name. */
static int write_output_text(const report_context *ctx, const char *name, char *text, gt_error *e)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", ctx->study.output_dir, name);
    if (!text)
        return gt_error_set(e, path, "out of memory");
    int rc = atomic_write_text(path, text, e);
    free(text);
    return rc;
}

int report_write_summary(const report_context *ctx, gt_error *e)
{
    if (write_output_text(ctx, "summary.json", cJSON_Print(ctx->summary), e) != 0)
        return -1;
    return report_write_claims(ctx, e);
}

int report_write_claims(const report_context *ctx, gt_error *e)
{
    if (!ctx->claims || ctx->claims->count == 0)
        return 0;
    return write_output_text(ctx, "claims.md", claims_table_markdown(ctx->claims), e);
}
