/* Writers of the Decima atmosphere LUTs (luts/atmosphere_luts.h), each
 * carrying atmosphere_luts_description() in its metadata or comment:
 *   <dir>/atmosphere_{inscatter,sun,sky}.exr  float, N0*N1 wide and N2*N3
 *       high (texel order: pixel (v N0 + s, t N2 + y)), channels
 *       CH_ATMOSPHERE_* of core/reference_schema.h, the description in
 *       ATTR_LUT, the sizes in ATTR_LUT_SIZES;
 *   <dir>/atmosphere_luts.h     C arrays ATMOSPHERE_INSCATTER (6 floats a
 *       texel: Rayleigh RGB, Mie RGB), ATMOSPHERE_SUN, ATMOSPHERE_SKY (3) and
 *       their sizes;
 *   <dir>/atmosphere_luts.hlsl, .glsl  the arrays as float3/vec3 and
 *       AtmosphereInscatterRayleigh/Mie(theta_s, theta_v, y, t),
 *       AtmosphereSun/Sky(theta_s, y, t): the text of luts/atmosphere_luts.inc
 *       behind a few definitions, the same lookup as atmosphere_lut_*.
 * All written atomically; the same tables give byte-identical files. */
#ifndef GTLAB_LUTS_ATMOSPHERE_LUTS_WRITERS_H
#define GTLAB_LUTS_ATMOSPHERE_LUTS_WRITERS_H

#include "core/error.h"
#include "luts/atmosphere_luts.h"

/* The text of luts/atmosphere_luts.inc, embedded by the build. */
extern const char atmosphere_luts_inc_text[];

int atmosphere_luts_write_exr(const char *dir, const atmosphere_luts *luts, gt_error *e);
int atmosphere_luts_write_c_header(const char *path, const atmosphere_luts *luts, gt_error *e);
int atmosphere_luts_write_shader(const char *path, int glsl, const atmosphere_luts *luts, gt_error *e);
/* All of them into dir. */
int atmosphere_luts_write_all(const char *dir, const atmosphere_luts *luts, gt_error *e);

#endif
