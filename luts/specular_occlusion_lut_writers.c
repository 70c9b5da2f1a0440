/* The GTSO table's JSON description (specular_occlusion_lut_writers.h). */
#include "luts/specular_occlusion_lut_writers.h"

#include <cjson/cJSON.h>
#include <stdlib.h>

#include "core/atomic_file.h"

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
