/* The figure of `gtlab bench convergence` (ao_convergence.h): RMSE
 * against wall time, log-log, one panel per scene, plain and control
 * variate, the target RMSE as a line. Writes <dir>/convergence.dat (blocks
 * scene by scene, plain then control variate: spp, seconds, RMSE) and
 * <dir>/convergence.png. */
#ifndef GTLAB_AO_AO_CONVERGENCE_PLOT_H
#define GTLAB_AO_AO_CONVERGENCE_PLOT_H

#include "ao/ao_convergence.h"
#include "core/error.h"

/* Returns 0, or -1 with e set (e.g. gnuplot missing: the data file is
 * written first). */
int convergence_plot(const ao_convergence_result *r, const char *dir, gt_error *e);

#endif
