/* `gtlab render specular-occlusion` (specular_occlusion_quantity.c): its
 * descriptor, and its settings, headed by a reference_settings naming it
 * (raytracer/reference_quantity.h). A caller of reference_render points
 * `.settings` at its header:
 *
 *   specular_occlusion_render_settings so = specular_occlusion_render_settings_make(0.4f, ENVIRONMENT_WHITE);
 *   reference_request req = {.quantity = QUANTITY_SPECULAR_OCCLUSION, ..., .settings = &so.header}; */
#ifndef GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_QUANTITY_H
#define GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_QUANTITY_H

#include "core/optics/sky_environment.h"
#include "raytracer/reference_render.h"

extern const reference_quantity_descriptor reference_quantity_specular_occlusion;
#define QUANTITY_SPECULAR_OCCLUSION (&reference_quantity_specular_occlusion)

typedef struct {
    reference_settings header;
    float roughness;              /* a roughness setting (core/roughness_setting.h); default: the material's */
    environment_kind environment; /* white, or sky: adds the split-integral channels */
} specular_occlusion_render_settings;

/* The settings of that roughness and environment, their header naming specular-occlusion. */
specular_occlusion_render_settings specular_occlusion_render_settings_make(float roughness,
                                                                           environment_kind environment);

#endif
