/* Plots through gnuplot (Debian's gnuplot-nox): a caller writes its data
 * file and the body of a gnuplot script; this sets the PNG terminal
 * (pngcairo if this gnuplot has it, else png), runs gnuplot and moves the
 * finished PNG into place atomically. */
#ifndef GTLAB_CLI_GNUPLOT_PLOT_H
#define GTLAB_CLI_GNUPLOT_PLOT_H

#include "core/error.h"

/* Whether a gnuplot executable is on the PATH. */
int gnuplot_available(void);

/* Renders `script` (plot commands; no terminal or output lines) into
 * png_path at width x height pixels. The script is kept beside the PNG as
 * <png_path without .png>.gp, so a person can edit and rerun it. Returns 0,
 * or -1 with e (gnuplot missing or failing: its first error line). */
int gnuplot_render(const char *script, const char *png_path, int width, int height, gt_error *e);

#endif
