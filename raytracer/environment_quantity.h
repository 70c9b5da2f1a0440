/* `gtlab render env-diffuse` and `env-specular` (raytracer/
 * environment_quantity.c): the references lit by an environment. They share
 * options with the white-dome quantities: --albedo and --bounces with
 * multibounce, --environment and --roughness with specular-occlusion (one
 * option object each, defined there), and own --env-rotate, --env-intensity
 * and (env-specular) --f0. */
#ifndef GTLAB_RAYTRACER_ENVIRONMENT_QUANTITY_H
#define GTLAB_RAYTRACER_ENVIRONMENT_QUANTITY_H

#include "raytracer/reference_quantity.h"

extern const reference_option reference_option_albedo, reference_option_bounces; /* multibounce_quantity.c */
extern const reference_option reference_option_environment,                     /* specular_occlusion_quantity.c */
    reference_option_roughness;

extern const reference_quantity_descriptor reference_quantity_env_diffuse, reference_quantity_env_specular;

/* --environment NAME|FILE for env-diffuse and env-specular: stored in their
 * settings block (environment_render_settings); the file is read by prepare. */
int environment_quantity_parse_environment(struct reference_request *rq, const char *value, gt_error *e);

#endif
