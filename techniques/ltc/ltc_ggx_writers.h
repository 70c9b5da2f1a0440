/* Writers of the GGX LTC table (ltc/ltc_ggx.h), each carrying
 * ltc_ggx_description() (the axes) in its metadata or comment:
 *   <base>.exr   float, N x N, channels CH_LTC_NAMES (a, b, c, d, E, B) and
 *                CH_LTC_ERROR (the fit's total-variation error per texel;
 *                core/reference_schema.h), description in "gtlab.lut", the
 *                largest fit error in "gtlab.lut.error"
 *   <base>.h     `static const float <identifier>[N*N*6]` and <IDENTIFIER>_SIZE
 *   <base>.hlsl  two arrays of N*N float4, `<identifier>_M` = (a, b, c, d)
 *                and `<identifier>_E` = (E, B, 0, 0) (the two textures of
 *                Heitz's shipped code), and `float4 LTC_INVERSE_M(float nv,
 *                float roughness)`, `float4 LTC_MAGNITUDE_FRESNEL(float nv,
 *                float roughness)`: the bilinear clamp-to-edge fetch at
 *                uv = (sqrt(1 - nv), roughness), i.e. ltc_table_sample,
 *                whose text (luts/table_lookup.inc) it carries
 *   <base>.glsl  the same as GLSL (vec4).
 * All written atomically; the same table gives byte-identical files. */
#ifndef GTLAB_LTC_LTC_GGX_WRITERS_H
#define GTLAB_LTC_LTC_GGX_WRITERS_H

#include "core/error.h"
#include "ltc/ltc_ggx.h"

int ltc_ggx_write_exr(const char *path, const ltc_table *t, gt_error *e);
int ltc_ggx_write_c_header(const char *path, const char *identifier, const ltc_table *t, gt_error *e);
int ltc_ggx_write_hlsl(const char *path, const char *identifier, const ltc_table *t, gt_error *e);
int ltc_ggx_write_glsl(const char *path, const char *identifier, const ltc_table *t, gt_error *e);
/* All four as <dir>/<base>.{exr,h,hlsl,glsl}. */
int ltc_ggx_write_all(const char *dir, const char *base, const char *identifier, const ltc_table *t, gt_error *e);

#endif
