/* The settings of `gtlab render multibounce` and `heightfield-multibounce`
 * (multibounce_quantity.c): one struct for both, its header naming the one
 * rendered (reference_quantity.h). A caller of reference_render points
 * `.settings` at its header:
 *
 *   multibounce_render_settings mb = {{QUANTITY_MULTIBOUNCE}, {.albedo_count = 1, .albedos = {0.5f}, .bounces = 4}};
 *   reference_request req = {.quantity = QUANTITY_MULTIBOUNCE, ..., .settings = &mb.header}; */
#ifndef GTLAB_RAYTRACER_MULTIBOUNCE_QUANTITY_H
#define GTLAB_RAYTRACER_MULTIBOUNCE_QUANTITY_H

#include "raytracer/multibounce_integrator.h"
#include "raytracer/reference_render.h"

typedef struct {
    reference_settings header;
    multibounce_settings multibounce; /* albedos, bounces */
} multibounce_render_settings;

/* rq's albedos and bounces when its settings are multibounce's or
 * heightfield-multibounce's, else NULL. */
multibounce_settings *multibounce_settings_of(const reference_request *rq);

#endif
