/* Line plots as PNG through gnuplot (gnuplot-nox): a data file and a
 * generated script in a temporary folder, the pngcairo terminal, the PNG
 * written to a temporary name and renamed into place. */
#ifndef GTLAB_CLI_GNUPLOT_PLOT_H
#define GTLAB_CLI_GNUPLOT_PLOT_H

#include "core/error.h"

typedef struct {
    const char *title, *xlabel, *ylabel;
    int log_x;
    double marker_x; /* a vertical line there (e.g. the optimum); NaN: none */
    const char *marker_label;
} plot_style;

/* One curve y(x) of n points, sorted by x. */
int plot_curve_png(const char *png_path, const plot_style *style, const double *x, const double *y, int n, gt_error *e);

#endif
