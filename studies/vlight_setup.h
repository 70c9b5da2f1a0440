/* What the volumetric-light study (studies/vlight.h), `gtlab approx raymarch`
 * and `gtlab bench` share: builtin:cornell at a given size with the default
 * spot of `gtlab render volumetric-light` (raytracer/volumetric_light_integrator.h),
 * its camera rays as the ray-march reads them (realtime/raymarch_volumetric.h:
 * the G-buffer's unit directions and distances, 0 where the ray misses), and
 * the reference L / I per pixel by quadrature with Embree shadow rays. */
#ifndef GTLAB_STUDIES_VLIGHT_SETUP_H
#define GTLAB_STUDIES_VLIGHT_SETUP_H

#include "raytracer/embree_scene.h"
#include "raytracer/gbuffer.h"
#include "raytracer/volumetric_light_integrator.h"
#include "realtime/raymarch_volumetric.h"
#include "scene/scene.h"

#define VLIGHT_SCENE "builtin:cornell"

typedef struct {
    scene s;
    embree_scene es;
    gbuffer gb;
    volumetric_light light;
    volumetric_medium medium;
    float *dir, *distance, *mask; /* 3 wh, wh, wh */
    raymarch_view view;
} vlight_setup;

/* Loads the scene and renders the G-buffer. Returns 0 or -1 with e (nothing to free). */
int vlight_setup_init(vlight_setup *v, int width, int height, int threads, gt_error *e);
void vlight_setup_free(vlight_setup *v);

/* The reference L / I (grey) per pixel by quadrature to rel_tol, with its
 * error estimate (either may be NULL); returns the shadow rays traced. */
long vlight_reference(const vlight_setup *v, double rel_tol, int threads, float *reference, float *error);

#endif
