/* The convergence figure; see convergence_plot.h. */
#include "ao/ao_convergence_plot.h"

#include <stdio.h>
#include <string.h>

#include "core/files/atomic_file.h"
#include "report/gnuplot_plot.h"

static int write_data(const ao_convergence_result *r, const char *path, gt_error *e)
{
    atomic_file f;
    FILE *out = atomic_file_open(&f, path, "w", e);
    if (!out)
        return -1;
    for (int i = 0; i < r->scene_count; ++i)
        for (int m = 0; m < CONVERGENCE_MODES; ++m) {
            fprintf(out, "# %s %s\n", r->scenes[i].scene, m == CONVERGENCE_CV ? "control-variate" : "plain");
            for (int k = 0; k < r->scenes[i].count[m]; ++k) {
                const convergence_point *p = &r->scenes[i].points[m][k];
                fprintf(out, "%d %.6g %.6g\n", p->spp, p->seconds, p->rmse > 0.0 ? p->rmse : 1e-6);
            }
            fprintf(out, "\n\n");
        }
    return atomic_file_close(&f, out, e);
}

int convergence_plot(const ao_convergence_result *r, const char *dir, gt_error *e)
{
    char data[4096], png[4096], script[16384];
    snprintf(data, sizeof data, "%s/convergence.dat", dir);
    snprintf(png, sizeof png, "%s/convergence.png", dir);
    if (write_data(r, data, e) != 0)
        return -1;
    int columns = 3, rows = (r->scene_count + columns - 1) / columns;
    int n = snprintf(script, sizeof script,
                     "set multiplot layout %d,%d title 'AO reference: RMSE of ao.V against wall time (%dx%d, %d "
                     "threads; RMSE 1e-6 stands for 0)'\n"
                     "set logscale xy\nset xlabel 'seconds'\nset ylabel 'RMSE'\nset key bottom left\nset grid\n",
                     rows, columns, r->request.width, r->request.height, r->request.threads);
    for (int i = 0; i < r->scene_count && n < (int)sizeof script - 512; ++i) {
        const ao_convergence_scene *s = &r->scenes[i];
        char title[160];
        if (s->kind[CONVERGENCE_PLAIN] == TARGET_AT_FIRST && s->kind[CONVERGENCE_CV] == TARGET_AT_FIRST)
            snprintf(title, sizeof title, "%s: both below RMSE %.3g at the first render", s->scene, r->request.target);
        else
            snprintf(title, sizeof title, "%s: control variate %.2fx faster to RMSE %.3g", s->scene, s->speedup,
                     r->request.target);
        n += snprintf(script + n, sizeof script - (size_t)n,
                      "set title '%s'\n"
                      "plot '%s' index %d using 2:3 with linespoints title 'plain', "
                      "'' index %d using 2:3 with linespoints title 'control variate', %g with lines dt 2 notitle\n",
                      title, data, 2 * i, 2 * i + 1, r->request.target);
    }
    snprintf(script + n, sizeof script - (size_t)n, "unset multiplot\n");
    return gnuplot_render(script, png, 1200, 400 * rows, e);
}
