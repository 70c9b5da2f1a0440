/* The C dialect of luts/table_lookup.inc, the bilinear clamp-to-edge lookup
 * of a square table at texel centres: what its primitives mean when C
 * compiles it (luts/dfg_lut.c for dfg_lut_sample, techniques/ltc/ltc_ggx.c for
 * ltc_table_sample), one channel of an interleaved table at a time, in
 * float, with C's fminf/fmaxf clamp. A C file includes this header, then
 * the .inc (the shaders' writers append its text behind their own dialect:
 * luts/table_lookup.h). */
#ifndef GTLAB_LUTS_TABLE_LOOKUP_C_H
#define GTLAB_LUTS_TABLE_LOOKUP_C_H

#include <math.h>
#include <stddef.h>

#define DFG_FN static inline
#define dfg_floor floorf
#define dfg_float(i) ((float)(i))
#define dfg_int(x) ((int)(x))

typedef float dfg_value;
/* Channel `channel` of an interleaved size x size table of `channels`
 * floats per texel: the DFG table (DFG_SCALE, DFG_BIAS, DFG_ALBEDO of
 * DFG_CHANNELS, luts/dfg_lut.h) and the LTC table (techniques/ltc/ltc_ggx.h) alike. */
typedef struct {
    const float *data;
    int size, channels, channel;
} dfg_table;
typedef struct {
    int i0, i1;
    float w;
} dfg_axis;

static inline float dfg_saturate(float u) { return fminf(fmaxf(u, 0.0f), 1.0f); }
static inline int dfg_table_size(dfg_table t) { return t.size; }
static inline float dfg_texel(dfg_table t, int i, int j)
{
    return t.data[((size_t)j * t.size + i) * t.channels + t.channel];
}

#endif
