#define _GNU_SOURCE
#include "cli/gnuplot_plot.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "core/atomic_file.h"

int plot_curve_png(const char *png_path, const plot_style *style, const double *x, const double *y, int n, gt_error *e)
{
    char dir[] = "/tmp/gtlab-plot-XXXXXX", data[64], script[64];
    if (!mkdtemp(dir))
        return gt_error_set(e, png_path, "cannot create a temporary folder for gnuplot");
    snprintf(data, sizeof data, "%s/curve.dat", dir);
    snprintf(script, sizeof script, "%s/plot.gp", dir);
    atomic_file out;
    int rc = -1;
    FILE *f = fopen(data, "w"), *g = f ? fopen(script, "w") : NULL;
    if (f && g && atomic_file_begin(&out, png_path, e) == 0) {
        for (int i = 0; i < n; ++i)
            fprintf(f, "%.9g %.9g\n", x[i], y[i]);
        fprintf(g, "set terminal pngcairo size 800,500 noenhanced\nset output '%s'\nset title '%s'\nset xlabel '%s'\nset ylabel '%s'\n"
                   "set grid\n%s",
                out.temp_path, style->title, style->xlabel, style->ylabel, style->log_x ? "set logscale x\n" : "");
        if (!isnan(style->marker_x))
            fprintf(g, "set arrow from %.9g, graph 0 to %.9g, graph 1 nohead dt 2\nset label '%s' at %.9g, graph 0.95\n",
                    style->marker_x, style->marker_x, style->marker_label ? style->marker_label : "", style->marker_x);
        fprintf(g, "plot '%s' using 1:2 with linespoints notitle\n", data);
        fclose(f), fclose(g), f = g = NULL;
        char command[256];
        snprintf(command, sizeof command, "gnuplot '%s' 2>/dev/null", script);
        if (system(command) == 0)
            rc = atomic_file_commit(&out, e);
        else {
            atomic_file_abort(&out);
            gt_error_set(e, png_path, "gnuplot failed (is gnuplot-nox installed?)");
        }
    } else if (!f || !g) {
        gt_error_set(e, png_path, "cannot write gnuplot's input files");
    }
    if (f)
        fclose(f);
    if (g)
        fclose(g);
    unlink(data);
    unlink(script);
    rmdir(dir);
    return rc;
}
