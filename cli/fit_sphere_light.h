/* The files of the sphere-light refit (studies/sphere_light.h,
 * sphere_fit_study): JSON, C header, HLSL and GLSL. Used by `gtlab fit
 * sphere-light` and the sphere-light stage of `gtlab all`. */
#ifndef GTLAB_CLI_FIT_SPHERE_LIGHT_H
#define GTLAB_CLI_FIT_SPHERE_LIGHT_H

#include "core/error.h"
#include "studies/sphere_light.h"

/* Whether json_path and the C header beside it can be written (before the
 * fit runs). */
int sphere_fit_check_writable(const char *json_path, gt_error *e);

/* Writes json_path plus the C header, HLSL and GLSL beside it (same name,
 * extensions .h, .hlsl, .glsl). */
int sphere_fit_write(const sphere_fit_settings *s, const sphere_fit_outcome *o, const char *json_path, gt_error *e);

#endif
