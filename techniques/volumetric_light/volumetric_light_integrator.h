/* `gtlab render volumetric-light`: the radiance a shadowed spot or point light
 * scatters once towards the camera through a homogeneous medium, along each
 * camera ray up to the first surface (issue 29; the lights, medium and
 * integrand in core/optics/volumetric_light.h, the two integrators in
 * techniques/volumetric_light/volumetric_light_integral.h). Channels (core/reference_schema.h):
 *
 *   vlight.L.R/G/B   the in-scattered radiance, with .stderr:
 *                      quadrature   adaptive gk15 in the equiangular angle,
 *                                   the same in every sample; its error
 *                                   estimate in vlight_quadrature_error.R/G/B
 *                      monte-carlo  equiangular sampling, one shadow ray per
 *                                   sample
 *
 * A surface's own radiance is not rendered (the talk adds the volume light on
 * top of the lit scene: "additive effect"). Pixels whose primary ray misses
 * the scene are not sampled (the shared loop samples surfaces).
 *
 * Where the light is: the settings' position and target, or, without them, a
 * placement relative to the scene's bounds lo..hi (e = hi - lo): position
 * lo + (0.15, 0.9, 1.6) e, target lo + (0.6, 0, 0.3) e, intensity |e|^2,
 * extinction 1 / |e|. In builtin:cornell that is a spot in front of the open
 * box, high and to the left, outside the camera's view (its 1/r^2 peak is not
 * on screen), aimed into the box across the blocks, whose shadows cut shafts. */
#ifndef GTLAB_VOLUMETRIC_LIGHT_VOLUMETRIC_LIGHT_INTEGRATOR_H
#define GTLAB_VOLUMETRIC_LIGHT_VOLUMETRIC_LIGHT_INTEGRATOR_H

#include "core/error.h"
#include "core/statistics/mc_film.h"
#include "raytracer/reference_quantity.h"
#include "raytracer/render_loop.h"
#include "volumetric_light/volumetric_light_integral.h"

typedef enum { VLIGHT_QUADRATURE = 0, VLIGHT_MONTE_CARLO } volumetric_light_method;

/* The settings of `gtlab render volumetric-light` (reference_request.settings;
 * their header names reference_quantity_volumetric_light, the quantity of
 * volumetric_light_quantity.c). */
typedef struct {
    reference_settings header;
    volumetric_light_kind kind;
    volumetric_light_method method;
    int has_placement;      /* 1: position and target below; 0: from the scene's bounds */
    vec3 position, target;
    double outer_deg, inner_deg; /* spot half-angles */
    double intensity;            /* [W/sr], grey; <= 0: |e|^2 */
    double sigma_t, albedo, g;   /* sigma_t <= 0: 1 / |e|; sigma_s = albedo sigma_t */
    int no_shadows;
    double rel_tol;              /* quadrature tolerance, relative to the integral's bound */
} volumetric_light_settings;

/* The defaults: spot of half-angles 30 and 20 degrees, albedo 0.8, g 0.3,
 * placement, intensity and extinction from the bounds, rel_tol 1e-5; the
 * header names no quantity (a render sets it). */
void volumetric_light_settings_default(volumetric_light_settings *s);

extern const reference_quantity_descriptor reference_quantity_volumetric_light;

enum { VLIGHT_QUANTITIES = 6 };

typedef struct {
    volumetric_light light;
    volumetric_medium medium;
    volumetric_lighting lighting;
    volumetric_light_method method;
    double rel_tol;
    vec3 eye;
    int quantity_count;
    mc_quantity quantities[VLIGHT_QUANTITIES];
} volumetric_light_plan;

/* The light and medium of the settings in a scene of bounds lo..hi. */
int volumetric_light_resolve(const volumetric_light_settings *s, vec3 lo, vec3 hi, volumetric_light *light,
                             volumetric_medium *medium, gt_error *e);
/* Builds the plan; -1 with e naming "volumetric-light" when a setting is bad. */
int volumetric_light_plan_init(volumetric_light_plan *plan, const volumetric_light_settings *s,
                               const embree_scene *es, vec3 lo, vec3 hi, vec3 eye, gt_error *e);
integrator volumetric_light_integrator(const embree_scene *es, const volumetric_light_plan *plan);

const char *volumetric_light_method_name(volumetric_light_method m);
/* "quadrature" / "monte-carlo" -> m; -1 if unknown. */
int volumetric_light_method_parse(const char *name, volumetric_light_method *m);

#endif
