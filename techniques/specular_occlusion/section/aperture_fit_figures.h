/* The renderings of a fit of the GTSO talk's gloss-to-aperture parameter u
 * (specular_occlusion/aperture_fit.h) that `gtlab fit aperture` and the
 * specular-occlusion section of `gtlab all` share: the fit as JSON, its curve
 * as a plot. */
#ifndef GTLAB_SPECULAR_OCCLUSION_APERTURE_FIT_FIGURES_H
#define GTLAB_SPECULAR_OCCLUSION_APERTURE_FIT_FIGURES_H

#include <cjson/cJSON.h>

#include "specular_occlusion/aperture_fit.h"

/* The fit as JSON (cone, u, DSSIM, DSSIM at the talk's u, the curve). */
cJSON *aperture_fit_json(const aperture_fit *fit, const char *channel, int exact);
/* That JSON written to path (atomically): `gtlab fit aperture`'s output.
 * Returns 0, or -1 with e. */
int aperture_fit_write_json(const aperture_fit *fit, const char *channel, int exact, const char *path, gt_error *e);
/* The curves of fits[0 .. count) in one PNG plot, each fitted u marked. */
int aperture_fit_plot(const aperture_fit *fits, int count, const char *path, const char *title, gt_error *e);
/* The RMSE of each region (specular_occlusion/aperture_fit.h) against u, as a PNG plot. */
int aperture_fit_region_plot(const aperture_fit *fit, const char *path, const char *title, gt_error *e);

#endif
