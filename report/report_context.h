/* The accuracy report's layer: each technique's section of `gtlab all`
 * rendered from its study's results struct (techniques/<name>/), into the report
 * (report_writer.h: Markdown and HTML), summary.json and the figures under
 * the output folder. A section computes nothing but presentation: tables and
 * JSON from one description of their columns (report_table.h), prose whose
 * figures are the struct's fields, gnuplot figures from data files the study
 * wrote. The command line (cli/) runs a study and hands its result to the
 * section; tests can render a section from a struct they made up.
 *
 * A section of technique T is report/T_section.{h,c}:
 *     int T_section(report_context *ctx, const T_result *r, gt_error *e); */
#ifndef GTLAB_REPORT_CONTEXT_H
#define GTLAB_REPORT_CONTEXT_H

#include <cjson/cJSON.h>

#include "core/error.h"
#include "report/claims_table.h"
#include "report/report_writer.h"
#include "project/study_context.h"

typedef struct {
    study_context study; /* output folder, quality, threads: what the studies saw */
    report *doc;
    cJSON *summary; /* summary.json: one member per section */
    claims_table *claims; /* the talks' claims the sections measured (NULL: not gathered) */
} report_context;

#endif
