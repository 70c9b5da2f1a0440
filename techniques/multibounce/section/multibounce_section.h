/* The GTAO multi-bounce refit: coefficients against the talk's, per-albedo
 * cubics, leave-one-scene-out table, what the data show, the figures, the
 * validation against the references and the performance. */
#ifndef GTLAB_MULTIBOUNCE_MULTIBOUNCE_SECTION_H
#define GTLAB_MULTIBOUNCE_MULTIBOUNCE_SECTION_H

#include "multibounce/multibounce_study.h"
#include "report/report_context.h"

/* Adds the section to ctx's report and summary.json; -1 (e set) if a file it
 * writes could not be made. */
int multibounce_section(report_context *ctx, const multibounce_study_result *r, gt_error *e);

#endif
