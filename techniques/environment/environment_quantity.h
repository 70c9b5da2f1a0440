/* `gtlab render env-diffuse` and `env-specular` (raytracer/
 * environment_quantity.c): the references lit by an environment. They share
 * options with the white-dome quantities: --albedo and --bounces with
 * multibounce, --roughness with specular-occlusion (one option object each,
 * raytracer/shared_options.h), --environment by name (their own object:
 * white, sky, sun or an image file), and own --env-rotate, --env-intensity
 * and (env-specular) --f0. */
#ifndef GTLAB_ENVIRONMENT_ENVIRONMENT_QUANTITY_H
#define GTLAB_ENVIRONMENT_ENVIRONMENT_QUANTITY_H

#include "raytracer/reference_quantity.h"

extern const reference_quantity_descriptor reference_quantity_env_diffuse, reference_quantity_env_specular;

#endif
