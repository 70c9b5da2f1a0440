/* Writers for a table of floats in the formats DESIGN.md promises, each
 * carrying `description` (the axes' parametrisation) in its metadata; for a
 * cubic 3-D LUT (size N, value [k][j][i] at data[(k*N + j)*N + i]):
 *   <base>.exr  float, N wide and N*N high (slice k in rows k*N .. k*N+N-1),
 *               channel "lut.V" (CH_LUT), description in attribute "gtlab.lut" (ATTR_LUT)
 *   <base>.png  the same layout quantised linearly to 8 bits (the talk stored
 *               its LUT as 8-bit BC4), description in ImageDescription
 *   <base>.h    a C array `static const float <identifier>[N*N*N]`, the
 *               description in its comment
 * All written atomically. */
#ifndef GTLAB_LUTS_LUT_WRITERS_H
#define GTLAB_LUTS_LUT_WRITERS_H

#include "core/error.h"
#include "core/reference_schema.h"

/* A cubic 3-D LUT of size N, as above. */
int lut_write_all(const char *dir, const char *base, const char *identifier, const float *data, int size,
                  const char *description, gt_error *e);

/* Any table of width x height values (row-major) the same way, e.g. a 1-D
 * table as width x 1: the EXR and PNG are width x height, the header's
 * <identifier>_SIZE is the width and its array holds width * height values. */
int lut_write_table(const char *dir, const char *base, const char *identifier, const float *data, int width,
                    int height, const char *description, gt_error *e);

#endif
