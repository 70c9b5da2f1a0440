/* The C meaning of the dialect in which core/optics/spherical_caps.inc,
 * core/optics/spherical_gaussian.inc, specular_occlusion/specular_occlusion.inc and
 * specular_occlusion/specular_occlusion_sg.inc are written (the common subset of C, HLSL
 * and GLSL): C computes in double, with the library's fmin/fmax/fabs; the
 * shaders that embed the same text define the same names for float
 * (specular_occlusion/specular_occlusion_shader.c). */
#ifndef GTLAB_CORE_OPTICS_SHARED_MATH_C_H
#define GTLAB_CORE_OPTICS_SHARED_MATH_C_H

#include <math.h>

#include "core/vec3.h" /* M_PI */

#define sc_real double
#define SC_LOCAL static /* a helper of one file: no linkage in C, plain in a shader */
#define SC_PI M_PI
#define sc_min fmin
#define sc_max fmax
#define sc_abs fabs
#define sc_expm1 expm1

#endif
