/* V_s with the visibility replaced by a cone, at the actual view: the
 * function GTSO's 3-D cone/lobe table approximates (issue 26, items 1 and 5):
 *
 *   V_s^cone(v, b, a_v, alpha) = \int_{cone(b, a_v)} f_r(v, l) (n.l) dl
 *                              / \int_{H(n)}        f_r(v, l) (n.l) dl
 *
 * in the local frame of the shading normal (n = +z), f_r the GGX BRDF
 * without Fresnel (core/optics/ggx.h), cone(b, a_v) the directions within a_v of the
 * unit axis b (the bent normal). Against the reference V_s (the same ratio
 * with the real visibility) its error is that of the visibility cone alone;
 * the 3-D table differs from it by its lobe taken at normal incidence (the
 * dropped view dimension: the table has no n.v) and its interpolation.
 *
 * Estimated by the reference's own sampling (l the mirror of v about a
 * visible normal, Heitz 2018; weight G2/G1) on a strata x strata grid, one
 * point per stratum placed by a hash of the stratum and `seed` (stratified
 * jittered sampling: each point uniform in its stratum). The numerator and
 * denominator share the samples (a ratio estimator, as the reference's).
 * Deterministic for a seed; give each pixel its own seed so that the
 * estimates' errors do not repeat across pixels. At 24 x 24 the error is a
 * few 1e-3, an order below a 128-spp reference's noise (tests). */
#ifndef GTLAB_SPECULAR_OCCLUSION_CONE_VISIBILITY_VIEW_H
#define GTLAB_SPECULAR_OCCLUSION_CONE_VISIBILITY_VIEW_H

#include <stdint.h>

#include "core/vec3.h"

/* v: unit view direction with v.z > 0 (local frame); axis: unit cone axis;
 * cos_av: cosine of the cone's half-angle; alpha = roughness^2. Returns the
 * ratio (1 when the denominator's estimate is 0). */
double so_cone_visibility_view(vec3 v, vec3 axis, double cos_av, double alpha, int strata, uint32_t seed);

#endif
