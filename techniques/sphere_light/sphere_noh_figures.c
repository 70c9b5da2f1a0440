/* The plots of the GetNoHSquared sweep; see sphere_noh_figures.h. */
#include "sphere_light/sphere_noh_figures.h"

#include <stdio.h>

#include "report/gnuplot_plot.h"

int sphere_noh_plots(const char *dir, gt_error *e)
{
    char commands[4096], path[4096];
    snprintf(commands, sizeof commands,
             "set datafile separator ','\n"
             "set multiplot layout 1,2 title 'GetNoHSquared: one Newton step against Karis (mean over light size and azimuth)'\n"
             "set xlabel 'n.v'\nset ylabel 'light elevation from n (deg)'\n"
             "set palette defined (-1 'red', 0 'white', 1 'blue')\n"
             "set title 'gain in (N.H)^2 (blue: the step helps)'\n"
             "stats '%s/sphere_noh_map.csv' using 3 nooutput\n"
             "m = (abs(STATS_min) > abs(STATS_max) ? abs(STATS_min) : abs(STATS_max))\n"
             "set cbrange [-m:m]\n"
             "plot '%s/sphere_noh_map.csv' using 1:2:3 with image notitle\n"
             "set palette defined (0 'white', 1 'red')\nset cbrange [0:*]\n"
             "set title 'share of configurations where the step is worse'\n"
             "plot '%s/sphere_noh_map.csv' using 1:2:4 with image notitle\n"
             "unset multiplot\n",
             dir, dir, dir);
    snprintf(path, sizeof path, "%s/sphere_noh_map.png", dir);
    if (gnuplot_render(commands, path, 1200, 500, e) != 0)
        return -1;
    /* Mean shortfall against n.v, averaged over the elevations too. */
    snprintf(commands, sizeof commands,
             "set datafile separator ','\nset key top right\nset logscale y\n"
             "set xlabel 'n.v'\nset ylabel 'mean shortfall of (N.H)^2 below the maximum'\n"
             "set title 'GetNoHSquared against the brute-force maximum'\n"
             "plot '%s/sphere_noh_by_nv.csv' using 1:2 with linespoints title 'Karis (0 steps)', "
             "'' using 1:3 with linespoints title '1 Newton step (Decima)', "
             "'' using 1:4 with linespoints title '2 Newton steps', "
             "'' using 1:5 with linespoints title \"1 step, guarded (f''(0) < 0)\"\n",
             dir);
    snprintf(path, sizeof path, "%s/sphere_noh_error.png", dir);
    return gnuplot_render(commands, path, 800, 500, e);
}
