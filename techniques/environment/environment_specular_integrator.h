/* GGX specular reflection of an environment (techniques/environment/environment_light.h),
 * with visibility and without, from the same samples (issue 28):
 *
 *   environment_specular.c             \int V(l) L_c(l) f_r(v, l) F_c(v.h) (n.l) dl
 *   environment_specular_unoccluded.c  \int L_c(l) f_r(v, l) F_c(v.h) (n.l) dl
 *
 * f_r core/optics/ggx.h's GGX (height-correlated Smith G2, no Fresnel) with
 * alpha = max(roughness^2, 1e-4) rounded to float (ggx_alpha_phong_cone: a
 * roughness-0 mirror stays a finite lobe; float as specular-occlusion's), the roughness the glTF material's (G-buffer
 * roughness.Y) or --roughness; F_c Schlick's F0_c + (1 - F0_c)(1 - v.h)^5
 * with F0 the glTF material's, 0.04 (1 - metallic) + base colour x metallic,
 * or a grey --f0 (1: no Fresnel, the white specular of specular-occlusion).
 * v points to the camera (moved onto the horizon when a shading normal
 * faces away, as specular-occlusion does); n is the shading normal.
 *
 * Each direction comes from a mixture (the one-sample balance heuristic,
 * core/optics/environment_sampler.h) of visible-normal sampling (Heitz 2018;
 * probability c) and the environment's sampler, chosen by u0 < c as in
 * env-diffuse, with weight
 *   f_r cos / p_mix = (G2 / G1) / (c + (1 - c) p_env / p_vndf)
 * (f_r cos / p_vndf = G2 / G1: stable as the lobe sharpens), 0 when l is
 * below the shading horizon; under a constant environment c = 1 and the
 * weight is G2 / G1. A direction below the geometric surface is blocked.
 * One occlusion ray per sample (dimension pair 0). */
#ifndef GTLAB_ENVIRONMENT_ENVIRONMENT_SPECULAR_INTEGRATOR_H
#define GTLAB_ENVIRONMENT_ENVIRONMENT_SPECULAR_INTEGRATOR_H

#include "environment/environment_light.h"
#include "raytracer/render_loop.h"

enum { ENVIRONMENT_SPECULAR_QUANTITIES = 6 };

typedef struct {
    const environment_light *light;
    float roughness;      /* perceptual, every surface; < 0: the material's */
    float f0;             /* grey, every surface; < 0: the material's */
    vec3 camera_position; /* v points from the surface to here */
    mc_quantity quantities[ENVIRONMENT_SPECULAR_QUANTITIES];
} environment_specular_plan;

/* Validates (roughness and f0 in [0, 1] or < 0; errors name "env-specular")
 * and names the channels. `light` must outlive the plan. */
int environment_specular_plan_init(environment_specular_plan *plan, const environment_light *light,
                                   float roughness, float f0, vec3 camera_position, gt_error *e);

integrator environment_specular_integrator(const embree_scene *es, const environment_specular_plan *plan);

#endif
