/* Best-fit normals (best_fit_normals/best_fit_normals_study.h): the audit of the talk's
 * cell counts, each encoding's angular error and its effect on a GGX
 * highlight, the table in every format (figures/normals_cells.png). */
#ifndef GTLAB_BEST_FIT_NORMALS_SECTION_H
#define GTLAB_BEST_FIT_NORMALS_SECTION_H

#include "report/report_context.h"
#include "best_fit_normals/best_fit_normals_study.h"

/* Adds the section and its claims rows; -1 (e set) if a figure could not be made. */
/* The four claims rows of the talk's "Storage techniques breakdown" from the
 * exact and sampled cell counts (a NULL table ignores them). */
void normals_add_claims(claims_table *t, const normals_result *r);
int normals_section(report_context *ctx, const normals_result *r, gt_error *e);

#endif
