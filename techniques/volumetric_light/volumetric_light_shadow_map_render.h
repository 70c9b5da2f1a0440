/* Renders a spot light's shadow map (volumetric_light/volumetric_light_shadow_map.h) with Embree: the
 * closest hit along each texel's centre ray from the light. Deterministic
 * (one ray per texel); OpenMP over rows. In the study part: it joins the
 * raytracer (Embree) and the real-time map, which the layers keep apart. */
#ifndef GTLAB_VOLUMETRIC_LIGHT_SHADOW_MAP_RENDER_H
#define GTLAB_VOLUMETRIC_LIGHT_SHADOW_MAP_RENDER_H

#include "core/optics/volumetric_light.h"
#include "raytracer/embree_scene.h"
#include "volumetric_light/volumetric_light_shadow_map.h"

/* The map of size^2 texels covering the spot's outer cone, with the relative
 * bias given. Returns 0 or -1 with e (a point light has no such map). */
int shadow_map_render(const embree_scene *es, const volumetric_light *spot, int size, double bias, int threads,
                      shadow_map *m, gt_error *e);

/* A point light's cube of six size^2 maps (volumetric_light/volumetric_light_shadow_map.h). */
int shadow_cube_render(const embree_scene *es, const volumetric_light *light, int size, double bias, int threads,
                       shadow_cube *c, gt_error *e);

#endif
