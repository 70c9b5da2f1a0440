/* Plots through gnuplot (DESIGN.md: a generated script and data file, PNG
 * out). The caller writes its data files and the plot commands; this runs
 * gnuplot with the pngcairo terminal and renames the finished PNG into
 * place, so a failed plot leaves nothing half-written. The script is kept
 * beside the PNG (NAME.gp, writing NAME.png) so a person can re-plot. */
#ifndef GTLAB_CLI_GNUPLOT_PNG_H
#define GTLAB_CLI_GNUPLOT_PNG_H

#include "core/error.h"

/* commands: gnuplot commands after "set terminal/output" (titles, axes,
 * plot ...), reading data files by path. Returns 0 or -1 with e (gnuplot
 * missing or failing). */
int gnuplot_png(const char *png_path, int width, int height, const char *commands, gt_error *e);

#endif
