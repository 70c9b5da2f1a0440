/* What the volumetric-light study (volumetric_light/volumetric_light_study.h), `gtlab approx raymarch`
 * and `gtlab bench` share: builtin:cornell at a given size with the default
 * spot of `gtlab render volumetric-light` (techniques/volumetric_light/volumetric_light_integrator.h),
 * its camera rays as the ray-march reads them (volumetric_light/volumetric_light_raymarch.h:
 * the G-buffer's unit directions and distances, 0 where the ray misses), and
 * the reference L / I per pixel by quadrature with Embree shadow rays. */
#ifndef GTLAB_VOLUMETRIC_LIGHT_SETUP_H
#define GTLAB_VOLUMETRIC_LIGHT_SETUP_H

#include "raytracer/embree_scene.h"
#include "raytracer/gbuffer.h"
#include "volumetric_light/volumetric_light_integrator.h"
#include "volumetric_light/volumetric_light_raymarch.h"
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
} volumetric_light_setup;

/* Loads the scene and renders the G-buffer. Returns 0 or -1 with e (nothing to free). */
int volumetric_light_setup_init(volumetric_light_setup *v, int width, int height, int threads, gt_error *e);
void volumetric_light_setup_free(volumetric_light_setup *v);

/* The reference L / I (grey) per pixel by quadrature to rel_tol, with its
 * error estimate (either may be NULL); returns the shadow rays traced. */
long volumetric_light_reference(const volumetric_light_setup *v, double rel_tol, int threads, float *reference, float *error);

#endif
