/* `gtlab render fog`: the height fog between the camera and the first
 * surface of each pixel (docs/render-quantities.md, issue 16). Channels
 * (core/reference_schema.h):
 *
 *   fog.T.R/G/B   transmittance from the camera to the surface, closed form
 *                 (core/optics/height_fog_medium.h), the same in every sample
 *   fog.L.R/G/B   radiance the fog scatters towards the camera, sun +
 *                 ambient, with .stderr:
 *                   quadrature  single scattering by gk15
 *                               (techniques/height_fog/height_fog_single_scatter.h), the same in
 *                               every sample; its error estimate in
 *                               fog_quadrature_error.R/G/B
 *                   single      the same integral by Monte Carlo
 *                   multiple    volumetric path tracing
 *                               (techniques/height_fog/height_fog_path_tracer.h)
 *
 * Options separate the analytic model's assumptions: no_sun_extinction
 * (the sun reaches every point unattenuated, as the published model
 * assumes) and no_shadows (the scene neither shadows the sun nor blocks
 * scattered paths). A surface's own radiance is not rendered: composite as
 * the talk does, background * fog.T + fog.L. Pixels whose primary ray
 * misses the scene get the fog along the whole ray to infinity (fog.T there
 * is the sky's transmittance: 0 for rays that never leave an infinite
 * layer, i.e. level or descending ones). */
#ifndef GTLAB_HEIGHT_FOG_INTEGRATOR_H
#define GTLAB_HEIGHT_FOG_INTEGRATOR_H

#include "core/error.h"
#include "core/statistics/mc_film.h"
#include "height_fog/height_fog_path_tracer.h"
#include "raytracer/reference_quantity.h"
#include "raytracer/render_loop.h"

typedef enum { HEIGHT_FOG_QUADRATURE, HEIGHT_FOG_SINGLE, HEIGHT_FOG_MULTIPLE } height_fog_scattering_mode;

/* The settings of `gtlab render fog` (reference_request.settings). */
typedef struct {
    reference_settings header; /* names reference_quantity_fog */
    char weather[16];         /* height_fog_weather: "sunny" or "dense" */
    double sun_elevation_deg; /* degrees above the horizon */
    height_fog_scattering_mode scattering;
    int no_sun_extinction, no_shadows;
    int max_scatterings;      /* multiple only */
} height_fog_settings;

enum { HEIGHT_FOG_QUANTITIES = 9 };

typedef struct {
    height_fog_param medium;
    height_fog_path_settings path;
    height_fog_scattering_mode scattering;
    camera_view view; /* the G-buffer's camera: the background pixels' rays */
    int quantity_count;
    mc_quantity quantities[HEIGHT_FOG_QUANTITIES];
} height_fog_plan;

/* Builds the plan; -1 with e naming "fog" when a setting is bad. */
int height_fog_plan_init(height_fog_plan *plan, const height_fog_settings *settings, const embree_scene *es, const camera_view *view,
                  gt_error *e);
integrator height_fog_integrator(const embree_scene *es, const height_fog_plan *plan);

/* The quantity (height_fog_quantity.c), and its defaults: sunny, the sun 25 degrees
 * up, multiple scattering (at most 1024 scatterings), extinction and
 * shadows on; the header names the quantity. */
extern const reference_quantity_descriptor reference_quantity_fog;
void height_fog_settings_default(height_fog_settings *s);
const char *height_fog_scattering_name(height_fog_scattering_mode s);
/* "quadrature" / "single" / "multiple" -> s; -1 if unknown. */
int height_fog_scattering_parse(const char *name, height_fog_scattering_mode *s);

#endif
