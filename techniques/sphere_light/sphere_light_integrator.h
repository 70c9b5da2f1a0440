/* The sphere-light reference on a scene (DESIGN.md "GGX sphere light"):
 * radiance leaving each G-buffer surface towards the camera, lit by a
 * uniform spherical emitter, integrated exactly over the light's solid
 * angle with the parameter-space reference's MIS sample
 * (techniques/sphere_light/sphere_light_reference.h), unshadowed by default (the
 * real-time approximations have no shadows); with `shadows`, each direction
 * that carries light is weighted by an Embree occlusion ray from the lifted
 * surface point to the light's surface (the light itself is not geometry).
 * Material: glTF metallic-roughness, a
 * Lambert lobe of colour base (1 - metallic) plus GGX (alpha = roughness^2,
 * height-correlated Smith) with Schlick Fresnel of F0 = mix(0.04, base,
 * metallic) evaluated per light direction inside the integral. Directions
 * below the shading surface contribute 0, specular ones below the geometric
 * surface too. Unshadowed, no rays are traced.
 *
 * Channels: sphere.R, sphere.G, sphere.B (quantity 0 drives the stop rule).
 * Sampling: the cap technique uses dimension pair 0, the BRDF technique
 * pair 1. */
#ifndef GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_INTEGRATOR_H
#define GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_INTEGRATOR_H

#include "raytracer/render_loop.h"

typedef struct {
    vec3 position;  /* the light's centre, world space */
    float radius;   /* > 0 */
    float radiance; /* emitted radiance L_e > 0 (white) */
    int shadows;    /* 1: occluders in the scene block the light */
} sphere_light_settings;

typedef struct {
    sphere_light_settings light;
    vec3 eye; /* the camera's position: v = normalize(eye - p) (pinhole) */
    mc_quantity quantities[3];
} sphere_light_plan;

/* Validates the light (errors name "sphere-light") and sets the channels'
 * scale exponent from the largest normal illuminance the scene can see. */
int sphere_light_plan_init(sphere_light_plan *plan, const sphere_light_settings *light, const scene *s, vec3 eye,
                           gt_error *e);

/* The settings as header text. */
void sphere_light_settings_text(const sphere_light_settings *light, char *text, size_t size);

/* The integrator; `plan` must outlive it. */
integrator sphere_light_integrator(const embree_scene *es, const sphere_light_plan *plan);

#endif
