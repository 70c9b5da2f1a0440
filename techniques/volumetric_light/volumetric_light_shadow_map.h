/* A spot light's shadow map as the ray-march reads it
 * (volumetric_light/volumetric_light_raymarch.h): a square perspective depth image seen
 * from the light along its axis, covering the outer cone (half field of
 * view = the cone's half-angle, so the cone is inscribed in the frustum).
 * Each texel holds the radial distance from the light to the first surface
 * along the ray through the texel's centre (+inf: nothing); gtlab renders it
 * with Embree (volumetric_light/volumetric_light_shadow_map_render.h), at a resolution the study
 * varies.
 *
 * Lookup (shadow_map_visibility): x projects to texel coordinates (u, v);
 * the four nearest texels are compared with x's own distance r and the
 * comparisons are weighted bilinearly (percentage-closer filtering with the
 * 2 x 2 footprint of a GPU's SampleCmp, Reeves, Salesin & Cook 1987). x is lit
 * by a texel when r <= (1 + bias) D: the relative bias absorbs that D is
 * measured along the texel's centre ray, not x's. Outside the frustum: 0 (the
 * light's falloff is 0 there too). */
#ifndef GTLAB_VOLUMETRIC_LIGHT_SHADOW_MAP_H
#define GTLAB_VOLUMETRIC_LIGHT_SHADOW_MAP_H

#include "core/error.h"
#include "core/vec3.h"

typedef struct {
    int size;        /* size x size texels */
    float *distance; /* [j * size + i], row j = v */
    vec3 position, forward, right, up;
    double tan_half; /* tan of the half field of view */
    double bias;     /* relative depth bias */
} shadow_map;

/* An empty map (distances +inf) of size^2 texels from position along the
 * unit forward with the given half field of view. Returns 0 or -1 with e. */
int shadow_map_alloc(shadow_map *m, int size, vec3 position, vec3 forward, double half_fov_deg, double bias,
                     gt_error *e);
void shadow_map_free(shadow_map *m);

/* The unit direction through texel coordinates (u, v) (texel centres at
 * integer + 1/2 ... as a GPU: texel i spans [i, i + 1)). */
vec3 shadow_map_direction(const shadow_map *m, double u, double v);

/* The PCF visibility of x in [0, 1]. */
double shadow_map_visibility(const shadow_map *m, vec3 x);

/* A point light's shadows: a cube of six maps from the light along +x, -x,
 * +y, -y, +z, -z, each of half field of view 45 degrees; x is looked up in
 * the face of the largest component of x - p (PCF clamps at the face's
 * edges, so a texel's width of error along the seams). */
typedef struct {
    shadow_map face[6];
} shadow_cube;

/* The unit forward of face k (0 .. 5). */
vec3 shadow_cube_axis(int k);
double shadow_cube_visibility(const shadow_cube *c, vec3 x);
void shadow_cube_free(shadow_cube *c);

#endif
