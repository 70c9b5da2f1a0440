/* The best-fit normals table (best_fit_normals/best_fit_normals.h) as an engine ships
 * it: <base>.exr (float t, channel CH_BEST_FIT_SCALE), <base>.png (8 bits:
 * the code round(255 t), exact since t = k / 255), <base>.h (the codes as a
 * C array) and <base>.hlsl (the talk's CompressNormalToUnsignedGBuffer over
 * the texture, with point sampling, and the decode, a normalisation). */
#ifndef GTLAB_BEST_FIT_NORMALS_WRITERS_H
#define GTLAB_BEST_FIT_NORMALS_WRITERS_H

#include "core/error.h"

/* Writes <dir>/<base>.{exr,png,h,hlsl}; description names the metric and size. */
int bfn_table_write_all(const char *dir, const char *base, const float *table, int size, const char *description,
                        gt_error *e);

#endif
