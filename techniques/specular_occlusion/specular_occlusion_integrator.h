/* Specular occlusion references (DESIGN.md "Definitions"; the GTSO half of
 * Jimenez et al. 2016, "Practical Realtime Strategies for Accurate Indirect
 * Occlusion", slides "Ground Truth Specular Occlusion"):
 *
 *   V_s   = \int V f_r cos / \int f_r cos          -> specocc.V   (GTSO)
 *   V_s^D = \int V D(h) cos / \int D(h) cos        -> specocc_d.V (the talk's
 *                                                    older, D-only definition)
 *   V_s^P = the same with Phong's D_p (core/optics/phong.h) -> specocc_phong.V (the
 *                                                    talk's Phong comparisons)
 *
 * with f_r the GGX BRDF without Fresnel (core/optics/ggx.h), alpha = roughness^2,
 * the roughness from the glTF material (G-buffer roughness.Y) or one value
 * for every surface, and the view direction pointing to the camera. The
 * numerators and denominators are written too: specocc_occluded.V and
 * specocc_unoccluded.V are \int V f_r cos and \int f_r cos (the directional
 * albedo under a white dome of radiance 1), specocc_d_occluded.V and
 * specocc_d_unoccluded.V the same with D(h) in place of f_r.
 *
 * Sampling: l is the mirror of v about a visible normal m ~ D_v (Heitz
 * 2018), pdf(l) = G1(v) D(h) / (4 n.v). The weights are then
 *   f_r cos / pdf  = G2(v, l) / G1(v)                  in [0, 1]
 *   D cos / pdf    = 4 (n.v)(n.l) / G1(v)               in [0, 4]
 *   D_p cos / pdf  = (D cos / pdf) D_p(h) / D(h)       in [0, 4 * 4/e]
 * (D_p / D peaks at (1 + x)^2 e^-x <= 4/e with x = tan^2 theta_h / alpha^2:
 * GGX's heavier tails cover the Phong lobe)
 * (both 0 when l falls below the surface), and one occlusion ray per sample
 * serves both definitions.
 *
 * Ratio and its standard error: numerator N and denominator D are estimated
 * from the same samples, and V_s = mean(N) / mean(D) (a ratio estimator:
 * consistent, with a bias of order 1/n far below its standard error). Its
 * standard error is the delta method's
 *   se(R)^2 = (se_N^2 - 2 R cov(N, D) + R^2 se_D^2) / mean(D)^2,
 * where the covariance of the means comes from a third accumulated quantity,
 * the blocked part B = D - N = (1 - V) w (specocc_blocked.V):
 *   cov(N, D) = (se_N^2 + se_D^2 - se_B^2) / 2.
 * All three are exact sums (core/statistics/mc_film.h), so merge and the even/odd noise
 * floor work on them; the ratio channels are derived from them on output.
 *
 * Split integrals (slides "Two Split", "Three Split"), with an environment
 * L (core/optics/sky_environment.h; settings.environment = ENVIRONMENT_SKY) from
 * the same samples and rays, all exact sums:
 *   split_truth.V             \int V L f_r cos         (the ground truth, with
 *                                                     its .stderr)
 *   split_env_d_occluded.V    \int V L D cos
 *   split_env_d_unoccluded.V  \int L D cos
 * and derived on output from the means (no standard error: their noise is
 * measured by the even/odd noise floor of split_truth.V):
 *   split_two.V   = [\int* V L D cos] \int f_r cos          (two-split)
 *   split_three.V = [\int* V D cos][\int* L D cos] \int f_r cos (three-split)
 * where \int* is normalised by \int D cos. The integrals are over the
 * actual view and normal (no n = v = R assumption): what is measured is the
 * error of splitting the integral, nothing else.
 *
 * The view direction may fall below the shading normal's horizon (shading
 * normals that disagree with the geometry); it is then moved onto the
 * horizon and lifted by 1e-4 so the sampler is defined. Directions below the
 * geometric surface count as occluded, as for AO. A pixel whose denominator
 * is 0 gets V_s = 0 with standard error 0. */
#ifndef GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_INTEGRATOR_H
#define GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_INTEGRATOR_H

#include "core/image.h"
#include "core/optics/sky_environment.h"
#include "raytracer/render_loop.h"

typedef struct {
    float roughness;      /* perceptual roughness for every surface; < 0: the glTF material's */
    vec3 camera_position; /* the view vector points from the surface to here */
    environment_kind environment; /* ENVIRONMENT_SKY adds the split-integral channels */
} specular_occlusion_settings;

integrator specular_occlusion_integrator(const embree_scene *es, const specular_occlusion_settings *settings);

/* Derives specocc.V, specocc_d.V and specocc_phong.V (+ .stderr), and with
 * the split channels split_two.V and split_three.V, from the
 * accumulated numerator, denominator and blocked-part channels of img (the
 * .stderr channels are optional: without them only the ratio is written, as
 * for the half means of the noise floor). Pixels with mask 0 get 0. */
int specular_occlusion_write_ratios(image *img);

#endif
