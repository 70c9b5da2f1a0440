/* Shaded frames for anti-aliasing studies (issue 19): what a game renders
 * before its AA pass, computed with Embree primary rays instead of a
 * rasteriser. A sample at image position (x, y) (pixels, centres at +0.5)
 * traces the camera ray; on a hit the linear radiance is
 *     L = albedo (E_sun max(0, n.l) V(l) + E_sky (0.5 + 0.5 n.y)),
 * albedo the glTF base colour (textures included, scene/material_lookup.h),
 * n the shading normal, V the sun's visibility by a shadow ray, the sky term
 * the irradiance of a sky brighter overhead with no occlusion (a cheap
 * stand-in for ambient light); a miss sees the sky radiance L_bg. Values are
 * RGB, row-major, 3 floats a pixel.
 *
 * Supersampling: s x s strata per pixel, one sample per stratum at a
 * position jittered by a hash of (pixel, stratum, seed), written as an
 * image of (W s) x (H s) samples for core/sampling/pixel_filter.h to resolve. */
#ifndef GTLAB_RAYTRACER_SHADED_FRAME_H
#define GTLAB_RAYTRACER_SHADED_FRAME_H

#include "raytracer/embree_scene.h"
#include "scene/camera.h"

typedef struct {
    vec3 sun_direction;   /* unit, towards the sun */
    float sun[3];         /* irradiance E_sun, RGB */
    float sky[3];         /* E_sky */
    float background[3];  /* L_bg */
} frame_lighting;

/* The default light: a sun 50 degrees up, warm, and a blue sky. */
frame_lighting frame_lighting_default(void);

/* L at image position (x, y) into out; 1 and the surface in hit (if not
 * NULL) when the ray hits one, 0 when it sees the sky. */
int shaded_frame_sample(const embree_scene *es, const camera_view *view, const frame_lighting *light, float x, float y,
                        float out[3], surface_hit *hit);

/* One sample per pixel at the centre plus `offset` (pixels). */
void shaded_frame_render(const embree_scene *es, const camera *cam, const frame_lighting *light,
                         const float offset[2], int threads, float *rgb);

/* (W s) x (H s) stratified jittered samples (the seed picks the jitter);
 * xy, if not NULL, receives each sample's image position (2 floats). */
void shaded_frame_render_supersampled(const embree_scene *es, const camera *cam, const frame_lighting *light, int s,
                                      unsigned seed, int threads, float *rgb, float *xy);

#endif
