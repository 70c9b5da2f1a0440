/* `gtlab render sphere-light` (sphere_light_quantity.c): the quantity and
 * its settings, the light (sphere_light_integrator.h). */
#ifndef GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_QUANTITY_H
#define GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_QUANTITY_H

#include "raytracer/reference_render.h"
#include "sphere_light/sphere_light_integrator.h"

extern const reference_quantity_descriptor reference_quantity_sphere_light;
#define QUANTITY_SPHERE_LIGHT (&reference_quantity_sphere_light)

/* The quantity's settings (reference_request.settings). */
typedef struct {
    reference_settings header; /* names reference_quantity_sphere_light */
    sphere_light_settings light;
} sphere_light_quantity_settings;

/* The settings of a render of that light (point the request's settings at
 * .header). */
sphere_light_quantity_settings sphere_light_quantity_settings_of(sphere_light_settings light);

#endif
