/* The report's frame around the sections of `gtlab all`: the introduction
 * (how the report was made, so a reader can rerun it) and summary.json. */
#ifndef GTLAB_REPORT_FRAME_H
#define GTLAB_REPORT_FRAME_H

#include "core/error.h"
#include "report/report_context.h"

/* The version and quality into summary.json, and the paragraph naming the
 * command that made the report (stage_list and project: NULL when not given)
 * and the stages whose sections came from earlier runs into the folder
 * (earlier: their keys, comma-separated; NULL or "" for none). */
void report_introduce(report_context *ctx, const char *stage_list, const char *project, const char *earlier);

/* <output>/summary.json, written atomically. */
int report_write_summary(const report_context *ctx, gt_error *e);
/* claims.md beside it: one paragraph per claim (claims_table_markdown);
 * nothing when no claim was measured. report_write_summary calls it. */
int report_write_claims(const report_context *ctx, gt_error *e);

#endif
