/* report.html's figures settled when the report is written, once every
 * stage has made its files: the writer (report_writer.c) marks an image's
 * path FIGURE_SRC path FIGURE_SRC where it is used, and FIGURE_BAR path
 * FIGURE_BAR where its colour bar would go. Resolved against the output
 * folder, a PNG with an SVG of the same name beside it (a gnuplot plot,
 * report/gnuplot_plot.h) is shown as the SVG, and a heatmap gets its colour
 * bar (report/heatmap_colour_bar.h); anything else is left as it was. */
#ifndef GTLAB_REPORT_FIGURE_RESOLVE_H
#define GTLAB_REPORT_FIGURE_RESOLVE_H

#define FIGURE_SRC "\x1f"
#define FIGURE_BAR "\x1e"

/* html with its marks resolved against dir (malloc'd; NULL when out of
 * memory). */
char *figures_resolve(const char *html, const char *dir);

#endif
