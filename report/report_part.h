/* A `gtlab all` stage's part of the report: everything its section wrote,
 * kept in the output folder so that the report can be assembled from the
 * parts of one run or of several (cli/verb_all.c):
 *
 *   - a rerun of some stages into a folder keeps the other stages'
 *     sections (issue 41: `--stages screen-shaders -o out` no longer
 *     replaces a full report with one of two sections);
 *   - the tasks of a batch plan, or the ranks of an MPI job, each run some
 *     stages, and the last assembles the report (issue 46 item 5).
 *
 * A part is DIR/parts/<stage>.json:
 *
 *   { "gtlab_version": ..., "quality": "preview", "project": "my.json" or "",
 *     "stage": "gtao", "seconds": 223.4,
 *     "journal": [["heading", 2, "GTAO"], ["paragraph", "..."], ...],
 *     "summary": { the stage's members of summary.json },
 *     "claims":  [ its rows of the claims table ] }
 *
 * The journal holds the stage's calls of report_writer.h, text formatted
 * (report.journal); replayed in the stages' order into one report they give
 * the bytes of report.md and report.html that one process writing them
 * directly would, since every anchor, contents entry and At-a-glance row is
 * computed from those calls alone (tests/report/test_report_part.c). A
 * stage's section writes only through ctx (report, summary, claims), so its
 * part is all of it. */
#ifndef GTLAB_REPORT_REPORT_PART_H
#define GTLAB_REPORT_REPORT_PART_H

#include <cjson/cJSON.h>

#include "report/report_context.h"

#define REPORT_PARTS_DIR "parts"

/* Where a stage writes while its part is recorded. */
typedef struct {
    report doc; /* a scratch report (its text is dropped) */
    cJSON *journal, *summary;
    claims_table *claims;
} report_part_recorder;

/* stage becomes run with its report, summary and claims table the
 * recorder's (fresh). -1 with e when out of memory. */
int report_part_begin(report_part_recorder *rec, const report_context *run, report_context *stage, gt_error *e);
/* Drops what was recorded (the stage failed). */
void report_part_discard(report_part_recorder *rec);
/* The part (cJSON_Delete it) of what was written since begin, by stage
 * `key` in `seconds`, the recorder emptied; NULL with e when out of memory
 * or when the stage gave the claims table a record it refuses. */
cJSON *report_part_end(report_part_recorder *rec, const report_context *run, const char *key, const char *project,
                       double seconds, gt_error *e);

/* Writes part as DIR/parts/<stage>.json atomically (the folder made). */
int report_part_write(const char *dir, const cJSON *part, gt_error *e);
/* Reads DIR/parts/<key>.json: 1 and *part, 0 when there is none, -1 with e
 * when it is not a part of stage key. */
int report_part_read(const char *dir, const char *key, cJSON **part, gt_error *e);
/* Whether part was made by this gtlab, at this quality, for this project
 * (NULL: none): 0, or -1 with why ("made at production quality"). */
int report_part_matches(const cJSON *part, study_quality quality, const char *project, char *why, size_t size);
/* The stage's wall seconds the part records. */
double report_part_seconds(const cJSON *part);

/* Appends the part to ctx's report, summary and claims table, as the stage
 * had written them there. The claims' texts point into part: keep it until
 * the table is written. -1 with e (what: the part's file) on a malformed
 * part. */
int report_part_replay(report_context *ctx, const cJSON *part, const char *what, gt_error *e);

#endif
