/* Spherical-Gaussian specular occlusion (Unity HDRP); see the header for
 * the lobes and the product integral. */
#include "specular_occlusion/specular_occlusion_sg.h"

#include "core/optics/shared_math_c.h"
#include "core/optics/spherical_gaussian.h"

/* The lobes' sharpnesses, their inner product and V_s, the text the
 * shaders embed too. */
#include "specular_occlusion/specular_occlusion_sg.inc"
