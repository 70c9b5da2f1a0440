/* The GGX LTC table as files: fitted (ltc_fit.h) and written
 * (ltc_ggx_writers.h) in one call, for `gtlab lut ltc` and the sphere-light
 * stage (which writes it under <output>/luts/ and scores it beside the
 * talks' sphere lights: sphere_light/sphere_light_study.h). */
#ifndef GTLAB_LTC_LTC_STUDY_H
#define GTLAB_LTC_LTC_STUDY_H

#include "core/error.h"
#include "ltc/ltc_ggx.h"

/* Fits a size^2 LTC table (ltc_fit_table, `threads` workers) into *t and
 * writes DIR/ltc_ggx.{exr,h,hlsl,glsl} (ltc_ggx_write_all, C and shader
 * identifier LTC_GGX); *seconds: the fit's wall time. On failure t is left
 * empty. */
int ltc_table_fit_and_write(const char *dir, int size, int threads, ltc_table *t, double *seconds, gt_error *e);

#endif
