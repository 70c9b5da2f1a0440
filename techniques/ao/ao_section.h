/* The AO and bent-normal references of every built-in scene: a table of their
 * sampling, noise and noise floor, and their previews. */
#ifndef GTLAB_AO_AO_SECTION_H
#define GTLAB_AO_AO_SECTION_H

#include "ao/ao_references.h"
#include "report/report_context.h"

/* Adds the section to ctx's report and summary.json; -1 (e set) if a file it
 * writes could not be made. */
int ao_references_section(report_context *ctx, const ao_references_result *r, gt_error *e);

#endif
