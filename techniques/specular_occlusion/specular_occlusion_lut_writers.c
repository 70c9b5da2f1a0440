/* The GTSO table's JSON description (specular_occlusion_lut_writers.h). */
#include "specular_occlusion/specular_occlusion_lut_writers.h"

#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/files/atomic_file.h"
#include "core/progress.h"
#include "luts/lut_writers.h"

int so_lut_write_json(const char *path, const so_lut *lut, double seconds, int points, double max_interp,
                      double rms_interp, gt_error *e)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "table", "specular-occlusion");
    cJSON_AddStringToObject(o, "lobe", so_lobe_name(lut->lobe));
    cJSON_AddNumberToObject(o, "size", lut->size);
    cJSON_AddStringToObject(o, "axes", so_lut_axes_name(lut->axes));
    cJSON_AddStringToObject(o, "layout", so_lut_axes_description(lut->axes));
    cJSON_AddNumberToObject(o, "max_quadrature_error_estimate", lut->max_error_estimate);
    cJSON_AddNumberToObject(o, "interpolation_points", points);
    cJSON_AddNumberToObject(o, "max_interpolation_error", max_interp);
    cJSON_AddNumberToObject(o, "rms_interpolation_error", rms_interp);
    cJSON_AddNumberToObject(o, "seconds", seconds);
    char *text = cJSON_Print(o);
    cJSON_Delete(o);
    int rc = text ? atomic_write_text(path, text, e) : gt_error_set(e, path, "out of memory");
    free(text);
    return rc;
}

int so_lut_make(const char *dir, int size, so_lobe lobe, so_lut_axes axes, int threads, int points, so_lut_made *out,
                gt_error *e)
{
    double start = seconds_now();
    so_lut lut;
    if (so_lut_build(&lut, size, lobe, axes, threads) != 0)
        return gt_error_set(e, "lut specular-occlusion", "out of memory");
    out->seconds = seconds_now() - start;
    out->max_error_estimate = lut.max_error_estimate;
    so_lut_interpolation_error(&lut, points, 1u, threads, &out->max_interp, &out->rms_interp);
    char identifier[128], path[4096], description[1024];
    snprintf(out->base, sizeof out->base, "specular_occlusion_%s_%d", so_lobe_name(lobe), size);
    snprintf(identifier, sizeof identifier, "gtlab_specular_occlusion_%s_%d",
             lobe == SO_LOBE_GGX_D ? "ggx_d" : so_lobe_name(lobe), size);
    snprintf(description, sizeof description, "GTSO cone/lobe specular occlusion, lobe %s (at n = v = R), size %d, axes %s: %s",
             so_lobe_name(lobe), size, so_lut_axes_name(axes), so_lut_axes_description(axes));
    snprintf(path, sizeof path, "%s/%s.json", dir, out->base);
    int rc = lut_write_all(dir, out->base, identifier, lut.data, size, description, e) != 0 ||
                     so_lut_write_json(path, &lut, out->seconds, points, out->max_interp, out->rms_interp, e) != 0
                 ? -1
                 : 0;
    so_lut_free(&lut);
    return rc;
}
