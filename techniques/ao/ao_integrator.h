/* Ambient occlusion and bent normals (DESIGN.md "Definitions"):
 *   V_d   = (1/pi)  \int_Omega V(w) (n.w) dw   cosine-weighted AO  -> ao.V
 *   V_u   = (1/2pi) \int_Omega V(w) dw          uniform AO          -> ao.Vuniform
 *   bent  = normalize( \int_Omega V(w) w (n.w) dw )                 -> bent.X/Y/Z
 * Each sample traces two occlusion rays: one cosine-distributed about the
 * shading normal (estimating V_d with weight V, the bent normal with V w) and
 * one uniform (estimating V_u with weight V). Sharing one direction would
 * give V_u the weight V / (2 n.w), whose variance diverges at the horizon.
 * A direction below the geometric surface (possible when the shading normal
 * tilts away from it) counts as occluded: the surface itself blocks it.
 *
 * Distance fade (issue 25, item 12: the GTAO talk's "150 inches of full
 * effect, from 150 to 200 soften sample contribution from 1 to 0"): with
 * 0 < fade_start < max_distance an occluder at distance t blocks with weight
 *   w(t) = clamp((max_distance - t) / (max_distance - fade_start), 0, 1),
 * i.e. V(w) becomes 1 - w(t_hit). Since w(t) = P(t < T) for T uniform on
 * [fade_start, max_distance], each ray takes its own cutoff T from a third
 * Sobol' dimension pair and counts as unoccluded beyond it: an unbiased
 * estimate of the faded visibility that still needs only occlusion rays. */
#ifndef GTLAB_AO_AO_INTEGRATOR_H
#define GTLAB_AO_AO_INTEGRATOR_H

#include "raytracer/render_loop.h"
#include "ao/slice_horizons.h"

typedef struct {
    float max_distance; /* V = 1 beyond it; INFINITY for none */
    /* Per G-buffer pixel, the horizons of the height-field control variate
     * (techniques/ao/ao_control_variate.h): ao.V and ao.Vuniform samples become
     * V - g + G. NULL: plain sampling. */
    const slice_horizons *control_variate;
    float fade_start; /* occlusion fades from 1 here to 0 at max_distance; 0 or >= max_distance: hard cutoff */
} ao_settings;

integrator ao_integrator(const embree_scene *es, const ao_settings *settings);

/* Traces the AO rays of samples first_index .. first_index + count - 1
 * (count <= SAMPLE_BATCH) from dimension pair `pair` into rays[0 .. 2 count)
 * (cosine, uniform, cosine, ...; afterwards tfar < 0 where blocked or below
 * the geometric surface); returns the number of rays traced. */
int ao_trace_batch(const embree_scene *es, const pixel_context *px, float max_distance, float fade_start, uint32_t pair,
                   uint32_t first_index, int count, struct RTCRay *rays);

#endif
