/* The GGX (Trowbridge-Reitz) microfacet BRDF that DESIGN.md defines for
 * specular occlusion and sphere lights: alpha = roughness^2, the GGX normal
 * distribution D, Smith's height-correlated masking-shadowing G2, and
 * importance sampling of the distribution of visible normals.
 *
 *   D(m)      = alpha^2 / (pi ((n.m)^2 (alpha^2 - 1) + 1)^2)
 *               (Walter et al. 2007, eq. 33)
 *   Lambda(w) = (-1 + sqrt(1 + alpha^2 tan^2 theta_w)) / 2
 *   G1(w)     = 1 / (1 + Lambda(w))
 *   G2(v, l)  = 1 / (1 + Lambda(v) + Lambda(l))
 *               (Heitz 2014, "Understanding the Masking-Shadowing Function",
 *               eqs. 72, 43 and 99)
 *   f_r(v, l) = D(h) G2(v, l) / (4 |n.v| |n.l|),   h = normalize(v + l)
 *               (Fresnel left to the caller: F = 1 is a white specular)
 *   D_v(m)    = G1(v) max(0, v.m) D(m) / (n.v)     (Heitz 2018, eq. 1)
 *
 * Directions are in the local frame of the surface: n = +z, v and l point
 * away from the surface. Scalars are doubles: LUT generators integrate these
 * functions to high accuracy. */
#ifndef GTLAB_CORE_OPTICS_GGX_H
#define GTLAB_CORE_OPTICS_GGX_H

#include "core/vec3.h"

/* alpha = roughness^2 (perceptual roughness, as glTF's metallic-roughness).
 * Unclamped: the references and the real-time functions take roughness 0
 * as it is. */
double ggx_alpha(double roughness);

/* alpha with a floor, where roughness 0 (a mirror) would break a formula
 * rather than make a sharp lobe. The two floors serve different purposes
 * and are kept apart: one floor for both would change the specular-occlusion
 * LUT's roughness-0 row or the cone apertures at roughness < 0.032. */

/* max(roughness^2, 1e-4): the Phong exponent 2/alpha^2 - 2 of the
 * specular-occlusion cone mappings stays finite (at most 2e8). */
double ggx_alpha_phong_cone(double roughness);

/* max(roughness^2, 1e-3): a lobe integrated by quadrature (the specular-
 * occlusion LUT): below it, cos theta_h near 1 leaves D with fewer than ~10
 * significant digits, and the lobe (width ~2e-3 rad) is a mirror for any
 * table. */
double ggx_alpha_tabulated(double roughness);

/* D(m) given cos theta_m = n.m; 0 for n.m <= 0. */
double ggx_ndf(double cos_m, double alpha);

/* Smith's Lambda and G1 for a direction with cos theta = n.w > 0. */
double ggx_smith_lambda(double cos_w, double alpha);
double ggx_smith_g1(double cos_w, double alpha);

/* Height-correlated G2 for n.v > 0 and n.l > 0. */
double ggx_smith_g2(double cos_v, double cos_l, double alpha);

/* f_r(v, l) without Fresnel; 0 unless both directions are above the surface. */
double ggx_brdf(vec3 v, vec3 l, double alpha);

/* A microfacet normal distributed as D_v(m) for the view direction v
 * (n.v > 0), from a point u in [0, 1)^2: Heitz 2018, "Sampling the GGX
 * Distribution of Visible Normals", listing 1 (isotropic alpha). */
vec3 ggx_sample_visible_normal(vec3 v, double alpha, const float u[2]);

/* D_v(m): the density of ggx_sample_visible_normal, per unit solid angle of m. */
double ggx_visible_normal_pdf(vec3 v, vec3 m, double alpha);

/* The mirror direction of v about m: 2 (v.m) m - v. */
vec3 ggx_reflect(vec3 v, vec3 m);

/* The density of l = ggx_reflect(v, m) with m ~ D_v, per unit solid angle of
 * l: D_v(h) / (4 v.h) with h = normalize(v + l) (Heitz 2018, eq. 17). It
 * integrates to less than 1 over the upper hemisphere: the remainder is the
 * chance that l falls below the surface. */
double ggx_reflection_pdf(vec3 v, vec3 l, double alpha);

/* The Monte Carlo weights of l = ggx_reflect(v, m), m ~ D_v, whose density
 * ggx_reflection_pdf simplifies to G1(v) D(h) / (4 n.v); both are 0 when l is
 * below the surface:
 *   f_r(v, l) (n.l) / pdf = G2(v, l) / G1(v)        in [0, 1]
 *   D(h) (n.l) / pdf      = 4 (n.v)(n.l) / G1(v)    in [0, 4]
 * (n.v / G1(v) = (n.v + sqrt(alpha^2 + (1 - alpha^2)(n.v)^2)) / 2 <= 1). */
double ggx_reflection_weight_brdf(vec3 v, vec3 l, double alpha);
double ggx_reflection_weight_ndf(vec3 v, vec3 l, double alpha);

#endif
