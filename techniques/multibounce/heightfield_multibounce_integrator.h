/* Height-field multi-bounce AO: the multi-bounce reference V'_d
 * (multibounce_integrator.h: Lambertian surfaces of albedo rho
 * under a white dome of radiance 1, L / rho) of the world a screen-space
 * technique sees, the depth buffer as a height field of infinite thickness
 * (techniques/ao/heightfield_ao_integrator.h). A path's rays are blocked where
 * the height-field AO reference blocks them, and a blocked ray goes on from
 * where it enters the height field's solid (heightfield_first_hit): a
 * pixel's surface (its tangent plane and normals), or the side of a pixel's
 * column behind a depth discontinuity (the plane through the eye and the
 * pixel edge), with that pixel's material; a ray that leaves the image or
 * crosses the camera plane escapes. Everything else (directions, albedos, bounces, Russian roulette,
 * the channels and the header) is the 3-D reference's, through the same
 * bounce loop (multibounce_world). So ao.V is the height-field AO reference's
 * estimator (the same rays, up to the origin's offset off the surface) and
 * the pair (ao.V, multibounce*.V) is a ground truth of one world: the one
 * whose visibility screen-space AO estimates.
 *
 * Mathematics it satisfies (techniques/multibounce/tests/test_heightfield_multibounce.c):
 * albedo 0 gives ao.V; every sample lies in [V, V + rho (1 - V)] of its own
 * first ray's V in {0, 1}, so the means do; on a plane V'_d = 1 for any
 * albedo; where the depth buffer is the whole scene (an open box seen from
 * above, every face in view) it agrees with the 3-D reference to within
 * the pixel discretisation of the faces' edges (under a code value at
 * 128^2); tests/raytracer/test_heightfield_thickness.c checks the hits. */
#ifndef GTLAB_MULTIBOUNCE_HEIGHTFIELD_MULTIBOUNCE_INTEGRATOR_H
#define GTLAB_MULTIBOUNCE_HEIGHTFIELD_MULTIBOUNCE_INTEGRATOR_H

#include "ao/heightfield_ao_integrator.h"
#include "multibounce/multibounce_integrator.h"

/* Sets plan's world to the height field of hs (which must outlive the
 * integrator, as plan) and returns the multi-bounce integrator over it; es
 * gives the materials of the scene albedo. */
integrator heightfield_multibounce_integrator(const embree_scene *es, const heightfield_settings *hs,
                                              multibounce_plan *plan);

#endif
