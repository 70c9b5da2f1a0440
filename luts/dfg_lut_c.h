/* The C dialect of luts/dfg_lut.inc: what its primitives mean when
 * luts/dfg_lut.c compiles it for dfg_lut_sample, one channel of the
 * interleaved table at a time, in float, with C's fminf/fmaxf clamp. */
#ifndef GTLAB_LUTS_DFG_LUT_C_H
#define GTLAB_LUTS_DFG_LUT_C_H

#include <math.h>
#include <stddef.h>

#include "luts/dfg_lut.h"

#define DFG_FN static inline
#define dfg_floor floorf
#define dfg_float(i) ((float)(i))
#define dfg_int(x) ((int)(x))

typedef float dfg_value;
/* Channel `channel` (DFG_SCALE, DFG_BIAS, DFG_ALBEDO) of `lut`. */
typedef struct {
    const dfg_lut *lut;
    int channel;
} dfg_table;
typedef struct {
    int i0, i1;
    float w;
} dfg_axis;

static inline float dfg_saturate(float u) { return fminf(fmaxf(u, 0.0f), 1.0f); }
static inline int dfg_table_size(dfg_table t) { return t.lut->size; }
static inline float dfg_texel(dfg_table t, int i, int j)
{
    return t.lut->data[((size_t)j * t.lut->size + i) * DFG_CHANNELS + t.channel];
}

#endif
