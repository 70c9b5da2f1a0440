/* The C dialect of sphere_light/sphere_light.inc: what its primitives mean when
 * sphere_light/sphere_light.c compiles it. Visibility and Fresnel come from
 * core/ (ggx_smith_g2 in double, as the C has always computed them), unless
 * SPHERE_LIGHT_SHADER is defined (the test that compiles the shaders' own
 * versions as C). */
#ifndef GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_C_H
#define GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_C_H

#include <float.h>
#include <math.h>
#include <stdbool.h>

#include "core/optics/fresnel.h"
#include "core/optics/ggx.h"
#include "sphere_light/sphere_light.h"

/* Always inlined, so that sphere_noh_squared_karis and _decima are each one
 * straight function whose instructions `gtlab bench sphere-light` counts. */
#define SL_FN static inline __attribute__((always_inline))
#define SL_FLT_MIN FLT_MIN
#define SL_PI ((float)M_PI)
#define sl_sqrt sqrtf
#define sl_spec float
#define sl_spec_of(x) (x)

/* A shader's max and saturate are one instruction each; C's fmaxf/fminf
 * are library calls (their NaN rules), which would distort the cost
 * measured by `gtlab bench sphere-light`. */
static inline float sl_max(float a, float b) { return a > b ? a : b; }
static inline float sl_saturate(float x) { return x < 0.0f ? 0.0f : x > 1.0f ? 1.0f : x; }

#ifndef SPHERE_LIGHT_SHADER
/* G2 / (4 n.l n.v) in double (core/optics/ggx.h). */
static inline float sl_ggx_visibility(float n_dot_v, float n_dot_l, float alpha)
{
    return (float)(ggx_smith_g2(n_dot_v, n_dot_l, alpha) / (4.0 * (double)n_dot_l * n_dot_v));
}
#define sl_fresnel_schlick fresnel_schlick
#endif

#endif
