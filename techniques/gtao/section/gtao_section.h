/* GTAO, HBAO and VO against the height-field and 3-D AO references: scores,
 * heatmaps, the convergence plot, and GTAO's parameters tuned by DSSIM
 * (written as gtao/params_fit.json too). */
#ifndef GTLAB_GTAO_GTAO_SECTION_H
#define GTLAB_GTAO_GTAO_SECTION_H

#include "gtao/gtao_validation.h"
#include "report/report_context.h"

/* Adds the section to ctx's report and summary.json; -1 (e set) if a file it
 * writes could not be made. */
int gtao_section(report_context *ctx, const gtao_validation_result *r, gt_error *e);

/* The At-a-glance row (report_headline.h): the real-time variants ranked by
 * their mean RMSE against the 3-D reference, paired over the scenes;
 * brute-force GTAO (exact horizons, seconds a frame) is the bound they
 * approach, not a contender, so it is left out of the ranking. */
void gtao_headline(report *doc, const gtao_validation_result *r);

/* The fit paragraph's explanation when fitted values end on the edge of
 * their range (gtao_fit_at_bound): which, what that means, and that their
 * standard errors are no interval there; "" when none does. */
void gtao_fit_bound_explanation(const gtao_fit_result *r, char *text, size_t size);

/* One scene's paragraph on brute-force GTAO (the reference preset's exact
 * horizons) against the height-field reference: within the reference's
 * noise, or above it by less than one 8-bit code value (equal for a viewer),
 * and so the converged presets' gap is their horizon search's steps; or
 * above it by more, a difference the tests do not explain. Its figures and
 * standing appended to list (summary.json's gtao_exact_horizons). Nothing
 * when the scene has no such run. */
void gtao_exact_horizons_statement(report *doc, cJSON *list, const gtao_validation_scene *s);

#endif
