/* The C dialect of atmosphere/atmosphere_luts.inc: one channel of one table of an
 * atmosphere_luts, in float, with C's fminf/fmaxf clamp. */
#ifndef GTLAB_ATMOSPHERE_LUTS_C_H
#define GTLAB_ATMOSPHERE_LUTS_C_H

#include <math.h>
#include <stddef.h>

#include "atmosphere/atmosphere_luts.h"

#define ATMO_FN static inline
#define atmo_floor floorf
#define atmo_float(i) ((float)(i))
#define atmo_int(x) ((int)(x))

typedef float atmo_value;
/* Channel `channel` (in-scatter: species * 3 + c) of table `table`. */
typedef struct {
    const atmosphere_luts *luts;
    int table, channel;
} atmo_table;
typedef struct {
    int i0, i1;
    float w;
} atmo_axis;

static inline float atmo_saturate(float u) { return fminf(fmaxf(u, 0.0f), 1.0f); }

static inline const int *atmo_sizes(atmo_table t)
{
    return t.table == ATMOSPHERE_TABLE_INSCATTER ? t.luts->sizes.inscatter
                                                 : t.table == ATMOSPHERE_TABLE_SUN ? t.luts->sizes.sun
                                                                                   : t.luts->sizes.sky;
}
static inline int atmo_size(atmo_table t, int axis) { return atmo_sizes(t)[axis]; }
static inline float atmo_max(atmo_table t, int axis)
{
    return axis == 0 ? (float)ATMOSPHERE_LUT_THETA_S_MAX
                     : axis == 1 ? (float)ATMOSPHERE_LUT_THETA_V_MAX : (float)t.luts->max_altitude;
}
static inline float atmo_texel(atmo_table t, int s, int v, int y, int w)
{
    const int *n = atmo_sizes(t);
    size_t texel = (((size_t)w * n[2] + y) * n[1] + v) * n[0] + s;
    int per_texel = t.table == ATMOSPHERE_TABLE_INSCATTER ? 6 : 3;
    return t.luts->table[t.table][texel * per_texel + t.channel];
}

#endif
