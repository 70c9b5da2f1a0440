/* `gtlab render env-diffuse` and `env-specular` (environment_quantity.c):
 * the references lit by an environment. They share options by name with the
 * white-dome quantities, each its own object parsing into their settings
 * (environment_light.h): --albedo and --bounces with multibounce,
 * --roughness and --environment (white, sky, sun or an image file) with
 * specular-occlusion; and own --env-rotate, --env-intensity and
 * (env-specular) --f0. */
#ifndef GTLAB_ENVIRONMENT_ENVIRONMENT_QUANTITY_H
#define GTLAB_ENVIRONMENT_ENVIRONMENT_QUANTITY_H

#include "raytracer/reference_quantity.h"

extern const reference_quantity_descriptor reference_quantity_env_diffuse, reference_quantity_env_specular;

#endif
