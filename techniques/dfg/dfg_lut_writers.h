/* Writers of the split-sum DFG LUT (luts/dfg_lut.h), each carrying
 * dfg_lut_description() (the axes) in its metadata or comment:
 *   <base>.exr   float, N x N, channels "dfg.A", "dfg.B", "dfg.E" (CH_DFG_*
 *                in core/reference_schema.h), description in "gtlab.lut",
 *                the largest quadrature error estimate in "gtlab.lut.error"
 *   <base>.png   16-bit RGB: R = A, G = B, blue 0 (UE4's R16G16 layout)
 *   <base>.h     `static const float <identifier>[N*N*3]` and <IDENTIFIER>_SIZE
 *   <base>.hlsl  `static const float3 <identifier>[N*N]` and
 *                `float3 DFG(float nv, float roughness)`: the bilinear
 *                clamp-to-edge fetch of dfg_lut_sample, whose text
 *                (luts/table_lookup.inc) it carries behind a few definitions
 *   <base>.glsl  the same as GLSL: `const vec3 <identifier>[N*N]` and
 *                `vec3 DFG(float nv, float roughness)`.
 * Row 0 of the images is the smoothest roughness. All written atomically;
 * the same table gives byte-identical files. */
#ifndef GTLAB_DFG_LUT_WRITERS_H
#define GTLAB_DFG_LUT_WRITERS_H

#include "core/error.h"
#include "luts/dfg_lut.h"

int dfg_lut_write_exr(const char *path, const dfg_lut *lut, gt_error *e);
int dfg_lut_write_png(const char *path, const dfg_lut *lut, gt_error *e);
int dfg_lut_write_c_header(const char *path, const char *identifier, const dfg_lut *lut, gt_error *e);
int dfg_lut_write_hlsl(const char *path, const char *identifier, const dfg_lut *lut, gt_error *e);
int dfg_lut_write_glsl(const char *path, const char *identifier, const dfg_lut *lut, gt_error *e);
/* All five as <dir>/<base>.{exr,png,h,hlsl,glsl}. */
int dfg_lut_write_all(const char *dir, const char *base, const char *identifier, const dfg_lut *lut, gt_error *e);

#endif
