/* Writers of the Decima atmosphere LUTs (atmosphere/atmosphere_luts.h), each
 * carrying atmosphere_luts_description() in its metadata or comment:
 *   <dir>/atmosphere_{inscatter,sun,sky}.exr  (the linear parametrization;
 *       under another, atmosphere_{inscatter,sun,sky}_<tag>.exr, the tag of
 *       atmosphere_lut_parametrization_tag: yusov2013, bruneton2008) float,
 *       N0*N1 wide and N2*N3 high (texel order: pixel (v N0 + s, t N2 + y)),
 *       channels CH_ATMOSPHERE_* of core/reference_schema.h, the description
 *       (layout and the parametrization's axes) in ATTR_LUT, the sizes in
 *       ATTR_LUT_SIZES, the parametrization's tag in ATTR_LUT_PARAMETRIZATION;
 *   <dir>/atmosphere_luts.h     C arrays ATMOSPHERE_INSCATTER (6 floats a
 *       texel: Rayleigh RGB, Mie RGB), ATMOSPHERE_SUN, ATMOSPHERE_SKY (3) and
 *       their sizes;
 *   <dir>/atmosphere_luts.hlsl, .glsl  the arrays as float3/vec3 and
 *       AtmosphereInscatterRayleigh/Mie(theta_s, theta_v, y, t),
 *       AtmosphereSun/Sky(theta_s, y, t): the text of atmosphere/atmosphere_luts.inc
 *       behind a few definitions, the same lookup as atmosphere_lut_*; linear
 *       only (the nonlinear mappings are C: atmosphere_lut_axes.h).
 * All written atomically; the same tables give byte-identical files. */
#ifndef GTLAB_ATMOSPHERE_LUTS_WRITERS_H
#define GTLAB_ATMOSPHERE_LUTS_WRITERS_H

#include "core/error.h"
#include "atmosphere/atmosphere_luts.h"

/* The text of atmosphere/atmosphere_luts.inc, embedded by the build. */
extern const char atmosphere_luts_inc_text[];

/* The EXR file name of `table` under `kind` ("atmosphere_inscatter_yusov2013.exr"). */
void atmosphere_luts_exr_name(atmosphere_lut_parametrization kind, int table, char *name, size_t size);
int atmosphere_luts_write_exr(const char *dir, const atmosphere_luts *luts, gt_error *e);
/* The three EXRs of `kind` in dir back into luts (the default model, whose
 * radii the mappings use; the files' sizes and texels): the tables as
 * written, bit for bit. -1 with e naming the file (absent, another
 * parametrization, sizes not the image's, a channel missing). */
int atmosphere_luts_read_exr(const char *dir, atmosphere_lut_parametrization kind, atmosphere_luts *luts, gt_error *e);
int atmosphere_luts_write_c_header(const char *path, const atmosphere_luts *luts, gt_error *e);
int atmosphere_luts_write_shader(const char *path, int glsl, const atmosphere_luts *luts, gt_error *e);
/* All of them into dir (linear tables only; another is refused: -1). */
int atmosphere_luts_write_all(const char *dir, const atmosphere_luts *luts, gt_error *e);

#endif
