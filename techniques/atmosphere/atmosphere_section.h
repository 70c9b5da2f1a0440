/* The Decima atmosphere LUTs (atmosphere/atmosphere_luts_study.h): their definitions,
 * their error against direct integration as each axis departs from the
 * talk's size (figures/atmosphere_sizes.png; day and twilight apart), the
 * sky the in-scatter table feeds under each parametrization, the files
 * written per parametrization (also in summary.json, atmosphere_luts.files),
 * and the talk's claim that its sizes suffice, in the claims table. */
#ifndef GTLAB_ATMOSPHERE_SECTION_H
#define GTLAB_ATMOSPHERE_SECTION_H

#include "report/report_context.h"
#include "atmosphere/atmosphere_luts_study.h"

/* Adds the section to ctx's report, summary.json and claims; -1 (e set) if
 * a file it writes could not be made. */
int atmosphere_section(report_context *ctx, const atmosphere_luts_result *r, gt_error *e);

#endif
