/* Plots through gnuplot (Debian's gnuplot-nox): a caller writes its data
 * file and the body of a gnuplot script; this sets the PNG terminal
 * (pngcairo if this gnuplot has it, else png), runs gnuplot and moves the
 * finished PNG into place atomically, then draws the same script with the
 * svg terminal beside it (<name>.svg), which report.html shows at full
 * width (report/figure_resolve.h); report.md keeps the PNG. */
#ifndef GTLAB_CLI_GNUPLOT_PLOT_H
#define GTLAB_CLI_GNUPLOT_PLOT_H

#include "core/error.h"

enum { GNUPLOT_SVG_FONT = 13 };

/* Whether a gnuplot executable is on the PATH. */
int gnuplot_available(void);

/* Renders `script` (plot commands; no terminal or output lines) into
 * png_path at width x height pixels, and into <png_path without .png>.svg
 * at the same size with a font scaled to be legible at the report's full
 * width (GNUPLOT_SVG_FONT points per 900 pixels of width, at least 11). The
 * PNG's script is kept beside it as <png_path without .png>.gp, so a person
 * can edit and rerun it. Returns 0, or -1 with e (gnuplot missing or
 * failing: its first error line; a PNG or SVG that is not whole, which
 * gnuplot does not report: a full disk). */
int gnuplot_render(const char *script, const char *png_path, int width, int height, gt_error *e);

#endif
