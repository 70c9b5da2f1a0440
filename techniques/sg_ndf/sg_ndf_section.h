/* The NDF fit with spherical Gaussians (sg_ndf/sg_ndf_study.h): E and max error
 * against k per material, the specular images' DSSIM, the plot
 * figures/sg_ndf_error.png, and the claims row for the talk's "~7 lobes for
 * anisotropic Ward". */
#ifndef GTLAB_SG_NDF_SECTION_H
#define GTLAB_SG_NDF_SECTION_H

#include "report/report_context.h"
#include "sg_ndf/sg_ndf_study.h"

/* The claims rows of the talk's "~7 lobes for anisotropic Ward": one per Ward
 * material with a checked 7-lobe fit within the threshold; a paragraph in
 * ctx's report for each other Ward material. */
void sg_ndf_claim_rows(report_context *ctx, const sg_ndf_result *r);
/* Adds the section to ctx's report, summary.json and claims; -1 (e set) if
 * the plot could not be made. */
int sg_ndf_section(report_context *ctx, const sg_ndf_result *r, gt_error *e);

#endif
