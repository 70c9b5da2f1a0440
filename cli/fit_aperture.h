/* gtlab fit aperture (fitters/aperture_fit.h: the GTSO talk's
 * gloss-to-aperture parameter u) and the renderings of a fit that the verb
 * and the `gtlab all` stage share: the fit as JSON, its curve as a plot. */
#ifndef GTLAB_CLI_FIT_APERTURE_H
#define GTLAB_CLI_FIT_APERTURE_H

#include <cjson/cJSON.h>

#include "fitters/aperture_fit.h"

/* The fit as JSON (u, DSSIM, DSSIM at the talk's u, the curve), and the curve as a PNG plot. */
cJSON *aperture_fit_json(const aperture_fit *fit, const char *channel, int exact);
int aperture_fit_plot(const aperture_fit *fit, const char *path, const char *title, gt_error *e);

#endif
