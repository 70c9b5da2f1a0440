/* `gtlab render multibounce` and `heightfield-multibounce`
 * (multibounce_quantity.c): their descriptors, and their settings, one
 * struct for both, its header naming the one rendered
 * (raytracer/reference_quantity.h). A caller of reference_render points
 * `.settings` at its header:
 *
 *   multibounce_render_settings mb = {{QUANTITY_MULTIBOUNCE}, {.albedo_count = 1, .albedos = {0.5f}, .bounces = 4}};
 *   reference_request req = {.quantity = QUANTITY_MULTIBOUNCE, ..., .settings = &mb.header}; */
#ifndef GTLAB_MULTIBOUNCE_MULTIBOUNCE_QUANTITY_H
#define GTLAB_MULTIBOUNCE_MULTIBOUNCE_QUANTITY_H

#include "multibounce/multibounce_integrator.h"
#include "raytracer/reference_render.h"

extern const reference_quantity_descriptor reference_quantity_multibounce, reference_quantity_heightfield_multibounce;
#define QUANTITY_MULTIBOUNCE (&reference_quantity_multibounce)
#define QUANTITY_HEIGHTFIELD_MULTIBOUNCE (&reference_quantity_heightfield_multibounce)

typedef struct {
    reference_settings header;
    multibounce_settings multibounce; /* albedos, bounces */
} multibounce_render_settings;

/* rq's albedos and bounces when its settings are multibounce's or
 * heightfield-multibounce's, else NULL. */
multibounce_settings *multibounce_settings_of(const reference_request *rq);

#endif
