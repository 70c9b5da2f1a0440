/* One reference render from start to finish: Embree scene, G-buffer, the
 * quantity's integrator, and the output image with the DESIGN.md channels and
 * header (quantity, scene, camera, spp, seed, sample block, version).
 * `gtlab render`, `gtlab all`, `gtlab bench` and the tests all come here. */
#ifndef GTLAB_RAYTRACER_REFERENCE_RENDER_H
#define GTLAB_RAYTRACER_REFERENCE_RENDER_H

#include "core/image.h"
#include "core/sky_environment.h"
#include "raytracer/gbuffer.h"
#include "raytracer/multibounce_integrator.h"
#include "raytracer/render_loop.h"
#include "raytracer/sphere_light_integrator.h"
#include "scene/scene.h"

typedef enum {
    QUANTITY_GBUFFER,
    QUANTITY_AO,
    QUANTITY_MULTIBOUNCE,
    QUANTITY_HEIGHTFIELD_AO,
    QUANTITY_SPECULAR_OCCLUSION,
    QUANTITY_SPHERE_LIGHT
} reference_quantity;

typedef struct {
    reference_quantity quantity;
    sampling_settings sampling;
    normal_mode normals;
    float max_distance;               /* ao and heightfield-ao; INFINITY: none */
    multibounce_settings multibounce; /* multibounce only: albedos, bounces */
    sphere_light_settings sphere_light; /* sphere-light only: the light */
    float roughness;                  /* specular-occlusion only: perceptual roughness, < 0: the material's */
    environment_kind environment;     /* specular-occlusion only: sky adds the split-integral channels */
} reference_request;

/* "gbuffer" / "ao" / "multibounce" / "heightfield-ao" / "specular-occlusion" /
 * "sphere-light" -> quantity; -1 if unknown. */
int reference_quantity_parse(const char *name, reference_quantity *q);
const char *reference_quantity_name(reference_quantity q);

/* Renders into `out` (initialised here). scene_spec is recorded in the header. */
int reference_render(const scene *s, const char *scene_spec, const camera *cam, const reference_request *req,
                     image *out, render_stats *stats, gt_error *e);

#endif
