/* The ambient combinations of environment/environment_approx.h as a screen pass: from
 * the G-buffer and AO / bent-normal buffers a shader has (the buffers of
 * specular_occlusion/specular_occlusion_screen.h, plus the albedo) into RGB images,
 * one float plane per channel, 0 outside the mask.
 *
 *   v = normalize(eye - P),  R = 2 (n.v) n - v,  n.v clamped to >= 0;
 *   the bent normal normalised (n where it is zero);
 *   V_s of a specular-occlusion variant from so_approx_pixel on the
 *   so_pixel_inputs of the same buffers (so_inputs_compute). */
#ifndef GTLAB_ENVIRONMENT_ENVIRONMENT_SCREEN_H
#define GTLAB_ENVIRONMENT_ENVIRONMENT_SCREEN_H

#include "environment/environment_approx.h"
#include "specular_occlusion/specular_occlusion_screen.h"

/* Diffuse outgoing radiance per unit albedo of one kind into out[3] (planes
 * of width x height). */
void environment_screen_diffuse(const environment_lighting *l, environment_irradiance_source s, environment_diffuse_kind k,
                               const so_screen_buffers *b, const float *const albedo[3], float *const out[3]);

/* Specular outgoing radiance, the split sum with F0 f0 (grey) times the
 * variant's V_s (v NULL: unoccluded, V_s = 1), at the roughness of `in`. */
void environment_screen_specular(const environment_lighting *l, const so_screen_buffers *b, const so_pixel_inputs *in,
                                vec3 eye, double f0, const so_variant *v, float *const out[3]);

#endif
