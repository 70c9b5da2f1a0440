/* Height-field AO: the screen-space ray marcher of the GTAO talk's
 * methodology (seeds/001, "Methodology": "Screen-space ray marcher (height
 * map)"). Cosine-weighted (and uniform) AO as in ao_integrator.h, but a ray
 * is blocked only by the depth buffer, taken as a height field seen from the
 * camera with infinite thickness: a point of the ray is inside the scene when
 * it lies farther along its eye ray than the surface the G-buffer holds
 * there. Each pixel's surface is its tangent plane (geometric normal) over the
 * pixel's footprint, clamped to its neighbours' depths, so planes are
 * reproduced exactly (core/optics/heightfield_model.h); background pixels hold
 * nothing. A ray that leaves the image or crosses the camera plane escapes
 * (nothing beyond the screen is known). This is the quantity GTAO computes
 * exactly, given enough slices and samples, so GTAO minus this reference is
 * pure sampling/denoising error; this reference minus the 3-D one is the
 * height-field assumption's error.
 *
 * With a finite thickness T (`gtlab render heightfield-ao --thickness T`)
 * each pixel's surface is a slab: a point blocks a ray only where its depth
 * along the camera axis lies between the surface's depth d and d + T, so
 * light passes behind thin objects (the occluder model of visibility-bitmask
 * AO, techniques/gtao/vbao.h). T = INFINITY is the height field above, bit
 * for bit. */
#ifndef GTLAB_AO_HEIGHTFIELD_AO_INTEGRATOR_H
#define GTLAB_AO_HEIGHTFIELD_AO_INTEGRATOR_H

#include "raytracer/reference_quantity.h"
#include "raytracer/render_loop.h"

enum { HEIGHTFIELD_LEVELS = 2 };
extern const int heightfield_tile_sizes[HEIGHTFIELD_LEVELS]; /* tile sides in pixels, coarse to fine */

typedef struct {
    const gbuffer *gb;
    float *depth;       /* per-pixel depth along the camera axis (owned) */
    float *depth_lo, *depth_hi; /* per pixel, the range of its and its neighbours' depths (owned) */
    float *tile_min[HEIGHTFIELD_LEVELS]; /* per tile of each level, the nearest depth of its surfaces (owned) */
    int tiles_x[HEIGHTFIELD_LEVELS];
    float max_distance; /* V = 1 beyond it along the ray; INFINITY for none */
    float thickness;    /* each pixel's slab, depth d to d + thickness; INFINITY (init's default): solid behind */
} heightfield_settings;

/* The heightfield-ao quantity's own settings (reference_request.settings;
 * NULL there: both INFINITY): `--max-distance D` and `--thickness T`. */
typedef struct {
    reference_settings header; /* names reference_quantity_heightfield_ao */
    float max_distance;        /* V = 1 beyond it along the ray; INFINITY: none */
    float thickness;
} heightfield_ao_options;

/* The settings of a render at that thickness, without a distance limit
 * (heightfield_ao_quantity.c; point the request's settings at .header). */
heightfield_ao_options heightfield_ao_thickness(float thickness);

/* Prepares the settings from a G-buffer (keeps a pointer to it), thickness
 * INFINITY. Returns 0, or -1 when out of memory. */
int heightfield_settings_init(heightfield_settings *hs, const gbuffer *gb, float max_distance);
void heightfield_settings_free(heightfield_settings *hs);

/* 1 if the ray p + t d, t in (0, max_distance], stays in front of the
 * height field, or with a finite thickness never enters a pixel's slab
 * (exposed for tests). */
int heightfield_unoccluded(const heightfield_settings *hs, vec3 p, vec3 d);

/* The surface the ray p + t d first meets in the height-field world (the
 * multi-bounce reference of techniques/multibounce/heightfield_multibounce_integrator.h):
 * 0 where heightfield_unoccluded is 1; else 1 and, if hit is not NULL, the
 * G-buffer hit of the pixel whose solid the ray enters (its material), at
 * the point where it does: on the pixel's surface (its tangent plane,
 * clamped as above; the crossing found by bisection within the cell, the
 * pixel's normals) when the ray passes behind it within its cell, or on the
 * side of the pixel's column (the plane through the eye and the pixel edge
 * crossed, its normal facing the ray) when the ray enters the cell already
 * behind the surface. Its distance t is from p. (With a finite thickness:
 * the pixel's surface where the ray enters its cell.) A ray leaving a point
 * on a column's side (not on its own pixel's surface) may be blocked by the
 * surface of the cell it starts in. */
int heightfield_first_hit(const heightfield_settings *hs, vec3 p, vec3 d, surface_hit *hit);

/* The horizon of the half-slice of p that leaves it along s (unit, s . v = 0,
 * v the unit vector from p to the eye), for the hemisphere of n: the
 * smallest angle from v, within the slice's plane, of the surface points
 * seen at the centres of the pixels one pixel apart along the screen
 * half-line p + t s projects to, out to the image's edge. Points on or below
 * p's tangent plane, beyond max_distance, or on background pixels do not
 * count. A direction of that half-plane at angle theta from v passes behind
 * the height field about when theta exceeds it (the centres stand for each
 * pixel's planar piece: a cheap horizon for the control variate, not the
 * exact one of heightfield_unoccluded). pi when nothing is found. */
float heightfield_horizon(const heightfield_settings *hs, vec3 p, vec3 n, vec3 v, vec3 s);

integrator heightfield_ao_integrator(const heightfield_settings *settings);

#endif
