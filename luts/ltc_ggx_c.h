/* The C dialect in which luts/ltc_ggx.c compiles luts/dfg_lut.inc's
 * bilinear lookup for the LTC table (luts/ltc_ggx.h): one channel of the
 * interleaved table at a time, in float, as luts/dfg_lut_c.h does for the
 * DFG table. Include it in no file that includes luts/dfg_lut_c.h. */
#ifndef GTLAB_LUTS_LTC_GGX_C_H
#define GTLAB_LUTS_LTC_GGX_C_H

#include <math.h>
#include <stddef.h>

#include "luts/ltc_ggx.h"

#define DFG_FN static inline
#define dfg_floor floorf
#define dfg_float(i) ((float)(i))
#define dfg_int(x) ((int)(x))

typedef float dfg_value;
typedef struct {
    const ltc_table *lut;
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
    return t.lut->data[((size_t)j * t.lut->size + i) * LTC_CHANNELS + t.channel];
}

#endif
