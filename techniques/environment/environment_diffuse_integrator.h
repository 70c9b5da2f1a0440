/* Lambertian surfaces lit by an environment (techniques/environment/environment_light.h),
 * with visibility and inter-reflections: the reference that engines'
 * AO x irradiance approximates (issue 28). What is estimated, per colour
 * channel c, is the outgoing radiance divided by the shading point's
 * albedo, as the white-dome multibounce reference does
 * (techniques/multibounce/multibounce_integrator.h):
 *
 *   environment_diffuse.c            L_c / rho_c, every surface of albedo rho (a grey
 *                            one, or the glTF base colour per channel), with
 *                            --bounces N inter-reflections (or 'inf', Russian
 *                            roulette as multibounce)
 *   environment_diffuse_direct.c     the same, direct light only:
 *                            (1/pi) \int V(w) L_c(w) max(0, n.w) dw
 *   environment_diffuse_unoccluded.c (1/pi) \int L_c(w) max(0, n.w) dw: visibility off
 *
 * (n the shading normal; multiply by the albedo for radiance). All three
 * come from the same directions, so direct / unoccluded is an exact ratio
 * of sums: the occlusion the lighting sees.
 *
 * Paths. At each vertex a direction is drawn from a mixture of cosine
 * sampling (probability c) and the environment's sampler (core/
 * environment_sampler.h): the first coordinate u0 of the vertex's
 * dimension pair chooses (u0 < c), and is rescaled to [0, 1) for the chosen
 * sampler. The path's weight is multiplied by (max(0, n.w) / pi) / p_mix
 * (the one-sample balance heuristic), and at each later vertex by rho as in
 * multibounce; an escaping path adds weight x L(w). A direction with
 * n.w <= 0 (only the environment's sampler draws one) ends the path with
 * nothing; one below the geometric surface is blocked (adds only to the
 * unoccluded channel). Dimension pairs, ray origins, frames, Russian
 * roulette and the wavefront order are multibounce's.
 *
 * Under a constant environment c = 1: every weight is exactly 1, the
 * directions are multibounce's and L = 1 multiplies exactly, so under the
 * white dome environment_diffuse equals multibounce.V (or .R/.G/.B with the scene's
 * albedo) and environment_diffuse_direct equals ao.V, bit for bit at the same seed.
 *
 * Film scale exponent: the light's (environment_light.h). */
#ifndef GTLAB_ENVIRONMENT_ENVIRONMENT_DIFFUSE_INTEGRATOR_H
#define GTLAB_ENVIRONMENT_ENVIRONMENT_DIFFUSE_INTEGRATOR_H

#include "environment/environment_light.h"
#include "multibounce/multibounce_integrator.h"
#include "raytracer/render_loop.h"

enum { ENVIRONMENT_DIFFUSE_QUANTITIES = 9 };

typedef struct {
    const environment_light *light;
    multibounce_settings albedo; /* scene_albedo, or albedo_count = 1; bounces */
    normal_mode normals;
    mc_quantity quantities[ENVIRONMENT_DIFFUSE_QUANTITIES];
} environment_diffuse_plan;

/* Validates the albedo settings (one grey albedo or the scene's; errors
 * name "env-diffuse") and names the channels. `light` must outlive the plan. */
int environment_diffuse_plan_init(environment_diffuse_plan *plan, const environment_light *light,
                                  const multibounce_settings *albedo, normal_mode normals, gt_error *e);

/* The integrator; `plan` must outlive it. */
integrator environment_diffuse_integrator(const embree_scene *es, const environment_diffuse_plan *plan);

#endif
