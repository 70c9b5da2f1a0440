/* Quantity options that quantities of other techniques list too (one object
 * each, reference_quantity.h): --albedo and --bounces of multibounce
 * (multibounce_quantity.c), --roughness of specular-occlusion
 * (specular_occlusion_quantity.c), which env-diffuse and env-specular share
 * (techniques/environment). Their values go to reference_request's fields
 * (multibounce, roughness) until those quantities own settings structs
 * (docs/render-quantities.md). */
#ifndef GTLAB_RAYTRACER_SHARED_OPTIONS_H
#define GTLAB_RAYTRACER_SHARED_OPTIONS_H

#include "raytracer/reference_quantity.h"

extern const reference_option reference_option_albedo, reference_option_bounces, reference_option_roughness;

#endif
