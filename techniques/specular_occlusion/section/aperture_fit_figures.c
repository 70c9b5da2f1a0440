/* The renderings of a gloss-to-aperture fit (specular_occlusion/aperture_fit.h) that
 * `gtlab fit aperture` and the specular-occlusion section share. */
#define _GNU_SOURCE
#include "specular_occlusion/aperture_fit_figures.h"

#include <stdio.h>
#include <stdlib.h>

#include "core/files/atomic_file.h"
#include "report/gnuplot_plot.h"

cJSON *aperture_fit_json(const aperture_fit *fit, const char *channel, int exact)
{
    cJSON *j = cJSON_CreateObject();
    cJSON_AddStringToObject(j, "problem", "aperture");
    cJSON_AddStringToObject(j, "reference_channel", channel);
    cJSON_AddStringToObject(j, "intersection", exact ? "exact" : "oat");
    cJSON_AddStringToObject(j, "cone", so_aperture_name(fit->mapping));
    cJSON_AddStringToObject(j, "search", "scan of log10 u by 1/8 decade, then golden section to 1e-3");
    cJSON_AddNumberToObject(j, "u", fit->u);
    cJSON_AddNumberToObject(j, "log10_u", fit->log10_u);
    cJSON_AddNumberToObject(j, "mean_dssim", fit->dssim);
    cJSON_AddBoolToObject(j, "at_range_edge", fit->at_range_edge);
    cJSON_AddNumberToObject(j, "mean_dssim_at_talk_u_0.01", fit->dssim_at_published);
    cJSON_AddNumberToObject(j, "evaluations", fit->evaluations);
    cJSON *regions = cJSON_AddObjectToObject(j, "regions");
    cJSON_AddNumberToObject(regions, "grazing_below_n_dot_v", APERTURE_GRAZING_NV);
    cJSON_AddNumberToObject(regions, "occluded_below_ao", APERTURE_OCCLUDED_AO);
    for (int k = 0; k < APERTURE_REGIONS; ++k) {
        cJSON *r = cJSON_AddObjectToObject(regions, aperture_region_name((aperture_region)k));
        cJSON_AddNumberToObject(r, "pixels", (double)fit->region_pixels[k]);
        cJSON_AddNumberToObject(r, "u_of_lowest_rmse", fit->region_best_u[k]);
    }
    cJSON *curve = cJSON_AddArrayToObject(j, "curve");
    for (int i = 0; i < fit->curve_count; ++i) {
        cJSON *p = cJSON_CreateObject();
        cJSON_AddNumberToObject(p, "u", fit->curve_u[i]);
        cJSON_AddNumberToObject(p, "mean_dssim", fit->curve_dssim[i]);
        for (int k = 0; k < APERTURE_REGIONS; ++k) {
            char key[32];
            snprintf(key, sizeof key, "rmse_%s", aperture_region_name((aperture_region)k));
            cJSON_AddNumberToObject(p, key, fit->curve_region_rmse[k][i]);
        }
        cJSON_AddItemToArray(curve, p);
    }
    return j;
}

/* The RMSE of each region along the scan, one curve per region, each
 * region's minimum marked. */
int aperture_fit_region_plot(const aperture_fit *fit, const char *path, const char *title, gt_error *e)
{
    char *script = NULL;
    size_t size = 0;
    FILE *mem = open_memstream(&script, &size);
    if (!mem)
        return gt_error_set(e, path, "out of memory");
    fprintf(mem, "$regions << EOD\n");
    for (int i = 0; i < fit->curve_count; ++i)
        fprintf(mem, "%.9g %.9g %.9g %.9g\n", fit->curve_u[i], fit->curve_region_rmse[0][i],
                fit->curve_region_rmse[1][i], fit->curve_region_rmse[2][i]);
    fprintf(mem, "EOD\n");
    for (int k = 0; k < APERTURE_REGIONS; ++k)
        fprintf(mem, "set arrow from %.9g, graph 0 to %.9g, graph 1 nohead dt 2 lc %d\n", fit->region_best_u[k],
                fit->region_best_u[k], k + 1);
    fprintf(mem,
            "set termoption noenhanced\nset title \"%s\"\nset xlabel 'u'\nset ylabel 'RMSE of V_s'\nset grid\n"
            "set logscale x\nset key top left\nplot $regions using 1:2 with lines lc 1 title 'grazing (n.v < %.2g, "
            "%ld px)', $regions using 1:3 with lines lc 2 title 'occluded (AO < %.2g, %ld px)', $regions using 1:4 "
            "with lines lc 3 title 'open (%ld px)'\n",
            title, APERTURE_GRAZING_NV, fit->region_pixels[APERTURE_GRAZING], APERTURE_OCCLUDED_AO,
            fit->region_pixels[APERTURE_OCCLUDED], fit->region_pixels[APERTURE_OPEN]);
    fclose(mem);
    int rc = gnuplot_render(script, path, 800, 500, e);
    free(script);
    return rc;
}

/* The DSSIM-vs-u curves of fits[0 .. count) on a log axis, each fitted u
 * marked; the points go inline as gnuplot datablocks so the kept .gp script
 * reruns alone. */
int aperture_fit_plot(const aperture_fit *fits, int count, const char *path, const char *title, gt_error *e)
{
    char *script = NULL;
    size_t size = 0;
    FILE *mem = open_memstream(&script, &size);
    if (!mem)
        return gt_error_set(e, path, "out of memory");
    for (int k = 0; k < count; ++k) {
        fprintf(mem, "$curve%d << EOD\n", k);
        for (int i = 0; i < fits[k].curve_count; ++i)
            fprintf(mem, "%.9g %.9g\n", fits[k].curve_u[i], fits[k].curve_dssim[i]);
        fprintf(mem, "EOD\nset arrow from %.9g, graph 0 to %.9g, graph 1 nohead dt 2 lc %d\n", fits[k].u, fits[k].u,
                k + 1);
    }
    fprintf(mem,
            "set termoption noenhanced\nset title \"%s\"\nset xlabel 'u'\nset ylabel 'mean DSSIM vs reference'\n"
            "set grid\nset logscale x\nset key top left\nplot ",
            title);
    for (int k = 0; k < count; ++k)
        fprintf(mem, "%s$curve%d using 1:2 with linespoints lc %d title 'cone %s (dashed: fitted u)'", k ? ", " : "",
                k, k + 1, so_aperture_name(fits[k].mapping));
    fprintf(mem, "\n");
    fclose(mem);
    int rc = gnuplot_render(script, path, 800, 500, e);
    free(script);
    return rc;
}

int aperture_fit_write_json(const aperture_fit *fit, const char *channel, int exact, const char *path, gt_error *e)
{
    cJSON *j = aperture_fit_json(fit, channel, exact);
    char *text = j ? cJSON_Print(j) : NULL;
    cJSON_Delete(j);
    int rc = text ? atomic_write_text(path, text, e) : gt_error_set(e, path, "out of memory");
    free(text);
    return rc;
}
