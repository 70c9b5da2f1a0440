/* Ambient occlusion and bent normals (DESIGN.md "Definitions"):
 *   V_d   = (1/pi)  \int_Omega V(w) (n.w) dw   cosine-weighted AO  -> ao.V
 *   V_u   = (1/2pi) \int_Omega V(w) dw          uniform AO          -> ao.Vuniform
 *   bent  = normalize( \int_Omega V(w) w (n.w) dw )                 -> bent.X/Y/Z
 * Each sample traces two occlusion rays: one cosine-distributed about the
 * shading normal (estimating V_d with weight V, the bent normal with V w) and
 * one uniform (estimating V_u with weight V). Sharing one direction would
 * give V_u the weight V / (2 n.w), whose variance diverges at the horizon.
 * A direction below the geometric surface (possible when the shading normal
 * tilts away from it) counts as occluded: the surface itself blocks it. */
#ifndef GTLAB_RAYTRACER_AO_INTEGRATOR_H
#define GTLAB_RAYTRACER_AO_INTEGRATOR_H

#include "raytracer/render_loop.h"

typedef struct {
    float max_distance; /* V = 1 beyond it; INFINITY for none */
} ao_settings;

integrator ao_integrator(const embree_scene *es, const ao_settings *settings);

#endif
